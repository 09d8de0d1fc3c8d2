// The blur pass as math: the bilinear model.
#include <cmath>
#include <fmt/format.h>

#include "tierlift/analytic/blur_model.h"

namespace tierlift::analytic {

namespace {

struct Size {
  uint32_t w, h;
};

// The model's failures: the pass it was asked for cannot be computed.
ir::Failure fail(std::string message) {
  return ir::fail("analytic", "analytic", std::move(message));
}

ir::Result<Size> target_size(const img::Image& src, const PassModel& m) {
  Size s{m.target_width ? m.target_width : src.width,
         m.target_height ? m.target_height : src.height};
  if (src.width == 0 || src.height == 0 || src.rgba.size() != size_t{src.width} * src.height * 4) {
    return fail("source image is empty or malformed");
  }
  if (s.w > img::kMaxDimension || s.h > img::kMaxDimension) {
    return fail(fmt::format("target {}x{} exceeds the limit of {}", s.w, s.h, img::kMaxDimension));
  }
  return s;
}

void store(img::Image& out, uint32_t x, uint32_t y, const std::array<double, 4>& v,
           Unorm8Ties ties) {
  float* p = out.at(x, y);
  for (int c = 0; c < 4; ++c) p[c] = store_value(out.format, v[c], ties);
}

} // namespace

img::ImageResult blur_pass(const std::vector<Tap>& taps, const img::Image& source,
                           const PassModel& model) {
  ir::Result<Size> size = target_size(source, model);
  if (!size) return std::move(size).failure();
  img::Image out(size->w, size->h, model.target_format);
  for (uint32_t j = 0; j < size->h; ++j)
    for (uint32_t i = 0; i < size->w; ++i) {
      auto uv = pixel_uv(i, j, size->w, size->h, model);
      std::array<double, 4> sum{};
      for (const Tap& t : taps) {
        auto s = sample(source, t.scale[0] * uv[0] + t.offset[0], t.scale[1] * uv[1] + t.offset[1],
                        model.sampler, model.conventions.subtexel_bits);
        for (int c = 0; c < 4; ++c) sum[c] += t.weight[c] * s[c];
      }
      store(out, i, j, sum, model.unorm8_ties);
    }
  return img::ImageResult(std::move(out));
}

} // namespace tierlift::analytic
