// What shader models 2.x and 3.0 add outside flow control proper: the comparisons of
// if_comp / break_comp / setp_comp (ir/flow_rules.h, the interpreter's rule), the predicate
// register p0 with setp and predicated writes, and ps_3_0's vPos and vFace inputs.
#include "tierlift/codegen/emitter.h"

namespace tierlift::codegen {

using spv::Op;
using SC = spv::StorageClass;

Id Emitter::compare(ir::flow::Comparison c, Id x, Id y, int n) {
  return ir::flow::compare(arith(n), c, x, y);
}

Id Emitter::first_component(const ir::SrcOperand& s) {
  return comp(load_src(s), 0);
}

Id Emitter::p0_var() {
  if (!p0_var_) {
    p0_var_ =
        b.global_variable(b.type_pointer(SC::Private, t_bvec4), SC::Private, b.const_null(t_bvec4));
    b.name(p0_var_, "p0");
  }
  return p0_var_;
}

Id Emitter::predicate_component(const ir::SrcOperand& p) {
  const Id p0 = b.op(Op::OpLoad, t_bvec4, {p0_var()});
  Id c = b.op(Op::OpCompositeExtract, t_bool, {p0, ir::swizzle_component(p.swizzle, 0)});
  if (p.mod == ir::SrcMod::Not) c = b.op(Op::OpLogicalNot, t_bool, {c});
  return c;
}

Id Emitter::predicate_mask(const ir::SrcOperand& p) {
  const Id p0 = b.op(Op::OpLoad, t_bvec4, {p0_var()});
  Id m = b.op(Op::OpVectorShuffle, t_bvec4,
              {p0, p0, ir::swizzle_component(p.swizzle, 0), ir::swizzle_component(p.swizzle, 1),
               ir::swizzle_component(p.swizzle, 2), ir::swizzle_component(p.swizzle, 3)});
  if (p.mod == ir::SrcMod::Not) m = b.op(Op::OpLogicalNot, t_bvec4, {m});
  return m;
}

// setp_comp p0.mask, src0, src1: the written components of p0 take src0 `comp` src1; a
// predicated setp writes only where its own predicate holds.
void Emitter::emit_setp(const ir::Instruction& ins) {
  if (!ins.dst || ins.src.size() < 2) {
    error(ins.loc, "malformed instruction 'setp'");
    return;
  }
  const auto c = *ir::flow::comparison_of(ins.op);
  const Id result = compare(c, load_src(ins.src[0]), load_src(ins.src[1]), 4);
  const Id old = b.op(Op::OpLoad, t_bvec4, {p0_var()});
  uint8_t mask = ins.dst->mask & 0xF;
  Id value = result;
  if (ins.pred) value = b.op(Op::OpSelect, t_bvec4, {predicate_mask(*ins.pred), result, old});
  uint32_t sel[4];
  for (uint32_t i = 0; i < 4; ++i) sel[i] = (mask & (1u << i)) ? i : 4 + i;
  value = b.op(Op::OpVectorShuffle, t_bvec4, {value, old, sel[0], sel[1], sel[2], sel[3]});
  b.op_void(Op::OpStore, {p0_var(), value});
}

// vPos: gl_FragCoord.xy − 0.5, so pixel (x, y) reads (x, y): Direct3D 9 puts pixel
// centres at integers, Vulkan at + 0.5 (NUMERICS.md "vPos"); z = w = 0. vFace: +1 on a
// front face, −1 on a back face; the pipeline's front face is clockwise on screen, the
// Direct3D 9 default (NUMERICS.md "vFace").
Id Emitter::misc_input(uint32_t index) {
  auto builtin_input = [&](Id& var, Id type, spv::BuiltIn which, const char* name) {
    if (var) return var;
    var = b.global_variable(b.type_pointer(SC::Input, type), SC::Input);
    b.decorate(var, spv::Decoration::BuiltIn, static_cast<uint32_t>(which));
    b.name(var, name);
    interface_ids_.push_back(var);
    return var;
  };
  if (index == ir::kMiscPosition) {
    const Id fc = b.op(Op::OpLoad, t_vec4,
                       {builtin_input(frag_coord_var_, t_vec4, spv::BuiltIn::FragCoord, "vPos")});
    const Id x = fsub(comp(fc, 0), f(0.5f), 1), y = fsub(comp(fc, 1), f(0.5f), 1);
    return compose(x, y, f(0.0f), f(0.0f));
  }
  const Id front =
      b.op(Op::OpLoad, t_bool,
           {builtin_input(front_facing_var_, t_bool, spv::BuiltIn::FrontFacing, "vFace")});
  return splat(b.op(Op::OpSelect, t_float, {front, f(1.0f), f(-1.0f)}));
}

} // namespace tierlift::codegen
