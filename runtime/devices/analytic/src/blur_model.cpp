// The blur pass as math: bilinear model, plain discrete convolution, corner model.
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

std::vector<TexelTap> intended_texel_taps(const std::vector<Tap>& taps, uint32_t width,
                                          uint32_t height) {
  std::vector<TexelTap> out;
  for (const Tap& t : taps) {
    auto whole = [](double texels) {
      double f = std::floor(std::fmin(std::fmax(texels, -1e12), 1e12) + 1e-6);
      return static_cast<int64_t>(f);
    };
    out.push_back({whole(t.offset[0] * width), whole(t.offset[1] * height), t.weight});
  }
  return out;
}

img::ImageResult discrete_convolution(const std::vector<TexelTap>& taps, const img::Image& source,
                                      const PassModel& model) {
  ir::Result<Size> size = target_size(source, model);
  if (!size) return std::move(size).failure();
  if (size->w != source.width || size->h != source.height)
    return fail("discrete convolution needs target size = source size");
  img::Image out(size->w, size->h, model.target_format);
  for (uint32_t j = 0; j < size->h; ++j)
    for (uint32_t i = 0; i < size->w; ++i) {
      std::array<double, 4> sum{};
      for (const TexelTap& t : taps) {
        int64_t x = address_texel(int64_t{i} + t.dx, source.width, model.sampler.address_u);
        int64_t y = address_texel(int64_t{j} + t.dy, source.height, model.sampler.address_v);
        for (int c = 0; c < 4; ++c) {
          double v = (x < 0 || y < 0) ? model.sampler.border[c]
                                      : texel_value(source, static_cast<uint32_t>(x),
                                                    static_cast<uint32_t>(y), c);
          sum[c] += t.weight[c] * v;
        }
      }
      store(out, i, j, sum, model.unorm8_ties);
    }
  return img::ImageResult(std::move(out));
}

namespace {

// A sample point relative to pixel i, in texel units minus the half texel: an integer
// means "on texel i + k", an integer + 0.5 means "on the edge between two texels".
// Returns the texels read (1 or 2) or nothing when the point is neither.
struct Straddle {
  int64_t first;
  int count;
};
// Offsets come from float constants (k/48 is not exact in float), so "on a centre" and
// "on an edge" are decided with a tolerance of 1e-5 texel; the value then follows the
// model's exact rule.
std::optional<Straddle> straddle(double p) {
  double twice = std::nearbyint(2.0 * p);
  if (!(std::fabs(2.0 * p - twice) <= 2e-5) || std::fabs(twice) > 2e12) return std::nullopt;
  auto t = static_cast<int64_t>(twice);
  if (t % 2 == 0) return Straddle{t / 2, 1};
  return Straddle{(t - 1) / 2, 2}; // t odd: texels (t-1)/2 and (t+1)/2
}

} // namespace

img::ImageResult corner_model(const std::vector<Tap>& taps, const img::Image& source,
                              const PassModel& model) {
  ir::Result<Size> size = target_size(source, model);
  if (!size) return std::move(size).failure();
  if (size->w != source.width || size->h != source.height)
    return fail("corner model needs target size = source size");
  img::Image out(size->w, size->h, model.target_format);
  const double w = source.width, h = source.height;
  for (uint32_t j = 0; j < size->h; ++j)
    for (uint32_t i = 0; i < size->w; ++i) {
      auto uv = pixel_uv(i, j, size->w, size->h, model);
      std::array<double, 4> sum{};
      for (const Tap& t : taps) {
        auto sx = straddle((t.scale[0] * uv[0] + t.offset[0]) * w - 0.5);
        auto sy = straddle((t.scale[1] * uv[1] + t.offset[1]) * h - 0.5);
        if (!sx || !sy)
          return fail(fmt::format("tap at offset ({}, {}) lands neither on a texel "
                                  "centre nor half-way between texels",
                                  t.offset[0], t.offset[1]));
        const double share = 1.0 / (sx->count * sy->count);
        for (int b = 0; b < sy->count; ++b)
          for (int a = 0; a < sx->count; ++a) {
            int64_t x = address_texel(sx->first + a, source.width, model.sampler.address_u);
            int64_t y = address_texel(sy->first + b, source.height, model.sampler.address_v);
            for (int c = 0; c < 4; ++c) {
              double v = (x < 0 || y < 0) ? model.sampler.border[c]
                                          : texel_value(source, static_cast<uint32_t>(x),
                                                        static_cast<uint32_t>(y), c);
              sum[c] += t.weight[c] * share * v;
            }
          }
      }
      store(out, i, j, sum, model.unorm8_ties);
    }
  return img::ImageResult(std::move(out));
}

ir::Result<CornerPrediction> predict_corner_difference(const std::vector<Tap>& taps,
                                                       const img::Image& source,
                                                       const PassModel& model) {
  for (const Tap& t : taps)
    if (t.scale != std::array<double, 2>{1, 1}) {
      // A scaled coordinate moves by a different amount at every pixel: no fixed texel.
      return fail("the corner prediction needs taps of the form texcoord + offset");
    }
  PassModel exact = model;
  exact.target_format = img::Format::RGBA32F; // the prediction itself is not stored
  auto corner = corner_model(taps, source, exact);
  auto plain =
      discrete_convolution(intended_texel_taps(taps, source.width, source.height), source, exact);
  if (!corner) return std::move(corner).failure();
  if (!plain) return std::move(plain).failure();
  CornerPrediction p;
  p.difference = img::Image(source.width, source.height, img::Format::RGBA32F);
  double sq = 0;
  for (size_t k = 0; k < p.difference.rgba.size(); ++k) {
    double d = static_cast<double>(corner->rgba[k]) - plain->rgba[k];
    p.difference.rgba[k] = static_cast<float>(d);
    p.max_abs = std::fmax(p.max_abs, std::fabs(d));
    sq += d * d;
  }
  p.rmse = p.difference.rgba.empty()
               ? 0.0
               : std::sqrt(sq / static_cast<double>(p.difference.rgba.size()));
  return p;
}

} // namespace tierlift::analytic
