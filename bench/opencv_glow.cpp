#include "opencv_glow.h"

#include <algorithm>
#include <cstdlib>

#include <opencv2/imgproc.hpp>

namespace tierlift::bench {
namespace {

// The taps (offsets −R..R, texels of the small texture) as a sepFilter2D kernel; sepFilter2D
// correlates, so kernel[R + k] weights the texel at offset k.
cv::Mat kernel_from_taps(const std::vector<effects::BlurTap>& taps) {
  int r = 0;
  for (const effects::BlurTap& t : taps) r = std::max(r, std::abs(t.offset));
  cv::Mat k = cv::Mat::zeros(2 * r + 1, 1, CV_32F);
  for (const effects::BlurTap& t : taps) k.at<float>(t.offset + r) += float(t.weight);
  return k;
}

} // namespace

OpenCvGlow::OpenCvGlow(const std::vector<effects::BlurTap>& taps, unsigned downsample)
    : kernel_(kernel_from_taps(taps)), downsample_(int(downsample)) {}

const cv::Mat& OpenCvGlow::run(const cv::Mat& in) {
  // Sources = (r·a, g·a, b·a, 0): a zero alpha makes `add` keep the scene's alpha, as the
  // composite pass does (it adds rgb only).
  const int from_to[] = {3, 0, 3, 1, 3, 2, -1, 3}; // -1: channel filled with zero
  mask_.create(in.size(), in.type());
  cv::mixChannels(&in, 1, &mask_, 1, from_to, 4);
  cv::multiply(in, mask_, sources_);
  const cv::Size small_size((in.cols + downsample_ - 1) / downsample_,
                            (in.rows + downsample_ - 1) / downsample_);
  cv::resize(sources_, small_, small_size, 0, 0, cv::INTER_AREA);
  cv::sepFilter2D(small_, blurred_, -1, kernel_, kernel_, cv::Point(-1, -1), 0,
                  cv::BORDER_REPLICATE);
  cv::resize(blurred_, glow_, in.size(), 0, 0, cv::INTER_LINEAR);
  cv::add(in, glow_, final_);
  return final_;
}

cv::Mat wrap(const img::Image& im) {
  return cv::Mat(int(im.height), int(im.width), CV_32FC4, const_cast<float*>(im.rgba.data()));
}

} // namespace tierlift::bench
