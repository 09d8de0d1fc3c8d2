// Internal: the per-coordinate steps of texture sampling, one definition each, shared by the
// per-pixel sample functions (texture_sampling.cpp, texture_sampling_llvmpipe.cpp) and the
// block read (texture_sampling_block.cpp), so that the two paths cannot drift.
#pragma once

#include <cmath>
#include <cstdint>

#include "tierlift/cpu/texture.h"
#include "tierlift/ir/numerics.h"

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

struct LinearAxis {
  int64_t i0 = 0; // left (top) texel before addressing
  float alpha = 0;
};

// llvmpipe's bilinear axis (texture_sampling_llvmpipe.cpp explains each step).
inline LinearAxis llvmpipe_linear_axis(float u, uint32_t n, AddressMode mode, int subtexel_bits) {
  const float size = static_cast<float>(n);
  float x = u * size;
  if (mode == AddressMode::Clamp) {
    // llvmpipe clamps the coordinate, not the index: min(u·N, N) with NaN → N, then − 0.5,
    // then max(·, 0). The result lies in [0, N − 0.5], so the conversion below is defined.
    x = x < size ? x : size;
    x = x - 0.5f;
    x = x > 0 ? x : 0;
  } else {
    x = x - 0.5f;
    constexpr float kLimit = 1099511627776.0f; // 2^40: far outside any address period
    if (std::isnan(x)) x = 0;
    x = x < -kLimit ? -kLimit : (x > kLimit ? kLimit : x);
  }
  const float f = std::floor(x);
  LinearAxis a;
  a.i0 = static_cast<int64_t>(f);
  a.alpha = x - f; // exact (Sterbenz)
  if (subtexel_bits > 0) a.alpha = static_cast<float>(quantize_fraction(a.alpha, subtexel_bits));
  return a;
}

// llvmpipe's lerp: v0 + α·(v1 − v0) as one fused multiply-add, with the x86 DAZ and FTZ bits
// set: denormal texels and results are zeros of their sign (NUMERICS.md rule 13).
inline float llvmpipe_lerp(float alpha, float v0, float v1) {
  using ir::numerics::flush_denormal;
  v0 = flush_denormal(v0);
  v1 = flush_denormal(v1);
  return flush_denormal(std::fma(alpha, flush_denormal(v1 - v0), v0));
}

} // namespace tierlift::cpu::detail
