// The legacy numeric rules of Direct3D 9 shader arithmetic (NUMERICS.md), each written once
// as a template over an arithmetic back end. The CPU interpreter instantiates them with
// fp32 scalars (numerics.h, FloatArith<D>); the SPIR-V code generator with a back end whose
// values are SPIR-V ids and whose operations emit one instruction each
// (codegen/src/emit_numerics.cpp). Because both run the very same sequence of operations,
// the two devices cannot drift apart.
//
// A back end `A` provides a value type `A::V`, a condition type `A::B` and:
//   k(x)                      a constant of the back end's width
//   add sub fmul div          one fp32 operation each, one rounding (fmul: a plain product)
//   fmul_y_normal(x, y)       fmul when y is known not to be a denormal (the Flush mode
//                             need not flush it; the value is fmul's)
//   neg abs                   data movement: they change the sign bit only
//   floor sqrt exp2 log2      one operation each
//   eq lt gt ge               ordered compares: a NaN makes them false
//   lor land is_nan           conditions
//   select(c, a, b)           data movement: hands on a's or b's bits
//   ftz(x)                    what a min/max instruction does to its result (NUMERICS.md 13:
//                             lavapipe compiles a clamp against constants into min/max,
//                             which flush denormals; an emitter leaves that to the device)
// Every rule evaluates both sides of a choice and selects, as the emitted code must; a
// ternary's false branch is the one a NaN takes.
#pragma once

#include <cfloat>
#include <limits>

namespace tierlift::ir::numerics::rule {

inline constexpr float kFltMax = FLT_MAX;
inline constexpr float kLitPowerLimit = 127.9961f;
inline constexpr float kIndexLimit = 1048576.0f; // 2^20, far beyond any constant index

// Rule 8: 0 × anything = +0, even ±inf and NaN (a denormal factor is 0 under Flush).
template <class A, class V = typename A::V> V mul(const A& a, V x, V y) {
  const V zero = a.k(0.0f);
  const auto x0 = a.eq(x, zero);
  const auto y0 = a.eq(y, zero);
  const auto either = a.lor(x0, y0);
  return a.select(either, zero, a.fmul(x, y));
}

// Rule 14: mad = round(round(x × y) + z), not fused.
template <class A, class V = typename A::V> V mad(const A& a, V x, V y, V z) {
  return a.add(mul(a, x, y), z);
}

// Rules 8 and 14 when one factor is known never to compare equal to zero (a non-zero
// exponent field: a normal number, an infinity or a NaN; never ±0 or a denormal, which the
// Flush mode reads as zero): only the other factor is tested. The same value as mul / mad
// for every value of the tested factor, one compare and one OR fewer. The CPU block executor
// uses them for a constant factor (vm_block.cpp); the code generator gets the same by
// folding its compare (CodegenOptions::known_*_constants).
template <class A, class V = typename A::V> V mul_y_nonzero(const A& a, V x, V y) {
  const V zero = a.k(0.0f);
  return a.select(a.eq(x, zero), zero, a.fmul_y_normal(x, y));
}
template <class A, class V = typename A::V> V mul_x_nonzero(const A& a, V x, V y) {
  const V zero = a.k(0.0f);
  return a.select(a.eq(y, zero), zero, a.fmul(x, y));
}
template <class A, class V = typename A::V> V mad_y_nonzero(const A& a, V x, V y, V z) {
  return a.add(mul_y_nonzero(a, x, y), z);
}
template <class A, class V = typename A::V> V mad_x_nonzero(const A& a, V x, V y, V z) {
  return a.add(mul_x_nonzero(a, x, y), z);
}

// Rules 8 and 14 for two plain factors (ir/plain_values.h: each +0 or a positive normal
// number): when either is zero it is +0, and +0 times a finite non-negative number is +0,
// so the plain product already is the rule's value, in every denormal mode.
template <class A, class V = typename A::V> V mul_plain(const A& a, V x, V y) {
  return a.fmul(x, y);
}
template <class A, class V = typename A::V> V mad_plain(const A& a, V x, V y, V z) {
  return a.add(mul_plain(a, x, y), z);
}

// Rule 15: dot products sum left to right, ((x0·y0 + x1·y1) + x2·y2) + x3·y3.
template <class A, class V = typename A::V> V dot(const A& a, const V* x, const V* y, int n) {
  V sum = mul(a, x[0], y[0]);
  for (int i = 1; i < n; ++i) sum = a.add(sum, mul(a, x[i], y[i]));
  return sum;
}

// dp2add: the two-component dot product, then the scalar third source.
template <class A, class V = typename A::V> V dp2add(const A& a, const V* x, const V* y, V z) {
  return a.add(dot(a, x, y, 2), z);
}

// lrp: s2 + s0·(s1 − s2), in exactly that order.
template <class A, class V = typename A::V> V lrp(const A& a, V s0, V s1, V s2) {
  return a.add(mul(a, s0, a.sub(s1, s2)), s2);
}

// A magnitude beyond ±FLT_MAX becomes ±FLT_MAX; NaN passes through.
template <class A, class V = typename A::V> V clamp_to_flt_max(const A& a, V x) {
  const V hi = a.k(kFltMax);
  const V lo = a.k(-kFltMax);
  const V inner = a.select(a.lt(x, lo), lo, x);
  return a.select(a.gt(x, hi), hi, inner);
}

// Rules 1, 2: rcp(1) = 1 exactly, rcp(±0) = +FLT_MAX, overflow clamps to ±FLT_MAX.
template <class A, class V = typename A::V> V rcp(const A& a, V x) {
  const V q = clamp_to_flt_max(a, a.div(a.k(1.0f), x));
  const V zero_case = a.select(a.eq(x, a.k(0.0f)), a.k(kFltMax), q);
  return a.select(a.eq(x, a.k(1.0f)), a.k(1.0f), zero_case);
}

// Rules 3, 4: rsq of |x|; exactly 1 for ±1, +FLT_MAX for ±0.
template <class A, class V = typename A::V> V rsq(const A& a, V x) {
  const V m = a.abs(x);
  const V q = clamp_to_flt_max(a, a.div(a.k(1.0f), a.sqrt(m)));
  const V zero_case = a.select(a.eq(m, a.k(0.0f)), a.k(kFltMax), q);
  return a.select(a.eq(m, a.k(1.0f)), a.k(1.0f), zero_case);
}

// Rules 5, 6: log2|x|, −FLT_MAX for ±0 (log2 itself only ever sees a non-zero input).
template <class A, class V = typename A::V> V log(const A& a, V x) {
  const V m = a.abs(x);
  const auto is0 = a.eq(m, a.k(0.0f));
  const V safe = a.select(is0, a.k(1.0f), m);
  return a.select(is0, a.k(-kFltMax), a.log2(safe));
}

// Rule 7: 2^x, overflow gives +FLT_MAX.
template <class A, class V = typename A::V> V exp(const A& a, V x) {
  return clamp_to_flt_max(a, a.exp2(x));
}

// Rules 16, 17: |x|^y = exp(y·log2|x|) with log2(0) = −inf; exponent 0 gives exactly 1.
template <class A, class V = typename A::V> V pow(const A& a, V x, V y) {
  const V m = a.abs(x);
  const auto is0 = a.eq(m, a.k(0.0f));
  const V lg = a.select(is0, a.k(-std::numeric_limits<float>::infinity()),
                        a.log2(a.select(is0, a.k(1.0f), m)));
  const V r = exp(a, mul(a, y, lg));
  return a.select(a.eq(y, a.k(0.0f)), a.k(1.0f), r);
}

// Rule 18: nrm's scale from the squared length: 0 for a zero vector, else rsq.
template <class A, class V = typename A::V> V nrm_scale(const A& a, V len2) {
  return a.select(a.eq(len2, a.k(0.0f)), a.k(0.0f), rsq(a, len2));
}

// Rules 9–12: ordered compares and selects.
template <class A, class V = typename A::V> V min(const A& a, V x, V y) {
  return a.select(a.lt(x, y), x, y);
}
template <class A, class V = typename A::V> V max(const A& a, V x, V y) {
  return a.select(a.ge(x, y), x, y);
}
template <class A, class V = typename A::V> V slt(const A& a, V x, V y) {
  return a.select(a.lt(x, y), a.k(1.0f), a.k(0.0f));
}
template <class A, class V = typename A::V> V sge(const A& a, V x, V y) {
  return a.select(a.ge(x, y), a.k(1.0f), a.k(0.0f));
}
template <class A, class V = typename A::V> V cmp(const A& a, V c, V x, V y) {
  return a.select(a.ge(c, a.k(0.0f)), x, y);
}
template <class A, class V = typename A::V> V cnd(const A& a, V c, V x, V y) {
  return a.select(a.gt(c, a.k(0.5f)), x, y);
}
// sgn(x) = (x < 0) ? −1 : (x == 0) ? 0 : 1, so sgn(NaN) = 1.
template <class A, class V = typename A::V> V sgn(const A& a, V x) {
  const V zero = a.k(0.0f);
  const V inner = a.select(a.eq(x, zero), zero, a.k(1.0f));
  return a.select(a.lt(x, zero), a.k(-1.0f), inner);
}

// Rule 23: saturate to [0, 1]; NaN becomes 0.
template <class A, class V = typename A::V> V saturate(const A& a, V x) {
  const V zero = a.k(0.0f);
  const V one = a.k(1.0f);
  const V inner = a.select(a.lt(x, one), x, one);
  return a.select(a.gt(x, zero), inner, zero);
}

// Rule 22: frc = x − floor(x), literally.
template <class A, class V = typename A::V> V frc(const A& a, V x) {
  return a.sub(x, a.floor(x));
}

// crs: one component of the cross product, x1·y2 − x2·y1 for (i, j) = (1, 2).
template <class A, class V = typename A::V> V cross_component(const A& a, V x1, V y2, V x2, V y1) {
  return a.sub(mul(a, x1, y2), mul(a, x2, y1));
}

// vs_1_1 expp: the D3D8 partial-precision vector (2^floor(v), v − floor(v), 2^v, 1).
template <class V> struct Lanes4 { V x, y, z, w; };
template <class A, class V = typename A::V> Lanes4<V> expp_partial(const A& a, V v) {
  const V fl = a.floor(v);
  const V e_fl = exp(a, fl);
  const V fraction = a.sub(v, fl);
  const V e_v = exp(a, v);
  return {e_fl, fraction, e_v, a.k(1.0f)};
}

// Rule 19: lit per the doc pseudo-code with strict "> 0" tests: (1, y', z', 1), the power
// clamped to ±127.9961.
template <class A, class V = typename A::V> Lanes4<V> lit(const A& a, V sx, V sy, V sw) {
  const V zero = a.k(0.0f);
  const V lim = a.k(kLitPowerLimit), nlim = a.k(-kLitPowerLimit);
  const V p = a.select(a.gt(sw, lim), lim, a.select(a.lt(sw, nlim), nlim, sw));
  const auto x_pos = a.gt(sx, zero);
  const auto y_pos = a.gt(sy, zero);
  const auto both = a.land(x_pos, y_pos);
  const V z = a.select(both, pow(a, sy, p), zero);
  return {a.k(1.0f), a.select(x_pos, sx, zero), z, a.k(1.0f)};
}

// Rule 31 (texm3x3spec/vspec): R = k·N − E with k = 2·(N·E)/(N·N); N·N = 0 gives k = 0.
template <class A, class V = typename A::V> V reflect_scale(const A& a, V ne, V nn) {
  const auto is0 = a.eq(nn, a.k(0.0f));
  const V two_ne = a.fmul(a.k(2.0f), ne);
  return a.select(is0, a.k(0.0f), a.div(two_ne, a.select(is0, a.k(1.0f), nn)));
}
template <class A, class V = typename A::V> V reflect_component(const A& a, V k, V n, V e) {
  return a.sub(mul(a, k, n), e);
}

// Rule 30 (texdepth, texm3x2depth): num/den, 1.0 for a zero divisor.
template <class A, class V = typename A::V> V depth_ratio(const A& a, V num, V den) {
  const auto is0 = a.eq(den, a.k(0.0f));
  return a.select(is0, a.k(1.0f), a.div(num, a.select(is0, a.k(1.0f), den)));
}

// Rule 32 (_dz / _dw): x and y divided by z or w; a zero divisor makes both 1.0.
template <class A, class V = typename A::V> void project_divide(const A& a, V& x, V& y, V d) {
  const auto is0 = a.eq(d, a.k(0.0f));
  x = a.select(is0, a.k(1.0f), a.div(x, d));
  y = a.select(is0, a.k(1.0f), a.div(y, d));
}

// bem / texbem / texbeml: base + m_r·r + m_g·g, summed in that order.
template <class A, class V = typename A::V>
V bump_offset(const A& a, V base, V m_r, V r, V m_g, V g) {
  return a.add(a.add(base, mul(a, m_r, r)), mul(a, m_g, g));
}
// Rule 33 (texbeml): the luminance factor b·LSCALE + LOFFSET, not clamped.
template <class A, class V = typename A::V> V bump_luminance(const A& a, V b, V lscale, V loffset) {
  return a.add(mul(a, b, lscale), loffset);
}

// Rule 20 (vs_2_0 mova): round half away from zero, sign(x)·floor(|x| + 0.5).
template <class A, class V = typename A::V> V mova_round(const A& a, V x) {
  const V fl = a.floor(a.add(a.abs(x), a.k(0.5f)));
  return a.select(a.lt(x, a.k(0.0f)), a.neg(fl), fl);
}
// Rule 21 (vs_1_1 mov a0): floor.
template <class A, class V = typename A::V> V mov_a0_floor(const A& a, V x) {
  return a.floor(x);
}
// Before the float → int conversion of an address: NaN → 0, magnitudes clamp to ±2^20.
template <class A, class V = typename A::V> V index_range(const A& a, V x) {
  const auto nan = a.is_nan(x);
  const V hi = a.k(kIndexLimit), lo = a.k(-kIndexLimit);
  V v = a.select(a.gt(x, hi), hi, x);
  v = a.select(a.lt(v, lo), lo, v);
  return a.select(nan, a.k(0.0f), v);
}

// Rules 24, 25: a clamp to [−max, +max] (NaN passes through), flushed as min/max flush.
template <class A, class V = typename A::V> V clamp_sym(const A& a, V x, V max) {
  const V lo = a.neg(max);
  const V inner = a.select(a.lt(x, lo), lo, x);
  return a.ftz(a.select(a.gt(x, max), max, inner));
}

// Rule 27: nearest multiple of 1/scale (ties up: floor(x·scale + 0.5)), limited to the
// largest multiple within ±max; NaN becomes 0.
template <class A, class V = typename A::V> V fixed_quantise(const A& a, V x, V scale, V max) {
  const V lim = a.floor(a.fmul(max, scale));
  const V u0 = a.floor(a.add(a.fmul(x, scale), a.k(0.5f)));
  const V neg_lim = a.neg(lim);
  const V u1 = a.select(a.gt(u0, lim), lim, a.select(a.lt(u0, neg_lim), neg_lim, u0));
  const V q = a.div(u1, scale);
  return a.select(a.is_nan(x), a.k(0.0f), q);
}

// The arithmetic source modifiers (source_modifiers.h, NUMERICS.md), each one rounding.
template <class A, class V = typename A::V> V bias(const A& a, V x) {
  return a.sub(x, a.k(0.5f));
}
template <class A, class V = typename A::V> V bx2(const A& a, V x) {
  return a.sub(a.fmul(a.k(2.0f), x), a.k(1.0f)); // 2x is exact: no fusion issue
}
template <class A, class V = typename A::V> V comp(const A& a, V x) {
  return a.sub(a.k(1.0f), x);
}
template <class A, class V = typename A::V> V x2(const A& a, V x) {
  return a.fmul(a.k(2.0f), x);
}

} // namespace tierlift::ir::numerics::rule
