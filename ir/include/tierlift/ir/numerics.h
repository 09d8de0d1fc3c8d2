// The legacy numeric rules of Direct3D 9 shader arithmetic, each defined once, by name
// (docs/design.md "Conventions"; docs/d3d9-rules.md §5, §8). The CPU interpreter calls these
// functions and the SPIR-V code generator emits exactly the same sequence of operations, so the two
// cannot drift. NUMERICS.md (repo root) states every rule, why it was chosen and which test
// checks it.
//
// Common choices (see NUMERICS.md for the reasons):
//  * Special results are finite: rcp(0), rsq(0) and every overflow of rcp/rsq/exp give
//    +FLT_MAX (or -FLT_MAX), never infinity; log(0) gives -FLT_MAX.
//  * 0 × anything = +0, including ±inf and NaN (legacy_mul).
//  * mad is NOT fused: the product is rounded to fp32, then the sum (SPIR-V: NoContraction).
//  * Denormals (NUMERICS.md rule 13): every rule is a template on Denormals. Keep (the
//    default) is IEEE: denormals in and out. Flush is what lavapipe measures: each fp32
//    operation and comparison reads a denormal operand as a zero of its sign and writes a
//    denormal result as a zero of its sign; a select passes its operand's bits on.
//  * Comparisons are ordered: a NaN makes every compare false (the documentation's ternaries).
//
// Every function uses only fp32 operations with one rounding each, so that the emitted
// SPIR-V can reproduce them bit for bit. Ternaries are written so that the false branch is
// the one a NaN takes.
#pragma once

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>

namespace tierlift::ir::numerics {

inline constexpr float kFltMax = FLT_MAX;

// --- denormals (NUMERICS.md rule 13) ---------------------------------------------------

enum class Denormals : uint8_t {
  Keep,  // IEEE: denormal operands and results are kept (ir::Rounding::Exact)
  Flush, // as lavapipe (x86 DAZ + FTZ): in and out of every operation (Rounding::Llvmpipe)
};
inline constexpr Denormals kKeep = Denormals::Keep, kFlush = Denormals::Flush;

// A denormal becomes the zero of its sign; every other value (±0, NaN, ±inf) is kept.
inline float flush_denormal(float x) {
  const auto u = std::bit_cast<uint32_t>(x);
  return (u & 0x7F800000u) == 0 ? std::bit_cast<float>(u & 0x80000000u) : x;
}
// An operand (in) or result (out) of one fp32 operation under D.
template <Denormals D> inline float dz(float x) {
  if constexpr (D == Denormals::Flush) return flush_denormal(x);
  return x;
}

// The single fp32 operations, each one rounding, under D. Data movement (mov, swizzles,
// the negate and abs modifiers, selects) is not an operation: it keeps every bit.
template <Denormals D = kKeep> inline float legacy_add(float a, float b) {
  return dz<D>(dz<D>(a) + dz<D>(b));
}
template <Denormals D = kKeep> inline float legacy_sub(float a, float b) {
  return dz<D>(dz<D>(a) - dz<D>(b));
}
// A plain product (no 0 × inf rule): the ps_1_x shift and the _x2 source modifier, whose
// factor is a power of two.
template <Denormals D = kKeep> inline float legacy_scale(float a, float b) {
  return dz<D>(dz<D>(a) * dz<D>(b));
}
template <Denormals D = kKeep> inline float legacy_div(float a, float b) {
  return dz<D>(dz<D>(a) / dz<D>(b));
}
template <Denormals D = kKeep> inline float legacy_floor(float x) {
  return std::floor(dz<D>(x));
}
template <Denormals D = kKeep> inline float legacy_sin(float x) {
  return dz<D>(std::sin(dz<D>(x)));
}
template <Denormals D = kKeep> inline float legacy_cos(float x) {
  return dz<D>(std::cos(dz<D>(x)));
}

// --- basic arithmetic -----------------------------------------------------------------

// 0 × anything = +0, even ±inf and NaN (docs/d3d9-rules.md §8.3: observed on NVIDIA, AMD and
// Intel; DXVK "Strict", Nine MUL_ZERO_WINS). Used by mul, mad, dp*, matrix macros, lrp,
// crs, nrm, dst, dp2add and every product inside texture-address instructions. Under
// Flush a denormal factor compares equal to 0, so the product is +0.
template <Denormals D = kKeep> inline float legacy_mul(float a, float b) {
  a = dz<D>(a);
  b = dz<D>(b);
  return (a == 0.0f || b == 0.0f) ? 0.0f : dz<D>(a * b);
}

// mad = round(round(a × b) + c): not fused. legacy_mul's select sits between the product
// and the sum, so no compiler can contract them into an FMA.
template <Denormals D = kKeep> inline float legacy_mad(float a, float b, float c) {
  return legacy_add<D>(legacy_mul<D>(a, b), c);
}

// Dot products sum left to right: ((x0·y0 + x1·y1) + x2·y2) + x3·y3.
template <Denormals D = kKeep> inline float legacy_dp2(const float* a, const float* b) {
  return legacy_add<D>(legacy_mul<D>(a[0], b[0]), legacy_mul<D>(a[1], b[1]));
}
template <Denormals D = kKeep> inline float legacy_dp3(const float* a, const float* b) {
  return legacy_add<D>(legacy_dp2<D>(a, b), legacy_mul<D>(a[2], b[2]));
}
template <Denormals D = kKeep> inline float legacy_dp4(const float* a, const float* b) {
  return legacy_add<D>(legacy_dp3<D>(a, b), legacy_mul<D>(a[3], b[3]));
}

// lrp: d = s2 + s0·(s1 − s2), evaluated in exactly that order.
template <Denormals D = kKeep> inline float legacy_lrp(float s0, float s1, float s2) {
  return legacy_add<D>(legacy_mul<D>(s0, legacy_sub<D>(s1, s2)), s2);
}

// Clamp a magnitude to ±FLT_MAX; NaN passes through (both compares are false).
inline float clamp_to_flt_max(float x) {
  return x > kFltMax ? kFltMax : (x < -kFltMax ? -kFltMax : x);
}

// --- scalar transcendental instructions ----------------------------------------------

// rcp: exactly 1 for 1; +FLT_MAX for ±0 (the doc pseudo-code "f == 0 ? +big"); overflow of
// tiny (denormal) inputs clamps to ±FLT_MAX. rcp(±inf) = ±0, rcp(NaN) = NaN. Under Flush a
// denormal is ±0, so rcp(−1e-40) = +FLT_MAX.
template <Denormals D = kKeep> inline float legacy_rcp(float x) {
  x = dz<D>(x);
  if (x == 1.0f) return 1.0f;
  if (x == 0.0f) return kFltMax;
  return clamp_to_flt_max(dz<D>(1.0f / x));
}

// rsq: absolute value first (never NaN for negative input); exactly 1 for ±1; +FLT_MAX for
// ±0. rsq(inf) = 0, rsq(NaN) = NaN.
template <Denormals D = kKeep> inline float legacy_rsq(float x) {
  float f = std::fabs(dz<D>(x));
  if (f == 1.0f) return 1.0f;
  if (f == 0.0f) return kFltMax;
  return clamp_to_flt_max(dz<D>(1.0f / std::sqrt(f)));
}

// log (and logp): log2|x|; log(±0) = −FLT_MAX; log(inf) = +inf; log(NaN) = NaN.
template <Denormals D = kKeep> inline float legacy_log(float x) {
  float f = std::fabs(dz<D>(x));
  if (f == 0.0f) return -kFltMax;
  return std::log2(f);
}

// exp: 2^x; overflow (x ≥ 128, +inf) gives +FLT_MAX instead of +inf; exp(−inf) = 0;
// exp(NaN) = NaN. Under Flush a result below 2^-126 is 0.
template <Denormals D = kKeep> inline float legacy_exp(float x) {
  return clamp_to_flt_max(dz<D>(std::exp2(dz<D>(x))));
}

// pow: |x|^y expanded as exp(y·log2|x|), the expansion the docs allow. pow(x, 0) = 1 for
// every x (0, inf and NaN included); pow(0, y>0) = 0; pow(0, y<0) = +FLT_MAX.
template <Denormals D = kKeep> inline float legacy_pow(float x, float y) {
  if (dz<D>(y) == 0.0f) return 1.0f;
  return legacy_exp<D>(legacy_mul<D>(y, std::log2(std::fabs(dz<D>(x)))));
}

// nrm's scale factor from the squared length: 0 for a zero vector (so nrm(0) = (0,0,0,0),
// as Wine's tests observe: "nrm never generates INF or NAN"), else legacy_rsq.
template <Denormals D = kKeep> inline float legacy_nrm_scale(float len2) {
  return dz<D>(len2) == 0.0f ? 0.0f : legacy_rsq<D>(len2);
}

// --- comparisons and selects (ordered: NaN makes the compare false) ------------------
// Under Flush the compare reads denormals as zeros, and the select hands on the chosen
// operand's own bits (lavapipe blends; measured in tests/vulkan/denormals_test.cpp).

template <Denormals D = kKeep> inline float legacy_min(float a, float b) {
  return dz<D>(a) < dz<D>(b) ? a : b;
}
template <Denormals D = kKeep> inline float legacy_max(float a, float b) {
  return dz<D>(a) >= dz<D>(b) ? a : b;
}
template <Denormals D = kKeep> inline float legacy_sge(float a, float b) {
  return dz<D>(a) >= dz<D>(b) ? 1.0f : 0.0f;
}
template <Denormals D = kKeep> inline float legacy_slt(float a, float b) {
  return dz<D>(a) < dz<D>(b) ? 1.0f : 0.0f;
}
template <Denormals D = kKeep> inline float legacy_cmp(float c, float a, float b) {
  return dz<D>(c) >= 0.0f ? a : b;
}
template <Denormals D = kKeep> inline float legacy_cnd(float c, float a, float b) {
  return dz<D>(c) > 0.5f ? a : b;
}
// sgn as the doc writes it: (x < 0) ? −1 : (x == 0) ? 0 : 1 — so sgn(NaN) = 1.
template <Denormals D = kKeep> inline float legacy_sgn(float x) {
  x = dz<D>(x);
  return x < 0.0f ? -1.0f : (x == 0.0f ? 0.0f : 1.0f);
}

// Saturate to [0, 1]; NaN becomes 0 (both compares false → 0). A denormal is 0 under Flush.
template <Denormals D = kKeep> inline float legacy_saturate(float x) {
  x = dz<D>(x);
  return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f;
}

// frc: x − floor(x), computed literally (not GLSL fract, which may clamp below 1): a tiny
// negative x rounds to exactly 1.0 (a denormal one is 0 under Flush). frc(±inf) = NaN.
template <Denormals D = kKeep> inline float legacy_frc(float x) {
  return legacy_sub<D>(x, legacy_floor<D>(x));
}

// --- texm3x3spec / texm3x3vspec reflection ------------------------------------------

// R = 2·(N·E)/(N·N)·N − E, evaluated as k = (2·(N·E)) / (N·N), R_i = k·N_i − E_i. A zero
// normal (N·N = 0) gives k = 0, so R = −E instead of a division by zero.
struct Vec3f {
  float x, y, z;
};
template <Denormals D = kKeep> inline Vec3f legacy_reflect(Vec3f n, Vec3f e) {
  auto mul = legacy_mul<D>;
  auto add = legacy_add<D>;
  auto sub = legacy_sub<D>;
  float ne = add(add(mul(n.x, e.x), mul(n.y, e.y)), mul(n.z, e.z));
  float nn = add(add(mul(n.x, n.x), mul(n.y, n.y)), mul(n.z, n.z));
  float k = nn == 0.0f ? 0.0f : legacy_div<D>(legacy_scale<D>(2.0f, ne), nn);
  return {sub(mul(k, n.x), e.x), sub(mul(k, n.y), e.y), sub(mul(k, n.z), e.z)};
}

// ps_1_x depth replacement (texm3x2depth z/w, ps_1_4 texdepth r/g): a zero divisor gives
// 1.0 (docs/d3d9-rules.md §5.5, §5.6). The device clamps depth to [0, 1] at the depth test.
template <Denormals D = kKeep> inline float legacy_depth_ratio(float num, float den) {
  return dz<D>(den) == 0.0f ? 1.0f : legacy_div<D>(num, den);
}

// --- lit --------------------------------------------------------------------------------

inline constexpr float kLitPowerLimit = 127.9961f;
// lit per the doc pseudo-code, strict "> 0" tests: returns d = (1, y', z', 1).
struct LitResult {
  float x, y, z, w;
};
template <Denormals D = kKeep> inline LitResult legacy_lit(float sx, float sy, float sw) {
  sw = dz<D>(sw);
  float p = sw > kLitPowerLimit ? kLitPowerLimit : (sw < -kLitPowerLimit ? -kLitPowerLimit : sw);
  LitResult d{1.0f, 0.0f, 0.0f, 1.0f};
  if (dz<D>(sx) > 0.0f) {
    d.y = sx;
    if (dz<D>(sy) > 0.0f) d.z = legacy_pow<D>(sy, p);
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
// vs_1_1 `mov a0.x, s`: floor (DXVK, Wine; the doc's "round" is wrong, docs/d3d9-rules.md §8.5).
template <Denormals D = kKeep> inline int32_t legacy_mov_a0_floor(float x) {
  return clamp_index_float(legacy_floor<D>(x));
}
// vs_2_0 `mova`: round to nearest, ties away from zero (Wine, MojoShader):
// sign(x)·floor(|x| + 0.5).
template <Denormals D = kKeep> inline int32_t legacy_mova_round(float x) {
  x = dz<D>(x);
  float r = std::floor(std::fabs(x) + 0.5f);
  return clamp_index_float(x < 0.0f ? -r : r);
}

// --- ps_1_x ranges --------------------------------------------------------------------

// Source modifiers (docs/d3d9-rules.md §4.2), each one rounding.
template <Denormals D = kKeep> inline float legacy_bias(float x) {
  return legacy_sub<D>(x, 0.5f);
}
template <Denormals D = kKeep> inline float legacy_bx2(float x) {
  return legacy_sub<D>(legacy_scale<D>(2.0f, x), 1.0f);
} // 2x is exact: no fusion issue
template <Denormals D = kKeep> inline float legacy_comp(float x) {
  return legacy_sub<D>(1.0f, x);
}

// Constants read in ps_1_x clamp to [−1, 1] (NaN passes through). Under Flush the result is
// flushed too: lavapipe compiles a clamp against constants into min/max instructions, which
// flush (measured, tests/vulkan/denormals_test.cpp), unlike a select between two operands.
template <Denormals D = kKeep> inline float legacy_ps1x_const(float x) {
  x = dz<D>(x);
  return x > 1.0f ? 1.0f : (x < -1.0f ? -1.0f : x);
}
// Register writes in ps_1_x clamp to [−max, +max] (NaN passes through); flushed as above.
template <Denormals D = kKeep> inline float legacy_ps1x_range(float x, float max) {
  x = dz<D>(x);
  return x > max ? max : (x < -max ? -max : x);
}
// Fixed-point emulation: nearest multiple of 2^-bits (ties round up: floor(x·2^bits + 0.5)),
// limited to the largest multiple within ±max. NaN becomes 0 (fixed point has no NaN).
template <Denormals D = kKeep> inline float legacy_fixed_quantise(float x, int bits, float max) {
  x = dz<D>(x);
  if (!(x == x)) return 0.0f;
  float scale = std::ldexp(1.0f, bits);
  float lim = std::floor(max * scale); // in units of 2^-bits
  float u = std::floor(x * scale + 0.5f);
  u = u > lim ? lim : (u < -lim ? -lim : u);
  return u / scale;
}

} // namespace tierlift::ir::numerics
