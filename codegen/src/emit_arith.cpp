// Arithmetic instructions: one case per opcode-table row, each the SPIR-V twin of the
// interpreter's compute function (docs/d3d9-rules.md §5; numeric rules from ir/numerics.h).
// The result is returned as a pending store so that co-issued pairs and matrix macros read
// every source before anything is written.
#include <spirv/unified1/GLSL.std.450.h>

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/numerics.h"

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
  out.mask = ins.dst->mask;
  auto src = [&](size_t i) { return load_src(ins.src[i]); };
  auto sc = [&](size_t i) { return scalar_src(ins.src[i]); };
  const Id zero = f(0.0f);
  auto matrix = [&](int rows, int cols) {
    const Id v = src(0);
    Id r[4] = {zero, zero, zero, zero};
    for (int i = 0; i < rows; ++i)
      r[i] = legacy_dp(v, load_src(ins.src[1], static_cast<uint32_t>(i)), cols);
    out.mask &= static_cast<uint8_t>((1u << rows) - 1);
    return compose(r[0], r[1], r[2], r[3]);
  };
  Id v = 0;
  switch (ins.op) {
  case Opcode::Mov:
  case Opcode::Mova: v = src(0); break;
  case Opcode::Add: v = fadd(src(0), src(1)); break;
  case Opcode::Sub: v = fsub(src(0), src(1)); break;
  case Opcode::Mul: v = legacy_mul(src(0), src(1)); break;
  case Opcode::Mad: {
    const Id a = src(0), c = src(1), d = src(2);
    v = legacy_mad(a, c, d);
    break;
  }
  case Opcode::Dp3: v = splat(legacy_dp(src(0), src(1), 3)); break;
  case Opcode::Dp4: v = splat(legacy_dp(src(0), src(1), 4)); break;
  case Opcode::Dp2Add: {
    const Id a = src(0), c = src(1), d = sc(2);
    v = splat(fadd(legacy_dp(a, c, 2), d, 1));
    break;
  }
  case Opcode::Min: {
    const Id a = src(0), c = src(1);
    v = select(cmp(Op::OpFOrdLessThan, a, c), a, c);
    break;
  }
  case Opcode::Max: {
    const Id a = src(0), c = src(1);
    v = select(cmp(Op::OpFOrdGreaterThanEqual, a, c), a, c);
    break;
  }
  case Opcode::Slt:
  case Opcode::Sge: {
    const Id a = src(0), c = src(1);
    v = select(cmp(ins.op == Opcode::Slt ? Op::OpFOrdLessThan : Op::OpFOrdGreaterThanEqual, a, c),
               vec4_const(1, 1, 1, 1), vec4_const(0, 0, 0, 0));
    break;
  }
  case Opcode::Rcp: v = splat(legacy_rcp(sc(0))); break;
  case Opcode::Rsq: v = splat(legacy_rsq(sc(0))); break;
  case Opcode::Exp: v = splat(legacy_exp(sc(0))); break;
  case Opcode::Log:
  case Opcode::Logp: v = splat(legacy_log(sc(0))); break;
  case Opcode::Expp: {
    const Id x = sc(0);
    if (prog.profile == ir::Profile::vs_1_1) {
      // (2^floor(v), v − floor(v), 2^v, 1) — the D3D8 partial-precision vector.
      const Id fl = glsl1(GLSLstd450Floor, x, 1);
      v = compose(legacy_exp(fl), fsub(x, fl, 1), legacy_exp(x), f(1.0f));
    } else {
      v = splat(legacy_exp(x));
    }
    break;
  }
  case Opcode::Pow: {
    const Id x = sc(0), y = sc(1);
    v = splat(legacy_pow(x, y));
    break;
  }
  case Opcode::Lit: {
    const Id s = src(0);
    const Id sx = comp(s, 0), sy = comp(s, 1), sw = comp(s, 3);
    const Id lim = f(ir::numerics::kLitPowerLimit), nlim = f(-ir::numerics::kLitPowerLimit);
    const Id p = select(cmp(Op::OpFOrdGreaterThan, sw, lim, 1), lim,
                        select(cmp(Op::OpFOrdLessThan, sw, nlim, 1), nlim, sw, 1), 1);
    const Id x_pos = cmp(Op::OpFOrdGreaterThan, sx, zero, 1);
    const Id y_pos = cmp(Op::OpFOrdGreaterThan, sy, zero, 1);
    const Id both = b.op(Op::OpLogicalAnd, t_bool, {x_pos, y_pos});
    const Id z = select(both, legacy_pow(sy, p), zero, 1);
    v = compose(f(1.0f), select(x_pos, sx, zero, 1), z, f(1.0f));
    break;
  }
  case Opcode::Dst: {
    const Id a = src(0), c = src(1);
    v = compose(f(1.0f), legacy_mul(comp(a, 1), comp(c, 1), 1), comp(a, 2), comp(c, 3));
    break;
  }
  case Opcode::Lrp: {
    const Id a = src(0), c = src(1), d = src(2);
    v = legacy_lrp(a, c, d);
    break;
  }
  case Opcode::Frc:
    v = legacy_frc(src(0));
    if (prog.profile == ir::Profile::vs_1_1) out.mask &= 0x3; // the macro writes x, y only
    break;
  case Opcode::M4x4: v = matrix(4, 4); break;
  case Opcode::M4x3: v = matrix(3, 4); break;
  case Opcode::M3x4: v = matrix(4, 3); break;
  case Opcode::M3x3: v = matrix(3, 3); break;
  case Opcode::M3x2: v = matrix(2, 3); break;
  case Opcode::Crs: {
    const Id a = src(0), c = src(1);
    const Id x =
        fsub(legacy_mul(comp(a, 1), comp(c, 2), 1), legacy_mul(comp(a, 2), comp(c, 1), 1), 1);
    const Id y =
        fsub(legacy_mul(comp(a, 2), comp(c, 0), 1), legacy_mul(comp(a, 0), comp(c, 2), 1), 1);
    const Id z =
        fsub(legacy_mul(comp(a, 0), comp(c, 1), 1), legacy_mul(comp(a, 1), comp(c, 0), 1), 1);
    v = compose(x, y, z, zero);
    out.mask &= 0x7;
    break;
  }
  case Opcode::Sgn: v = legacy_sgn(src(0)); break;
  case Opcode::Abs: v = glsl1(GLSLstd450FAbs, src(0)); break;
  case Opcode::Nrm: {
    const Id a = src(0);
    const Id scale = legacy_nrm_scale(legacy_dp(a, a, 3));
    v = legacy_mul(a, splat(scale));
    break;
  }
  case Opcode::SinCos: {
    const Id x = sc(0);
    v = compose(glsl1(GLSLstd450Cos, x, 1), glsl1(GLSLstd450Sin, x, 1), zero, zero);
    out.mask &= 0x3; // d.z undefined, d.w untouched
    break;
  }
  case Opcode::Cnd: {
    const Id c = src(0), a = src(1), d = src(2);
    v = select(cmp(Op::OpFOrdGreaterThan, c, vec4_const(0.5f, 0.5f, 0.5f, 0.5f)), a, d);
    break;
  }
  case Opcode::Cmp: {
    const Id c = src(0), a = src(1), d = src(2);
    v = select(cmp(Op::OpFOrdGreaterThanEqual, c, vec4_const(0, 0, 0, 0)), a, d);
    break;
  }
  case Opcode::Bem: {
    // d.r = s0.r + M00·s1.r + M10·s1.g; d.g = s0.g + M01·s1.r + M11·s1.g (stage = dst#).
    const Id a = src(0), c = src(1);
    const Id m = bumpenv(ins.dst->index, 0);
    const Id r = fadd(fadd(comp(a, 0), legacy_mul(comp(m, 0), comp(c, 0), 1), 1),
                      legacy_mul(comp(m, 2), comp(c, 1), 1), 1);
    const Id g = fadd(fadd(comp(a, 1), legacy_mul(comp(m, 1), comp(c, 0), 1), 1),
                      legacy_mul(comp(m, 3), comp(c, 1), 1), 1);
    v = compose(r, g, zero, zero);
    out.mask &= 0x3;
    break;
  }
  default:
    error(ins.loc, "code generation for '" + std::string(info.mnemonic) + "' is not implemented");
    return false;
  }
  out.value = v;
  return true;
}

Id Emitter::bumpenv(uint32_t stage, uint32_t which) {
  // ps_1_x uniform member kMemberBump: per stage (M00, M01, M10, M11) at 2·stage and
  // (lscale, loffset, 0, 0) at 2·stage + 1.
  const Id chain =
      b.op(Op::OpAccessChain, b.type_pointer(SC::Uniform, t_vec4),
           {uniform_var_, b.const_uint(kMemberBump), b.const_uint((stage & 7) * 2 + (which & 1))});
  return b.op(Op::OpLoad, t_vec4, {chain});
}

} // namespace tierlift::codegen
