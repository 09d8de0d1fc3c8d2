// The SPIR-V primitives and the arithmetic back end (SpirvArith) through which the code
// generator instantiates the numeric rules of ir/numeric_rules.h: the same templates the
// interpreter runs, so the same compares (ordered, a NaN takes the false branch), the same
// order of additions, and every add/sub/mul/div decorated NoContraction so no driver fuses
// what the interpreter rounds twice.
#include <array>

#include <spirv/unified1/GLSL.std.450.h>

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/numeric_rules.h"

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
  const Id x = b.op(Op::OpCompositeExtract, t_float, {vec4, i});
  set_never_zero(x, (never_zero(vec4) >> i) & 1);
  return x;
}

Id Emitter::false_const(int n) {
  const Id no = b.const_bool(false);
  if (n == 1) return no;
  const Id parts[] = {no, no, no, no};
  return b.const_composite(t_bvec4, parts);
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

SpirvArith Emitter::arith(int n) {
  return SpirvArith{*this, n};
}

Id SpirvArith::k(float x) const {
  return n == 1 ? e.f(x) : e.vec4_const(x, x, x, x);
}
Id SpirvArith::add(Id a, Id c) const {
  return e.fadd(a, c, n);
}
Id SpirvArith::sub(Id a, Id c) const {
  return e.fsub(a, c, n);
}
Id SpirvArith::fmul(Id a, Id c) const {
  return e.fmul(a, c, n);
}
Id SpirvArith::div(Id a, Id c) const {
  return e.fdiv(a, c, n);
}
Id SpirvArith::neg(Id a) const {
  return e.fneg(a, n);
}
// |a| as the sign bit cleared (a bitwise AND on the bits), not GLSL FAbs: lavapipe (Mesa
// 22.3) compiles FAbs of a constant vector holding a NaN in z, (1, -2, NaN, 0.5), to the
// vector unchanged, where the bitwise form folds right (found by `tierlift test --generate`,
// ps_2_0 seed 3 case 00075). The same bits for every input, NaN, ±0 and denormals included.
Id SpirvArith::abs(Id a) const {
  const Id t_float = e.type_of_width(n);
  // The unsigned type of type_of_width's shape: uint for n = 1, uvec4 otherwise.
  const Id t_bits = n == 1 ? e.t_uint : e.b.type_vector(e.t_uint, 4);
  const Id mask = e.b.const_uint(0x7fffffffu);
  const Id masks =
      n == 1 ? mask : e.b.const_composite(t_bits, std::array<Id, 4>{mask, mask, mask, mask});
  const Id bits = e.b.op(spv::Op::OpBitcast, t_bits, {a});
  return e.b.op(spv::Op::OpBitcast, t_float,
                {e.b.op(spv::Op::OpBitwiseAnd, t_bits, {bits, masks})});
}
Id SpirvArith::floor(Id a) const {
  return e.glsl1(GLSLstd450Floor, a, n);
}
Id SpirvArith::sqrt(Id a) const {
  return e.glsl1(GLSLstd450Sqrt, a, n);
}
Id SpirvArith::exp2(Id a) const {
  return e.glsl1(GLSLstd450Exp2, a, n);
}
// Vulkan leaves Log2(0) undefined: the rules only ever take it of a non-zero value.
Id SpirvArith::log2(Id a) const {
  return e.glsl1(GLSLstd450Log2, a, n);
}
// A compare with zero of a value that is never zero (Emitter::never_zero_) is false; the
// rules then drop the branch it would have chosen (lor, select below).
Id SpirvArith::eq(Id a, Id c) const {
  const Id zero = k(0.0f);
  const Id x = c == zero ? a : a == zero ? c : 0; // the value compared with zero, if one is
  const uint8_t known = x ? e.never_zero(x) : uint8_t{0};
  const uint8_t all = n == 1 ? 1 : 0xF;
  if (known == 0) return e.cmp(Op::OpFOrdEqual, a, c, n);
  if (known == all) return e.false_const(n);
  // Some components known: false there, a compare for the others.
  Id parts[4];
  for (uint32_t i = 0; i < 4; ++i)
    parts[i] = (known >> i) & 1 ? e.b.const_bool(false)
                                : e.cmp(Op::OpFOrdEqual, e.comp(x, i), e.f(0.0f), 1);
  return e.b.op(Op::OpCompositeConstruct, e.t_bvec4, {parts[0], parts[1], parts[2], parts[3]});
}
Id SpirvArith::lt(Id a, Id c) const {
  return e.cmp(Op::OpFOrdLessThan, a, c, n);
}
Id SpirvArith::gt(Id a, Id c) const {
  return e.cmp(Op::OpFOrdGreaterThan, a, c, n);
}
Id SpirvArith::ge(Id a, Id c) const {
  return e.cmp(Op::OpFOrdGreaterThanEqual, a, c, n);
}
Id SpirvArith::lor(Id a, Id c) const {
  if (a == e.false_const(n)) return c;
  if (c == e.false_const(n)) return a;
  return e.b.op(Op::OpLogicalOr, e.bool_type(n), {a, c});
}
Id SpirvArith::land(Id a, Id c) const {
  return e.b.op(Op::OpLogicalAnd, e.bool_type(n), {a, c});
}
Id SpirvArith::is_nan(Id a) const {
  return e.b.op(Op::OpIsNan, e.bool_type(n), {a});
}
Id SpirvArith::select(Id c, Id a, Id b) const {
  if (c == e.false_const(n)) return b;
  return e.select(c, a, b, n);
}

Id Emitter::dot(Id a, Id c, int count) {
  Id x[4], y[4];
  for (int i = 0; i < count; ++i) {
    x[i] = comp(a, static_cast<uint32_t>(i));
    y[i] = comp(c, static_cast<uint32_t>(i));
  }
  return ir::numerics::rule::dot(arith(1), x, y, count);
}

Id Emitter::to_index(Id x) {
  return b.op(Op::OpConvertFToS, t_int, {ir::numerics::rule::index_range(arith(1), x)});
}

} // namespace tierlift::codegen
