// Internal: the per-coordinate steps of texture sampling, one definition each, shared by the
// per-pixel sample functions (texture_sampling.cpp, texture_sampling_llvmpipe.cpp) and the
// block read (texture_sampling_block.cpp), so that the two paths cannot drift.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "tierlift/cpu/texture.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::cpu::detail {

// Texel-space coordinate u·N as a double (exact: a float times an integer ≤ 2^14 fits in
// 53 bits), so bilinear weights are exact before sub-texel quantisation. Clamped far outside any
// address-mode period so the int64 conversion is defined; NaN becomes 0.
inline double texel_space(float u, uint32_t n) {
  double x = static_cast<double>(u) * n;
  if (std::isnan(x)) return 0.0;
  constexpr double kLimit = 1099511627776.0; // 2^40
  return x < -kLimit ? -kLimit : (x > kLimit ? kLimit : x);
}

// Point sampling's texel index: floor(u·N) with the product rounded to float, as a GPU's
// fp32 multiply rounds it: u = float(i/N), a texel corner that float cannot hold exactly,
// then still selects texel i rather than i − 1 whenever float(i/N)·N rounds back to i.
inline int64_t point_texel(float u, uint32_t n) {
  return static_cast<int64_t>(std::floor(static_cast<float>(texel_space(u, n))));
}

// Texel (i, j) after addressing (indices from address_texel); border colour when either
// axis fell outside under Border.
inline Vec4 fetch(const img::Image& image, const SamplerState& s, const std::optional<int64_t>& i,
                  const std::optional<int64_t>& j) {
  if (!i || !j) return s.border_color;
  const float* p = image.at(static_cast<uint32_t>(*i), static_cast<uint32_t>(*j));
  return {p[0], p[1], p[2], p[3]};
}

using rounding::LinearAxis;

// llvmpipe's bilinear axis (rounding::linear_axis), with the sub-texel quantisation a
// device with subtexel_bits > 0 applies on top.
inline LinearAxis llvmpipe_linear_axis(float u, uint32_t n, AddressMode mode, int subtexel_bits) {
  LinearAxis a = rounding::linear_axis(u, n, mode == AddressMode::Clamp);
  if (subtexel_bits > 0) a.alpha = static_cast<float>(quantize_fraction(a.alpha, subtexel_bits));
  return a;
}

// llvmpipe's reading of an axis whose coordinate it cannot address (NUMERICS.md rule 37;
// Direct3D 9 leaves such reads undefined, so matching lavapipe is a device-matching choice):
// the integer conversion of a non-finite value gives INT_MIN and the bilinear weight
// x − floor(x) is NaN. Per address mode (n texels, u·N rounded to float as llvmpipe does):
//   * Wrap, n a power of two: fl32(u·N) not finite: POINT reads texel INT_MIN & (n − 1) = 0,
//     LINEAR a NaN weight. Other sizes take fract(u) first: u not finite: POINT reads the
//     clamped fraction's texel n − 1, LINEAR a NaN weight.
//   * Border: fl32(u·N) not finite: POINT reads the border colour, LINEAR a NaN weight.
//   * Mirror: u not finite: the mirrored coordinate is NaN, which llvmpipe sends to 0: texel
//     0 (LINEAR: both taps texel 0, weight ½).
//   * Clamp: already the ordinary rule (llvmpipe clamps the coordinate; NaN as documented).
// A NaN weight makes every channel NaN (the lerp propagates it).
struct UnaddressableAxis {
  enum class Kind : uint8_t { Ordinary, NanWeight, Texel, Border } kind = Kind::Ordinary;
  int64_t texel = 0;
  float alpha = 0;
};
inline UnaddressableAxis llvmpipe_unaddressable(float u, uint32_t n, AddressMode mode,
                                                Filter filter) {
  using Kind = UnaddressableAxis::Kind;
  const bool linear = filter != Filter::Point;
  const bool scaled_finite = std::isfinite(u * static_cast<float>(n));
  switch (mode) {
  case AddressMode::Wrap:
    if ((n & (n - 1)) == 0) {
      if (scaled_finite) return {};
      return linear ? UnaddressableAxis{Kind::NanWeight, 0, 0}
                    : UnaddressableAxis{Kind::Texel, 0, 0};
    }
    if (std::isfinite(u)) return {};
    return linear ? UnaddressableAxis{Kind::NanWeight, 0, 0}
                  : UnaddressableAxis{Kind::Texel, static_cast<int64_t>(n) - 1, 0};
  case AddressMode::Border:
    if (scaled_finite) return {};
    return linear ? UnaddressableAxis{Kind::NanWeight, 0, 0}
                  : UnaddressableAxis{Kind::Border, 0, 0};
  case AddressMode::Mirror:
    if (std::isfinite(u)) return {};
    return {Kind::Texel, 0, 0.5f};
  default: return {};
  }
}

inline float llvmpipe_lerp(float alpha, float v0, float v1) {
  return rounding::lerp(alpha, v0, v1);
}

} // namespace tierlift::cpu::detail
