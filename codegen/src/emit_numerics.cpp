// SPIR-V for the legacy numeric rules of ir/numerics.h. Each function emits exactly the
// operation sequence of the ir::numerics function with the same name: the same compares
// (ordered, so a NaN takes the false branch), the same order of additions, and every
// add/sub/mul decorated NoContraction so no driver fuses what the interpreter rounds twice.
#include <spirv/unified1/GLSL.std.450.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "tierlift/codegen/emitter.h"

namespace tierlift::codegen {

using spv::Op;

Id Emitter::vec4_const(float x, float y, float z, float w) {
  const Id parts[] = {f(x), f(y), f(z), f(w)};
  return b.const_composite(t_vec4, parts);
}

Id Emitter::splat(Id scalar) {
  return b.op(Op::OpCompositeConstruct, t_vec4, {scalar, scalar, scalar, scalar});
}

Id Emitter::bsplat(Id cond) {
  return b.op(Op::OpCompositeConstruct, t_bvec4, {cond, cond, cond, cond});
}

Id Emitter::comp(Id vec4, uint32_t i) {
  return b.op(Op::OpCompositeExtract, t_float, {vec4, i});
}

Id Emitter::compose(Id x, Id y, Id z, Id w) {
  return b.op(Op::OpCompositeConstruct, t_vec4, {x, y, z, w});
}

namespace {
Id exact(SpirvBuilder& b, Op op, Id type, Id a, Id c) {
  const Id r = b.op(op, type, {a, c});
  b.decorate(r, spv::Decoration::NoContraction);
  return r;
}
} // namespace

Id Emitter::fadd(Id a, Id c, int n) {
  return exact(b, Op::OpFAdd, type_of_width(n), a, c);
}
Id Emitter::fsub(Id a, Id c, int n) {
  return exact(b, Op::OpFSub, type_of_width(n), a, c);
}
Id Emitter::fmul(Id a, Id c, int n) {
  return exact(b, Op::OpFMul, type_of_width(n), a, c);
}
Id Emitter::fdiv(Id a, Id c, int n) {
  return exact(b, Op::OpFDiv, type_of_width(n), a, c);
}
Id Emitter::fneg(Id a, int n) {
  return b.op(Op::OpFNegate, type_of_width(n), {a});
}

Id Emitter::cmp(spv::Op op, Id a, Id c, int n) {
  return b.op(op, bool_type(n), {a, c});
}

Id Emitter::select(Id cond, Id a, Id c, int n) {
  return b.op(Op::OpSelect, type_of_width(n), {cond, a, c});
}

Id Emitter::glsl1(uint32_t inst, Id a, int n) {
  const Id args[] = {a};
  return b.ext_inst(glsl, type_of_width(n), inst, args);
}

// The zero of the right width for selects.
static Id zero_of(Emitter& e, int n) {
  return n == 1 ? e.f(0.0f) : e.vec4_const(0, 0, 0, 0);
}

Id Emitter::legacy_mul(Id a, Id c, int n) {
  const Id z = zero_of(*this, n);
  const Id az = cmp(Op::OpFOrdEqual, a, z, n);
  const Id cz = cmp(Op::OpFOrdEqual, c, z, n);
  const Id either = b.op(Op::OpLogicalOr, bool_type(n), {az, cz});
  return select(either, z, fmul(a, c, n), n);
}

Id Emitter::legacy_mad(Id a, Id c, Id d, int n) {
  return fadd(legacy_mul(a, c, n), d, n);
}

Id Emitter::legacy_dp(Id a, Id c, int count) {
  Id sum = legacy_mul(comp(a, 0), comp(c, 0), 1);
  for (int i = 1; i < count; ++i)
    sum = fadd(sum,
               legacy_mul(comp(a, static_cast<uint32_t>(i)), comp(c, static_cast<uint32_t>(i)), 1),
               1);
  return sum;
}

Id Emitter::legacy_lrp(Id s0, Id s1, Id s2) {
  return fadd(legacy_mul(s0, fsub(s1, s2)), s2);
}

Id Emitter::clamp_to_flt_max(Id x, int n) {
  const Id hi = n == 1 ? f(FLT_MAX) : splat(f(FLT_MAX));
  const Id lo = n == 1 ? f(-FLT_MAX) : splat(f(-FLT_MAX));
  const Id inner = select(cmp(Op::OpFOrdLessThan, x, lo, n), lo, x, n);
  return select(cmp(Op::OpFOrdGreaterThan, x, hi, n), hi, inner, n);
}

Id Emitter::legacy_rcp(Id x) {
  const Id q = clamp_to_flt_max(fdiv(f(1.0f), x, 1));
  const Id zero_case = select(cmp(Op::OpFOrdEqual, x, f(0.0f), 1), f(FLT_MAX), q, 1);
  return select(cmp(Op::OpFOrdEqual, x, f(1.0f), 1), f(1.0f), zero_case, 1);
}

Id Emitter::legacy_rsq(Id x) {
  const Id a = glsl1(GLSLstd450FAbs, x, 1);
  const Id q = clamp_to_flt_max(fdiv(f(1.0f), glsl1(GLSLstd450Sqrt, a, 1), 1));
  const Id zero_case = select(cmp(Op::OpFOrdEqual, a, f(0.0f), 1), f(FLT_MAX), q, 1);
  return select(cmp(Op::OpFOrdEqual, a, f(1.0f), 1), f(1.0f), zero_case, 1);
}

Id Emitter::legacy_log(Id x) {
  const Id a = glsl1(GLSLstd450FAbs, x, 1);
  // Log2 is only evaluated on a non-zero input (its result for 0 is not defined in Vulkan).
  const Id is0 = cmp(Op::OpFOrdEqual, a, f(0.0f), 1);
  const Id safe = select(is0, f(1.0f), a, 1);
  return select(is0, f(-FLT_MAX), glsl1(GLSLstd450Log2, safe, 1), 1);
}

Id Emitter::legacy_exp(Id x) {
  return clamp_to_flt_max(glsl1(GLSLstd450Exp2, x, 1));
}

Id Emitter::legacy_pow(Id x, Id y) {
  // std::log2(0) = -inf; Vulkan leaves Log2(0) undefined, so the -inf is selected here.
  const Id a = glsl1(GLSLstd450FAbs, x, 1);
  const Id is0 = cmp(Op::OpFOrdEqual, a, f(0.0f), 1);
  const Id log = select(is0, f(-std::numeric_limits<float>::infinity()),
                        glsl1(GLSLstd450Log2, select(is0, f(1.0f), a, 1), 1), 1);
  const Id r = legacy_exp(legacy_mul(y, log, 1));
  return select(cmp(Op::OpFOrdEqual, y, f(0.0f), 1), f(1.0f), r, 1);
}

Id Emitter::legacy_nrm_scale(Id len2) {
  return select(cmp(Op::OpFOrdEqual, len2, f(0.0f), 1), f(0.0f), legacy_rsq(len2), 1);
}

Id Emitter::legacy_saturate(Id x, int n) {
  const Id zero = zero_of(*this, n);
  const Id one = n == 1 ? f(1.0f) : vec4_const(1, 1, 1, 1);
  const Id inner = select(cmp(Op::OpFOrdLessThan, x, one, n), x, one, n);
  return select(cmp(Op::OpFOrdGreaterThan, x, zero, n), inner, zero, n);
}

Id Emitter::legacy_frc(Id x, int n) {
  return fsub(x, glsl1(GLSLstd450Floor, x, n), n);
}

Id Emitter::legacy_sgn(Id x) {
  const Id z = zero_of(*this, 4);
  const Id inner = select(cmp(Op::OpFOrdEqual, x, z), z, vec4_const(1, 1, 1, 1));
  return select(cmp(Op::OpFOrdLessThan, x, z), vec4_const(-1, -1, -1, -1), inner);
}

Id Emitter::legacy_clamp_sym(Id x, Id max, int n) {
  const Id hi = n == 1 ? max : splat(max);
  const Id lo = fneg(hi, n);
  const Id inner = select(cmp(Op::OpFOrdLessThan, x, lo, n), lo, x, n);
  return select(cmp(Op::OpFOrdGreaterThan, x, hi, n), hi, inner, n);
}

Id Emitter::legacy_fixed_quantise(Id x, int bits, Id max) {
  const float scale = std::ldexp(1.0f, std::clamp(bits, 1, 23));
  const Id s = splat(f(scale));
  const Id lim = glsl1(GLSLstd450Floor, fmul(splat(max), s));
  const Id u0 = glsl1(GLSLstd450Floor, fadd(fmul(x, s), splat(f(0.5f))));
  const Id neg_lim = fneg(lim);
  const Id u1 = select(cmp(Op::OpFOrdGreaterThan, u0, lim), lim,
                       select(cmp(Op::OpFOrdLessThan, u0, neg_lim), neg_lim, u0));
  const Id q = fdiv(u1, s);
  const Id is_nan = b.op(Op::OpIsNan, t_bvec4, {x});
  return select(is_nan, zero_of(*this, 4), q);
}

Id Emitter::legacy_index(Id x) {
  // clamp_index_float: NaN → 0, clamp to ±2^20, truncate.
  const Id is_nan = b.op(Op::OpIsNan, t_bool, {x});
  const Id hi = f(1048576.0f), lo = f(-1048576.0f);
  Id v = select(cmp(Op::OpFOrdGreaterThan, x, hi, 1), hi, x, 1);
  v = select(cmp(Op::OpFOrdLessThan, v, lo, 1), lo, v, 1);
  v = select(is_nan, f(0.0f), v, 1);
  return b.op(Op::OpConvertFToS, t_int, {v});
}

} // namespace tierlift::codegen
