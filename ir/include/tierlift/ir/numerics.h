// The legacy numeric rules of Direct3D 9 shader arithmetic, each defined once, by name
// (design.md "Conventions"; d3d9-isa.md §5, §8). The CPU interpreter calls these functions
// and the SPIR-V code generator emits exactly the same sequence of operations, so the two
// cannot drift. NUMERICS.md (repo root) states every rule, why it was chosen and which test
// checks it.
//
// Common choices (see NUMERICS.md for the reasons):
//  * Special results are finite: rcp(0), rsq(0) and every overflow of rcp/rsq/exp give
//    +FLT_MAX (or -FLT_MAX), never infinity; log(0) gives -FLT_MAX.
//  * 0 × anything = +0, including ±inf and NaN (legacy_mul).
//  * mad is NOT fused: the product is rounded to fp32, then the sum (SPIR-V: NoContraction).
//  * Denormals are kept (no flush to zero), as x86 SSE and lavapipe do by default.
//  * Comparisons are ordered: a NaN makes every compare false (the sheet's ternaries).
//
// Every function uses only fp32 operations with one rounding each, so that the emitted
// SPIR-V can reproduce them bit for bit. Ternaries are written so that the false branch is
// the one a NaN takes.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>

namespace tierlift::ir::numerics {

inline constexpr float kFltMax = FLT_MAX;

// --- basic arithmetic -----------------------------------------------------------------

// 0 × anything = +0, even ±inf and NaN (d3d9-isa.md §8.3: observed on NVIDIA, AMD and
// Intel; DXVK "Strict", Nine MUL_ZERO_WINS). Used by mul, mad, dp*, matrix macros, lrp,
// crs, nrm, dst, dp2add and every product inside texture-address instructions.
inline float legacy_mul(float a, float b) {
  return (a == 0.0f || b == 0.0f) ? 0.0f : a * b;
}

// mad = round(round(a × b) + c): not fused. legacy_mul's select sits between the product
// and the sum, so no compiler can contract them into an FMA.
inline float legacy_mad(float a, float b, float c) {
  return legacy_mul(a, b) + c;
}

// Dot products sum left to right: ((x0·y0 + x1·y1) + x2·y2) + x3·y3.
inline float legacy_dp2(const float* a, const float* b) {
  return legacy_mul(a[0], b[0]) + legacy_mul(a[1], b[1]);
}
inline float legacy_dp3(const float* a, const float* b) {
  return legacy_dp2(a, b) + legacy_mul(a[2], b[2]);
}
inline float legacy_dp4(const float* a, const float* b) {
  return legacy_dp3(a, b) + legacy_mul(a[3], b[3]);
}

// lrp: d = s2 + s0·(s1 − s2), evaluated in exactly that order.
inline float legacy_lrp(float s0, float s1, float s2) {
  return legacy_mul(s0, s1 - s2) + s2;
}

// Clamp a magnitude to ±FLT_MAX; NaN passes through (both compares are false).
inline float clamp_to_flt_max(float x) {
  return x > kFltMax ? kFltMax : (x < -kFltMax ? -kFltMax : x);
}

// --- scalar transcendental instructions ----------------------------------------------

// rcp: exactly 1 for 1; +FLT_MAX for ±0 (the doc pseudo-code "f == 0 ? +big"); overflow of
// tiny (denormal) inputs clamps to ±FLT_MAX. rcp(±inf) = ±0, rcp(NaN) = NaN.
inline float legacy_rcp(float x) {
  if (x == 1.0f) return 1.0f;
  if (x == 0.0f) return kFltMax;
  return clamp_to_flt_max(1.0f / x);
}

// rsq: absolute value first (never NaN for negative input); exactly 1 for ±1; +FLT_MAX for
// ±0. rsq(inf) = 0, rsq(NaN) = NaN.
inline float legacy_rsq(float x) {
  float f = std::fabs(x);
  if (f == 1.0f) return 1.0f;
  if (f == 0.0f) return kFltMax;
  return clamp_to_flt_max(1.0f / std::sqrt(f));
}

// log (and logp): log2|x|; log(±0) = −FLT_MAX; log(inf) = +inf; log(NaN) = NaN.
inline float legacy_log(float x) {
  float f = std::fabs(x);
  if (f == 0.0f) return -kFltMax;
  return std::log2(f);
}

// exp: 2^x; overflow (x ≥ 128, +inf) gives +FLT_MAX instead of +inf; exp(−inf) = 0;
// exp(NaN) = NaN.
inline float legacy_exp(float x) {
  return clamp_to_flt_max(std::exp2(x));
}

// pow: |x|^y expanded as exp(y·log2|x|), the expansion the docs allow. pow(x, 0) = 1 for
// every x (0, inf and NaN included); pow(0, y>0) = 0; pow(0, y<0) = +FLT_MAX.
inline float legacy_pow(float x, float y) {
  if (y == 0.0f) return 1.0f;
  return legacy_exp(legacy_mul(y, std::log2(std::fabs(x))));
}

// nrm's scale factor from the squared length: 0 for a zero vector (so nrm(0) = (0,0,0,0),
// as Wine's tests observe: "nrm never generates INF or NAN"), else legacy_rsq.
inline float legacy_nrm_scale(float len2) {
  return len2 == 0.0f ? 0.0f : legacy_rsq(len2);
}

// --- comparisons and selects (ordered: NaN makes the compare false) ------------------

inline float legacy_min(float a, float b) {
  return a < b ? a : b;
}
inline float legacy_max(float a, float b) {
  return a >= b ? a : b;
}
inline float legacy_sge(float a, float b) {
  return a >= b ? 1.0f : 0.0f;
}
inline float legacy_slt(float a, float b) {
  return a < b ? 1.0f : 0.0f;
}
inline float legacy_cmp(float c, float a, float b) {
  return c >= 0.0f ? a : b;
}
inline float legacy_cnd(float c, float a, float b) {
  return c > 0.5f ? a : b;
}
// sgn as the doc writes it: (x < 0) ? −1 : (x == 0) ? 0 : 1 — so sgn(NaN) = 1.
inline float legacy_sgn(float x) {
  return x < 0.0f ? -1.0f : (x == 0.0f ? 0.0f : 1.0f);
}

// Saturate to [0, 1]; NaN becomes 0 (both compares false → 0).
inline float legacy_saturate(float x) {
  return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f;
}

// frc: x − floor(x), computed literally (not GLSL fract, which may clamp below 1): a tiny
// negative x rounds to exactly 1.0. frc(±inf) = NaN.
inline float legacy_frc(float x) {
  return x - std::floor(x);
}

// --- texm3x3spec / texm3x3vspec reflection ------------------------------------------

// R = 2·(N·E)/(N·N)·N − E, evaluated as k = (2·(N·E)) / (N·N), R_i = k·N_i − E_i. A zero
// normal (N·N = 0) gives k = 0, so R = −E instead of a division by zero.
struct Vec3f {
  float x, y, z;
};
inline Vec3f legacy_reflect(Vec3f n, Vec3f e) {
  float ne = legacy_mul(n.x, e.x) + legacy_mul(n.y, e.y) + legacy_mul(n.z, e.z);
  float nn = legacy_mul(n.x, n.x) + legacy_mul(n.y, n.y) + legacy_mul(n.z, n.z);
  float k = nn == 0.0f ? 0.0f : (2.0f * ne) / nn;
  return {legacy_mul(k, n.x) - e.x, legacy_mul(k, n.y) - e.y, legacy_mul(k, n.z) - e.z};
}

// ps_1_x depth replacement (texm3x2depth z/w, ps_1_4 texdepth r/g): a zero divisor gives
// 1.0 (d3d9-isa.md §5.5, §5.6). The device clamps depth to [0, 1] at the depth test.
inline float legacy_depth_ratio(float num, float den) {
  return den == 0.0f ? 1.0f : num / den;
}

// --- lit --------------------------------------------------------------------------------

inline constexpr float kLitPowerLimit = 127.9961f;
// lit per the doc pseudo-code, strict "> 0" tests: returns d = (1, y', z', 1).
struct LitResult {
  float x, y, z, w;
};
inline LitResult legacy_lit(float sx, float sy, float sw) {
  float p = sw > kLitPowerLimit ? kLitPowerLimit : (sw < -kLitPowerLimit ? -kLitPowerLimit : sw);
  LitResult d{1.0f, 0.0f, 0.0f, 1.0f};
  if (sx > 0.0f) {
    d.y = sx;
    if (sy > 0.0f) d.z = legacy_pow(sy, p);
  }
  return d;
}

// --- address register conversion -----------------------------------------------------

// Keeps float→int conversions defined: NaN → 0, magnitudes clamp to ±2^20 (far beyond any
// constant index), then the cast.
inline int32_t clamp_index_float(float v) {
  if (!(v == v)) return 0;
  if (v > 1048576.0f) v = 1048576.0f;
  if (v < -1048576.0f) v = -1048576.0f;
  return static_cast<int32_t>(v);
}
// vs_1_1 `mov a0.x, s`: floor (DXVK, Wine; the doc's "round" is wrong, d3d9-isa.md §8.5).
inline int32_t legacy_mov_a0_floor(float x) {
  return clamp_index_float(std::floor(x));
}
// vs_2_0 `mova`: round to nearest, ties away from zero (Wine, MojoShader):
// sign(x)·floor(|x| + 0.5).
inline int32_t legacy_mova_round(float x) {
  float r = std::floor(std::fabs(x) + 0.5f);
  return clamp_index_float(x < 0.0f ? -r : r);
}

// --- ps_1_x ranges --------------------------------------------------------------------

// Source modifiers (d3d9-isa.md §4.2), each one rounding.
inline float legacy_bias(float x) {
  return x - 0.5f;
}
inline float legacy_bx2(float x) {
  return 2.0f * x - 1.0f;
} // 2x is exact: no fusion issue
inline float legacy_comp(float x) {
  return 1.0f - x;
}

// Constants read in ps_1_x clamp to [−1, 1] (NaN passes through).
inline float legacy_ps1x_const(float x) {
  return x > 1.0f ? 1.0f : (x < -1.0f ? -1.0f : x);
}
// Register writes in ps_1_x clamp to [−max, +max] (NaN passes through).
inline float legacy_ps1x_range(float x, float max) {
  return x > max ? max : (x < -max ? -max : x);
}
// Fixed-point emulation: nearest multiple of 2^-bits (ties round up: floor(x·2^bits + 0.5)),
// limited to the largest multiple within ±max. NaN becomes 0 (fixed point has no NaN).
inline float legacy_fixed_quantise(float x, int bits, float max) {
  if (!(x == x)) return 0.0f;
  float scale = std::ldexp(1.0f, bits);
  float lim = std::floor(max * scale); // in units of 2^-bits
  float u = std::floor(x * scale + 0.5f);
  u = u > lim ? lim : (u < -lim ? -lim : u);
  return u / scale;
}

} // namespace tierlift::ir::numerics
