// Arithmetic instructions: one case per opcode-table row, each the SPIR-V twin of the
// interpreter's compute function (docs/d3d9-rules.md §5), both instantiating the numeric rules of
// ir/numeric_rules.h (v4: vec4 width, s1: scalar).
// The result is returned as a pending store so that co-issued pairs and matrix macros read
// every source before anything is written.
#include <spirv/unified1/GLSL.std.450.h>

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::codegen {

using ir::Opcode;
using spv::Op;
using SC = spv::StorageClass;

bool Emitter::emit_arith(const ir::Instruction& ins, PendingStore& out) {
  const ir::OpInfo& info = ir::op_info(ins.op);
  if (!ins.dst || ins.src.size() < info.num_src) {
    error(ins.loc, "malformed instruction '" + std::string(info.mnemonic) + "'");
    return false;
  }
  out.dst = *ins.dst;
  out.mods = ins.mods;
  // Only what the opcode produces in this profile is written (the table's writes column:
  // frc in vs_1_1 .xy, m3x2 / sincos / bem .xy, m4x3 / m3x3 / crs .xyz).
  out.mask = ins.dst->mask & ir::op_writes(ins.op, prog.profile);
  // The constant 0 is made before any source is loaded, as it always was, so the module's
  // ids (and its words) do not depend on how this function is split.
  f(0.0f);
  // Each group gives 0 for an opcode that is not its own.
  Id v = arith_per_component(ins, out.mask);
  if (!v) v = arith_scalar(ins);
  if (!v) v = arith_across_components(ins);
  if (!v) {
    error(ins.loc, "code generation for '" + std::string(info.mnemonic) + "' is not implemented");
    return false;
  }
  out.value = v;
  return true;
}

Id Emitter::arith_per_component(const ir::Instruction& ins, uint8_t mask) {
  auto src = [&](size_t i) { return load_src(ins.src[i]); };
  const SpirvArith v4 = arith(4);
  switch (ins.op) {
  case Opcode::Mov:
  case Opcode::Mova: return src(0);
  case Opcode::Add: return v4.add(src(0), src(1));
  case Opcode::Sub: return v4.sub(src(0), src(1));
  case Opcode::Mul: {
    const Id a = src(0), c = src(1);
    return plain_factors(0, 1, mask) ? rule::mul_plain(v4, a, c) : rule::mul(v4, a, c);
  }
  case Opcode::Mad: {
    const Id a = src(0), c = src(1), d = src(2);
    return plain_factors(0, 1, mask) ? rule::mad_plain(v4, a, c, d) : rule::mad(v4, a, c, d);
  }
  case Opcode::Min: {
    const Id a = src(0), c = src(1);
    return rule::min(v4, a, c);
  }
  case Opcode::Max: {
    const Id a = src(0), c = src(1);
    return rule::max(v4, a, c);
  }
  case Opcode::Slt:
  case Opcode::Sge: {
    const Id a = src(0), c = src(1);
    return ins.op == Opcode::Slt ? rule::slt(v4, a, c) : rule::sge(v4, a, c);
  }
  case Opcode::Lrp: {
    const Id a = src(0), c = src(1), d = src(2);
    return rule::lrp(v4, a, c, d);
  }
  case Opcode::Frc: return rule::frc(v4, src(0));
  case Opcode::Sgn: return rule::sgn(v4, src(0));
  case Opcode::Abs: return v4.abs(src(0));
  case Opcode::Dsx:
  case Opcode::Dsy: {
    // NUMERICS.md rule F8: fine differences inside the 2x2 quad (lavapipe's OpDPdx is fine too,
    // but only the Fine forms promise it). Vulkan supports DerivativeControl everywhere.
    b.capability(spv::Capability::DerivativeControl);
    return b.op(ins.op == Opcode::Dsx ? Op::OpDPdxFine : Op::OpDPdyFine, t_vec4, {src(0)});
  }
  case Opcode::Cnd: {
    const Id c = src(0), a = src(1), d = src(2);
    return rule::cnd(v4, c, a, d);
  }
  case Opcode::Cmp: {
    const Id c = src(0), a = src(1), d = src(2);
    return rule::cmp(v4, c, a, d);
  }
  default: return 0;
  }
}

Id Emitter::arith_scalar(const ir::Instruction& ins) {
  auto sc = [&](size_t i) { return scalar_src(ins.src[i]); };
  const SpirvArith s1 = arith(1);
  switch (ins.op) {
  case Opcode::Rcp: return splat(rule::rcp(s1, sc(0)));
  case Opcode::Rsq: return splat(rule::rsq(s1, sc(0)));
  case Opcode::Exp: return splat(rule::exp(s1, sc(0)));
  case Opcode::Log:
  case Opcode::Logp: return splat(rule::log(s1, sc(0)));
  case Opcode::Expp: {
    const Id x = sc(0);
    if (prog.profile != ir::Profile::vs_1_1) return splat(rule::exp(s1, x));
    const rule::Lanes4<Id> d = rule::expp_partial(s1, x);
    return compose(d.x, d.y, d.z, d.w);
  }
  case Opcode::Pow: {
    const Id x = sc(0), y = sc(1);
    return splat(rule::pow(s1, x, y));
  }
  case Opcode::SinCos:
  case Opcode::SinCos3: { // 3.0's one-source form: the same, no constants read
    const Id x = sc(0), zero = f(0.0f);
    return compose(glsl1(GLSLstd450Cos, x, 1), glsl1(GLSLstd450Sin, x, 1), zero, zero);
  }
  default: return 0;
  }
}

Id Emitter::arith_across_components(const ir::Instruction& ins) {
  auto src = [&](size_t i) { return load_src(ins.src[i]); };
  const Id zero = f(0.0f);
  const SpirvArith v4 = arith(4), s1 = arith(1);
  switch (ins.op) {
  case Opcode::Dp3: return splat(dot(src(0), src(1), 3));
  case Opcode::Dp4: return splat(dot(src(0), src(1), 4));
  case Opcode::Dp2Add: {
    const Id a = src(0), c = src(1), d = scalar_src(ins.src[2]);
    return splat(s1.add(dot(a, c, 2), d));
  }
  case Opcode::Lit: {
    const Id s = src(0);
    const Id sx = comp(s, 0), sy = comp(s, 1), sw = comp(s, 3);
    const rule::Lanes4<Id> d = rule::lit(s1, sx, sy, sw);
    return compose(d.x, d.y, d.z, d.w);
  }
  case Opcode::Dst: {
    const Id a = src(0), c = src(1);
    return compose(f(1.0f), rule::mul(s1, comp(a, 1), comp(c, 1)), comp(a, 2), comp(c, 3));
  }
  case Opcode::M4x4:
  case Opcode::M4x3:
  case Opcode::M3x4:
  case Opcode::M3x3:
  case Opcode::M3x2: {
    // The table's rows, each a dot product over the lanes it reads (m4xN: 4).
    const ir::OpSemantics& sem = ir::op_semantics(ins.op);
    const int rows = sem.matrix_rows, cols = sem.src_lanes == 0xF ? 4 : 3;
    const Id v = src(0);
    Id r[4] = {zero, zero, zero, zero};
    for (int i = 0; i < rows; ++i)
      r[i] = dot(v, load_src(ins.src[1], static_cast<uint32_t>(i)), cols);
    return compose(r[0], r[1], r[2], r[3]);
  }
  case Opcode::Crs: {
    const Id a = src(0), c = src(1);
    auto cross = [&](uint32_t i, uint32_t j) {
      return rule::cross_component(s1, comp(a, i), comp(c, j), comp(a, j), comp(c, i));
    };
    const Id x = cross(1, 2), y = cross(2, 0), z = cross(0, 1);
    return compose(x, y, z, zero);
  }
  case Opcode::Nrm: {
    const Id a = src(0);
    const Id scale = rule::nrm_scale(s1, dot(a, a, 3));
    return rule::mul(v4, a, splat(scale));
  }
  case Opcode::Bem: {
    // d.r = s0.r + M00·s1.r + M10·s1.g; d.g = s0.g + M01·s1.r + M11·s1.g (stage = dst#).
    const Id a = src(0), c = src(1);
    const Id m = bumpenv(ins.dst->index, 0);
    const Id r = rule::bump_offset(s1, comp(a, 0), comp(m, 0), comp(c, 0), comp(m, 2), comp(c, 1));
    const Id g = rule::bump_offset(s1, comp(a, 1), comp(m, 1), comp(c, 0), comp(m, 3), comp(c, 1));
    return compose(r, g, zero, zero);
  }
  default: return 0;
  }
}

Id Emitter::bumpenv(uint32_t stage, uint32_t which) {
  // ps_1_x uniform member kMemberBump (UniformBlockInfo): per stage the matrix slot, then
  // (lscale, loffset, 0, 0).
  const uint32_t slot =
      (stage % UniformBlockInfo::kBumpStages) * UniformBlockInfo::kBumpSlotsPerStage;
  const Id chain =
      b.op(Op::OpAccessChain, b.type_pointer(SC::Uniform, t_vec4),
           {uniform_var_, b.const_uint(kMemberBump), b.const_uint(slot + (which & 1))});
  return b.op(Op::OpLoad, t_vec4, {chain});
}

} // namespace tierlift::codegen
