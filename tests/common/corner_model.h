// Test-only models of a blur pass that reads whole texels, used to show the half-texel rule
// both ways: the plain discrete convolution the author meant, and the corner model (what a
// D3D9 quad without the half-texel offset reads). No product code calls them; they sit
// beside the analytic model (tierlift/analytic/blur_model.h) and use its addressing, texel
// values and store rule.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tierlift/analytic/blur_model.h"

namespace tierlift::test {

// The address rule (pass::address_texel) with −1 for the border colour.
inline int64_t address_texel(int64_t i, int64_t n, pass::AddressMode mode) {
  return pass::address_texel(mode, i, n).value_or(-1);
}
using analytic::PassModel;
using analytic::pixel_uv;
using analytic::Tap;
using analytic::texel_value;

// A tap as a whole-texel displacement: the plain discrete convolution's view.
struct TexelTap {
  int64_t dx = 0, dy = 0;
  std::array<double, 4> weight{};
};

// What the corner model predicts the no-half-texel pass differs from the plain convolution
// by: corner_model − discrete_convolution(intended_texel_taps), per value, unquantised
// (RGBA32F image of signed differences), and its largest magnitude.
struct CornerPrediction {
  img::Image difference;
  double max_abs = 0;
  double rmse = 0;
};

namespace detail {

struct SameSize {
  bool ok = false;
  std::string error;
  explicit operator bool() const { return ok; }
};
// These models read texel i for pixel i: the target must have the source's size.
inline SameSize same_size_target(const img::Image& source, const PassModel& m) {
  if (source.width == 0 || source.height == 0 ||
      source.rgba.size() != size_t{source.width} * source.height * 4)
    return {false, "source image is empty or malformed"};
  if ((m.target_width && m.target_width != source.width) ||
      (m.target_height && m.target_height != source.height))
    return {false, "these models need target size = source size"};
  return {true, ""};
}

inline void store(img::Image& out, uint32_t x, uint32_t y, const std::array<double, 4>& v,
                  analytic::Unorm8Ties ties) {
  float* p = out.at(x, y);
  for (int c = 0; c < 4; ++c) p[c] = analytic::store_value(out.format, v[c], ties);
}

} // namespace detail

// The texels the author meant: offset·size rounded down (+1e-6 slack), so (k + 0.5)/W
// (the article's half-texel offsets) and k/W (without them) both mean tap k. For taps of
// the form texcoord + offset (scale 1; the scale is not read).
inline std::vector<TexelTap> intended_texel_taps(const std::vector<Tap>& taps, uint32_t width,
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

// out(i, j) = Σ_k w_k · T[addr(i + dx_k), addr(j + dy_k)], stored with img::quantize.
// Target and source sizes must be equal.
inline img::ImageResult discrete_convolution(const std::vector<TexelTap>& taps,
                                             const img::Image& source, const PassModel& model) {
  auto size = detail::same_size_target(source, model);
  if (!size) return ir::fail("analytic", "model", size.error);
  img::Image out(source.width, source.height, model.target_format);
  for (uint32_t j = 0; j < source.height; ++j)
    for (uint32_t i = 0; i < source.width; ++i) {
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
      detail::store(out, i, j, sum, model.unorm8_ties);
    }
  return img::ImageResult(std::move(out));
}

namespace detail {

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
inline std::optional<Straddle> straddle(double p) {
  double twice = std::nearbyint(2.0 * p);
  if (!(std::fabs(2.0 * p - twice) <= 2e-5) || std::fabs(twice) > 2e12) return std::nullopt;
  auto t = static_cast<int64_t>(twice);
  if (t % 2 == 0) return Straddle{t / 2, 1};
  return Straddle{(t - 1) / 2, 2}; // t odd: texels (t-1)/2 and (t+1)/2
}

} // namespace detail

// The corner model: a tap whose sample point lies on a texel centre reads that texel; one
// that lies half a texel off (on an edge or a corner between texels, as a D3D9 quad without
// the half-texel offset does) reads the plain mean of the 2 or 4 texels around it. Written
// from that rule alone (no bilinear weights). Positions are classified with a tolerance of
// 1e-5 texel (offsets come from float constants); any other position is an error. Target and
// source sizes must be equal. Stored with img::quantize.
inline img::ImageResult corner_model(const std::vector<Tap>& taps, const img::Image& source,
                                     const PassModel& model) {
  auto size = detail::same_size_target(source, model);
  if (!size) return ir::fail("analytic", "model", size.error);
  img::Image out(source.width, source.height, model.target_format);
  const double w = source.width, h = source.height;
  for (uint32_t j = 0; j < source.height; ++j)
    for (uint32_t i = 0; i < source.width; ++i) {
      auto uv = pixel_uv(i, j, source.width, source.height, model);
      std::array<double, 4> sum{};
      for (const Tap& t : taps) {
        auto sx = detail::straddle((t.scale[0] * uv[0] + t.offset[0]) * w - 0.5);
        auto sy = detail::straddle((t.scale[1] * uv[1] + t.offset[1]) * h - 0.5);
        if (!sx || !sy)
          return ir::fail("analytic", "model",
                          fmt::format("tap at offset ({}, {}) lands neither on a texel "
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
      detail::store(out, i, j, sum, model.unorm8_ties);
    }
  return img::ImageResult(std::move(out));
}

// Taps must have scale 1 (an error otherwise).
inline ir::Result<CornerPrediction> predict_corner_difference(const std::vector<Tap>& taps,
                                                              const img::Image& source,
                                                              const PassModel& model) {
  for (const Tap& t : taps)
    if (t.scale != std::array<double, 2>{1, 1}) {
      // A scaled coordinate moves by a different amount at every pixel: no fixed texel.
      return ir::fail("analytic", "model",
                      "the corner prediction needs taps of the form texcoord + offset");
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

} // namespace tierlift::test
