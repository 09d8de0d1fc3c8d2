// The legacy numeric rules of Direct3D 9 shader arithmetic on fp32 scalars, by name. Each
// rule is written once, as a template over an arithmetic back end (numeric_rules.h); this
// header is the fp32 back end (FloatArith) and the named functions the CPU interpreter
// calls. The SPIR-V code generator instantiates the same templates with a back end that
// emits instructions, so the two cannot drift. NUMERICS.md (repo root) states every rule,
// why it was chosen and which test checks it.
//
// Common choices (see NUMERICS.md for the reasons):
//  * Special results are finite: rcp(0), rsq(0) and every overflow of rcp/rsq/exp give
//    +FLT_MAX (or -FLT_MAX), never infinity; log(0) gives -FLT_MAX.
//  * 0 × anything = +0, including ±inf and NaN (legacy_mul).
//  * mad is NOT fused: the product is rounded to fp32, then the sum (SPIR-V: NoContraction).
//  * Denormals (NUMERICS.md rule 13): the fp32 back end is a template on Denormals. Keep (the
//    default) is IEEE: denormals in and out. Flush is what lavapipe measures: each fp32
//    operation and comparison reads a denormal operand as a zero of its sign and writes a
//    denormal result as a zero of its sign; a select passes its operand's bits on.
//  * Comparisons are ordered: a NaN makes every compare false (the sheet's ternaries).
//
// Every rule uses only fp32 operations with one rounding each, so that the emitted SPIR-V
// reproduces them bit for bit; both sides of a choice are computed and selected, the false
// branch being the one a NaN takes.
#pragma once

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>

#include "tierlift/ir/numeric_rules.h"

namespace tierlift::ir::numerics {

inline constexpr float kFltMax = rule::kFltMax;

// --- denormals (NUMERICS.md rule 13) ---------------------------------------------------

enum class Denormals : uint8_t {
  Keep,  // IEEE: denormal operands and results are kept (ir::Rounding::Exact)
  Flush, // as lavapipe (x86 DAZ + FTZ): in and out of every operation (Rounding::Llvmpipe)
  // Flush, for a rule whose operands are known to hold no denormal (the CPU block executor
  // proves it per instruction): results are flushed, operands are not looked at. The same
  // values as Flush for such operands, since flushing a non-denormal changes nothing; every
  // value inside a rule is then a flushed result, a constant or a select among those.
  FlushResults,
};
inline constexpr Denormals kKeep = Denormals::Keep, kFlush = Denormals::Flush;

// A denormal becomes the zero of its sign; every other value (±0, NaN, ±inf) is kept.
inline float flush_denormal(float x) {
  const auto u = std::bit_cast<uint32_t>(x);
  return (u & 0x7F800000u) == 0 ? std::bit_cast<float>(u & 0x80000000u) : x;
}
// x never compares equal to zero, whatever the denormal mode: its exponent field is not 0
// (a normal number, an infinity or a NaN). A product with such a factor need test only the
// other one for rule 8 (mul_y_nonzero; the code generator's known_*_constants).
inline bool never_compares_zero(float x) {
  return (std::bit_cast<uint32_t>(x) & 0x7F800000u) != 0;
}
// x is +0 or −0 (a denormal is not: Rounding::Exact keeps it).
inline bool signed_zero(float x) {
  return (std::bit_cast<uint32_t>(x) & 0x7FFFFFFFu) == 0;
}

// A result (or, outside FloatArith, any value) of one fp32 operation under D.
template <Denormals D> inline float dz(float x) {
  if constexpr (D != Denormals::Keep) return flush_denormal(x);
  return x;
}
// An operand of one fp32 operation under D (FloatArith): FlushResults leaves it alone.
template <Denormals D> inline float dz_in(float x) {
  if constexpr (D == Denormals::Flush) return flush_denormal(x);
  return x;
}

// The fp32 back end of the rule templates under D. The single fp32 operations each round
// once; data movement (negate, abs, select) keeps every bit; compares read operands as the
// operations do. ftz: a clamp's min/max flushes its result (NUMERICS.md rule 13).
template <Denormals D> struct FloatArith {
  using V = float;
  using B = bool;
  static float k(float x) { return x; }
  static float add(float a, float b) { return dz<D>(dz_in<D>(a) + dz_in<D>(b)); }
  static float sub(float a, float b) { return dz<D>(dz_in<D>(a) - dz_in<D>(b)); }
  static float fmul(float a, float b) { return dz<D>(dz_in<D>(a) * dz_in<D>(b)); }
  static float fmul_y_normal(float a, float b) { return dz<D>(dz_in<D>(a) * b); }
  static float div(float a, float b) { return dz<D>(dz_in<D>(a) / dz_in<D>(b)); }
  static float neg(float a) { return -a; }
  static float abs(float a) { return std::fabs(a); }
  static float floor(float a) { return std::floor(dz_in<D>(a)); }
  static float sqrt(float a) { return dz<D>(std::sqrt(dz_in<D>(a))); }
  static float exp2(float a) { return dz<D>(std::exp2(dz_in<D>(a))); }
  static float log2(float a) { return std::log2(dz_in<D>(a)); }
  static float sin(float a) { return dz<D>(std::sin(dz_in<D>(a))); }
  static float cos(float a) { return dz<D>(std::cos(dz_in<D>(a))); }
  static bool eq(float a, float b) { return dz_in<D>(a) == dz_in<D>(b); }
  static bool lt(float a, float b) { return dz_in<D>(a) < dz_in<D>(b); }
  static bool gt(float a, float b) { return dz_in<D>(a) > dz_in<D>(b); }
  static bool ge(float a, float b) { return dz_in<D>(a) >= dz_in<D>(b); }
  static bool lor(bool a, bool b) { return a || b; }
  static bool land(bool a, bool b) { return a && b; }
  static bool is_nan(float a) { return a != a; }
  static float select(bool c, float a, float b) { return c ? a : b; }
  static float ftz(float a) { return dz<D>(a); }
};

// The named rules on fp32 scalars (NUMERICS.md gives each rule's number and reason).
#define TIERLIFT_FP32_RULE(name, rule_name, params, args)                                          \
  template <Denormals D = kKeep> inline float name params {                                        \
    return rule::rule_name(FloatArith<D>{}, args);                                                 \
  }

// Single operations. legacy_scale is a plain product (no 0 × inf rule): the ps_1_x shift
// and the _x2 source modifier, whose factor is a power of two.
template <Denormals D = kKeep> inline float legacy_add(float a, float b) {
  return FloatArith<D>::add(a, b);
}
template <Denormals D = kKeep> inline float legacy_sub(float a, float b) {
  return FloatArith<D>::sub(a, b);
}
template <Denormals D = kKeep> inline float legacy_scale(float a, float b) {
  return FloatArith<D>::fmul(a, b);
}
template <Denormals D = kKeep> inline float legacy_div(float a, float b) {
  return FloatArith<D>::div(a, b);
}
template <Denormals D = kKeep> inline float legacy_sin(float x) {
  return FloatArith<D>::sin(x);
}
template <Denormals D = kKeep> inline float legacy_cos(float x) {
  return FloatArith<D>::cos(x);
}

#define TL_ARGS(...) __VA_ARGS__
// Products (rules 8, 14) and lrp.
TIERLIFT_FP32_RULE(legacy_mul, mul, (float a, float b), TL_ARGS(a, b))
TIERLIFT_FP32_RULE(legacy_mad, mad, (float a, float b, float c), TL_ARGS(a, b, c))
// The same with a factor known never to compare equal to zero (numeric_rules.h).
TIERLIFT_FP32_RULE(legacy_mul_y_nonzero, mul_y_nonzero, (float a, float b), TL_ARGS(a, b))
TIERLIFT_FP32_RULE(legacy_mul_x_nonzero, mul_x_nonzero, (float a, float b), TL_ARGS(a, b))
TIERLIFT_FP32_RULE(legacy_mad_y_nonzero, mad_y_nonzero, (float a, float b, float c),
                   TL_ARGS(a, b, c))
TIERLIFT_FP32_RULE(legacy_mad_x_nonzero, mad_x_nonzero, (float a, float b, float c),
                   TL_ARGS(a, b, c))
TIERLIFT_FP32_RULE(legacy_lrp, lrp, (float s0, float s1, float s2), TL_ARGS(s0, s1, s2))
// Scalar transcendental instructions (rules 1–7, 16–18).
TIERLIFT_FP32_RULE(legacy_rcp, rcp, (float x), x)
TIERLIFT_FP32_RULE(legacy_rsq, rsq, (float x), x)
TIERLIFT_FP32_RULE(legacy_log, log, (float x), x)
TIERLIFT_FP32_RULE(legacy_exp, exp, (float x), x)
TIERLIFT_FP32_RULE(legacy_pow, pow, (float x, float y), TL_ARGS(x, y))
TIERLIFT_FP32_RULE(legacy_nrm_scale, nrm_scale, (float len2), len2)
// Ordered compares and selects (rules 9–12): a NaN takes the false branch.
TIERLIFT_FP32_RULE(legacy_min, min, (float a, float b), TL_ARGS(a, b))
TIERLIFT_FP32_RULE(legacy_max, max, (float a, float b), TL_ARGS(a, b))
TIERLIFT_FP32_RULE(legacy_sge, sge, (float a, float b), TL_ARGS(a, b))
TIERLIFT_FP32_RULE(legacy_slt, slt, (float a, float b), TL_ARGS(a, b))
TIERLIFT_FP32_RULE(legacy_cmp, cmp, (float c, float a, float b), TL_ARGS(c, a, b))
TIERLIFT_FP32_RULE(legacy_cnd, cnd, (float c, float a, float b), TL_ARGS(c, a, b))
TIERLIFT_FP32_RULE(legacy_sgn, sgn, (float x), x)
// _sat (rule 23), frc (rule 22) and the depth ratio (rule 30).
TIERLIFT_FP32_RULE(legacy_saturate, saturate, (float x), x)
TIERLIFT_FP32_RULE(legacy_frc, frc, (float x), x)
TIERLIFT_FP32_RULE(legacy_depth_ratio, depth_ratio, (float num, float den), TL_ARGS(num, den))
#undef TL_ARGS
#undef TIERLIFT_FP32_RULE

// Dot products over fp32 arrays (rule 15).
template <Denormals D = kKeep> inline float legacy_dp2(const float* a, const float* b) {
  return rule::dot(FloatArith<D>{}, a, b, 2);
}
template <Denormals D = kKeep> inline float legacy_dp3(const float* a, const float* b) {
  return rule::dot(FloatArith<D>{}, a, b, 3);
}
template <Denormals D = kKeep> inline float legacy_dp4(const float* a, const float* b) {
  return rule::dot(FloatArith<D>{}, a, b, 4);
}

// texm3x3spec / texm3x3vspec reflection (rule 31).
struct Vec3f {
  float x, y, z;
};
template <Denormals D = kKeep> inline Vec3f legacy_reflect(Vec3f n, Vec3f e) {
  const FloatArith<D> a;
  const float nv[3] = {n.x, n.y, n.z}, ev[3] = {e.x, e.y, e.z};
  const float k = rule::reflect_scale(a, rule::dot(a, nv, ev, 3), rule::dot(a, nv, nv, 3));
  return {rule::reflect_component(a, k, n.x, e.x), rule::reflect_component(a, k, n.y, e.y),
          rule::reflect_component(a, k, n.z, e.z)};
}

// lit (rule 19): d = (1, y', z', 1).
inline constexpr float kLitPowerLimit = rule::kLitPowerLimit;
using LitResult = rule::Lanes4<float>;
template <Denormals D = kKeep> inline LitResult legacy_lit(float sx, float sy, float sw) {
  return rule::lit(FloatArith<D>{}, sx, sy, sw);
}

// Address register conversion (rules 20, 21): NaN → 0, magnitudes clamp to ±2^20 (far
// beyond any constant index), then the cast keeps the conversion defined.
template <Denormals D = kKeep> inline int32_t clamp_index_float(float v) {
  return static_cast<int32_t>(rule::index_range(FloatArith<D>{}, v));
}
template <Denormals D = kKeep> inline int32_t legacy_mov_a0_floor(float x) {
  return clamp_index_float<D>(rule::mov_a0_floor(FloatArith<D>{}, x));
}
template <Denormals D = kKeep> inline int32_t legacy_mova_round(float x) {
  return clamp_index_float<D>(rule::mova_round(FloatArith<D>{}, x));
}

// ps_1_x ranges (rules 24, 25, 27).
template <Denormals D = kKeep> inline float legacy_ps1x_const(float x) {
  return rule::clamp_sym(FloatArith<D>{}, x, 1.0f);
}
template <Denormals D = kKeep> inline float legacy_ps1x_range(float x, float max) {
  return rule::clamp_sym(FloatArith<D>{}, x, max);
}
template <Denormals D = kKeep> inline float legacy_fixed_quantise(float x, int bits, float max) {
  return rule::fixed_quantise(FloatArith<D>{}, x, std::ldexp(1.0f, bits), max);
}

} // namespace tierlift::ir::numerics
