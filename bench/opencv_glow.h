// The glow written with OpenCV, the peer of the glow benchmarks: sources rgb × alpha, resize
// INTER_AREA by the downsample factor, sepFilter2D with the plan's own taps (BORDER_REPLICATE,
// as the blur passes clamp), resize INTER_LINEAR back, add — in float, into buffers kept
// across frames (the idiomatic use). The peer of bench_glow and bench_cpu_glow.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "tierlift/effects/glow/blur_profile.h"
#include "tierlift/image/image.h"

namespace tierlift::bench {

class OpenCvGlow {
public:
  OpenCvGlow(const std::vector<effects::BlurTap>& taps, unsigned downsample);
  // `in` is RGBA float; returns the final frame (valid until the next call).
  const cv::Mat& run(const cv::Mat& in);

private:
  cv::Mat kernel_;
  int downsample_;
  cv::Mat mask_, sources_, small_, blurred_, glow_, final_;
};

// An RGBA32F image as a cv::Mat sharing its storage.
cv::Mat wrap(const img::Image& im);

} // namespace tierlift::bench
