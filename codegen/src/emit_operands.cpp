// Operand fetch and store in the order of docs/d3d9-rules.md §7, the same order the interpreter
// uses (runtime/devices/cpu/src/vm/vm_operands.cpp): fetch (constant defs override the uniform
// block, relative addressing with out-of-range → 0, ps_1_x constant clamp), pre-swizzle
// _dz/_dw, swizzle, post-swizzle modifiers with negate last; store: shift, ps_1_x range
// clamp, _sat, fixed-point quantise, write mask.
#include <spirv/unified1/GLSL.std.450.h>

#include <algorithm>
#include <cmath>

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/numerics.h"
#include "tierlift/ir/profile.h"

namespace tierlift::codegen {

using ir::RegFile;
using ir::SrcMod;
using spv::Op;
using SC = spv::StorageClass;

namespace {
// The last def of a register wins (docs/d3d9-rules.md §1.4).
const ir::ConstDef* find_def(const ir::Program& p, RegFile file, uint32_t index) {
  const ir::ConstDef* found = nullptr;
  for (const ir::ConstDef& d : p.defs)
    if (d.file == file && d.index == index) found = &d;
  return found;
}
} // namespace

Id Emitter::load_const(uint32_t index, const std::optional<ir::RelAddr>& rel) {
  // NUMERICS.md rule 13: under Rounding::Llvmpipe a def's denormals load as zeros of their
  // sign, as the interpreter loads them (runtime/devices/cpu/src/vm/vm_program.cpp): the driver
  // would fold def-only arithmetic with denormals kept, the same arithmetic at run time
  // flushes them.
  const bool flush = opt.conventions.rounding == ir::Rounding::Llvmpipe;
  auto def_value = [&](const ir::ConstDef& d) {
    auto c = [&](int i) { return flush ? ir::numerics::flush_denormal(d.f(i)) : d.f(i); };
    return vec4_const(c(0), c(1), c(2), c(3));
  };
  const Id ptr_vec4 = b.type_pointer(SC::Uniform, t_vec4);
  if (!rel) {
    if (const ir::ConstDef* d = find_def(prog, RegFile::Const, index)) return def_value(*d);
    // Far beyond any device's constant count (bad input the validator would reject): read
    // 0 rather than declare a gigantic block, as the interpreter's missing registers do.
    if (index >= 65536) return vec4_const(0, 0, 0, 0);
    consts_read_.insert(index);
    const Id chain = b.op(Op::OpAccessChain, ptr_vec4,
                          {uniform_var_, b.const_uint(kMemberFloat), b.const_uint(index)});
    return b.op(Op::OpLoad, t_vec4, {chain});
  }
  const_relative_ = true;
  Id offset;
  if (rel->file == RegFile::Loop) {
    offset = b.op(Op::OpLoad, t_int, {loop_var()});
  } else {
    const Id a0 = b.op(Op::OpLoad, t_ivec4, {register_var(RegFile::Addr, 0)});
    offset = b.op(Op::OpCompositeExtract, t_int, {a0, static_cast<uint32_t>(rel->component & 3)});
  }
  const auto limit = static_cast<int32_t>(relative_limit());
  const Id idx = b.op(Op::OpIAdd, t_int, {b.const_int(static_cast<int32_t>(index)), offset});
  const Id ge0 = b.op(Op::OpSGreaterThanEqual, t_bool, {idx, b.const_int(0)});
  const Id lt = b.op(Op::OpSLessThan, t_bool, {idx, b.const_int(limit)});
  const Id in_range = b.op(Op::OpLogicalAnd, t_bool, {ge0, lt});
  const Id safe = b.op(Op::OpSelect, t_int, {in_range, idx, b.const_int(0)});
  const Id chain =
      b.op(Op::OpAccessChain, ptr_vec4, {uniform_var_, b.const_uint(kMemberFloat), safe});
  Id value = b.op(Op::OpLoad, t_vec4, {chain});
  std::map<uint32_t, const ir::ConstDef*> defs;
  for (const ir::ConstDef& d : prog.defs)
    if (d.file == RegFile::Const) defs[d.index] = &d;
  for (const auto& [k, d] : defs) {
    const Id hit = b.op(Op::OpIEqual, t_bool, {idx, b.const_int(static_cast<int32_t>(k))});
    value = b.op(Op::OpSelect, t_vec4, {bsplat(hit), def_value(*d), value});
  }
  // SPIR-V 1.3 selects need a condition as wide as the result.
  return b.op(Op::OpSelect, t_vec4, {bsplat(in_range), value, vec4_const(0, 0, 0, 0)});
}

uint32_t Emitter::relative_limit() const {
  // Relative reads may reach any constant the device offers: 256 in a vertex shader (as
  // the interpreter, runtime/devices/cpu/src/vm/vm_program.cpp); outside → (0, 0, 0, 0).
  const uint32_t limit = ir::limits(prog.profile).float_consts;
  return ir::is_vertex(prog.profile) ? std::max<uint32_t>(limit, 256) : limit;
}

Id Emitter::loop_var() {
  if (!aL_var_) {
    aL_var_ = b.global_variable(b.type_pointer(SC::Private, t_int), SC::Private, b.const_int(0));
    b.name(aL_var_, "aL");
  }
  return aL_var_;
}

Id Emitter::load_int_const(uint32_t index) {
  if (const ir::ConstDef* d = find_def(prog, RegFile::ConstInt, index)) {
    const Id parts[] = {b.const_int(d->i(0)), b.const_int(d->i(1)), b.const_int(d->i(2)),
                        b.const_int(d->i(3))};
    return b.const_composite(t_ivec4, parts);
  }
  const Id chain = b.op(Op::OpAccessChain, b.type_pointer(SC::Uniform, t_ivec4),
                        {uniform_var_, b.const_uint(kMemberInt), b.const_uint(index)});
  return b.op(Op::OpLoad, t_ivec4, {chain});
}

Id Emitter::load_bool_const(uint32_t index) {
  if (const ir::ConstDef* d = find_def(prog, RegFile::ConstBool, index))
    return b.const_bool(d->b());
  const Id chain = b.op(Op::OpAccessChain, b.type_pointer(SC::Uniform, t_uint),
                        {uniform_var_, b.const_uint(kMemberBool), b.const_uint(index)});
  const Id raw = b.op(Op::OpLoad, t_uint, {chain});
  return b.op(Op::OpINotEqual, t_bool, {raw, b.const_uint(0)});
}

Id Emitter::load_register(RegFile file, uint32_t index, const std::optional<ir::RelAddr>& rel) {
  const bool ps11_13 = ir::is_ps11_13(prog.profile);
  switch (file) {
  case RegFile::Const: return load_const(index, rel);
  case RegFile::Input: {
    const Id v = b.op(Op::OpLoad, t_vec4, {input_var(file, index)});
    // Pixel colour inputs are saturated on input in every pixel profile (NUMERICS.md 26).
    return prog.stage() == ir::ShaderStage::Pixel ? legacy_saturate(v) : v;
  }
  case RegFile::Texture:
    // ps_1_1…1_3: t# are read/write registers filled by texture instructions; later
    // profiles read the interpolated coordinates directly.
    if (!ps11_13) return b.op(Op::OpLoad, t_vec4, {input_var(file, index)});
    [[fallthrough]];
  case RegFile::Temp:
  case RegFile::RastOut:
  case RegFile::AttrOut:
  case RegFile::TexCrdOut:
  case RegFile::ColorOut:
  case RegFile::DepthOut: return b.op(Op::OpLoad, t_vec4, {register_var(file, index)});
  default: break;
  }
  return vec4_const(0, 0, 0, 0); // samplers, labels, i#, b#: read by their instructions
}

Id Emitter::load_src(const ir::SrcOperand& s, uint32_t index_offset) {
  Id v = load_register(s.file, s.index + index_offset, s.rel);
  if (s.file == RegFile::Const && ir::is_ps1x(prog.profile)) v = legacy_clamp_sym(v, f(1.0f));
  if (s.mod == SrcMod::Dz || s.mod == SrcMod::Dw) {
    const Id d = comp(v, s.mod == SrcMod::Dz ? 2 : 3);
    const Id is0 = cmp(Op::OpFOrdEqual, d, f(0.0f), 1);
    const Id x = select(is0, f(1.0f), fdiv(comp(v, 0), d, 1), 1);
    const Id y = select(is0, f(1.0f), fdiv(comp(v, 1), d, 1), 1);
    v = compose(x, y, comp(v, 2), comp(v, 3));
  }
  if (s.swizzle != ir::kIdentitySwizzle) {
    v = b.op(Op::OpVectorShuffle, t_vec4,
             {v, v, ir::swizzle_component(s.swizzle, 0), ir::swizzle_component(s.swizzle, 1),
              ir::swizzle_component(s.swizzle, 2), ir::swizzle_component(s.swizzle, 3)});
  }
  auto all = [&](float x) { return vec4_const(x, x, x, x); };
  switch (s.mod) {
  case SrcMod::Neg: return fneg(v);
  case SrcMod::Bias: return fsub(v, all(0.5f));
  case SrcMod::BiasNeg: return fneg(fsub(v, all(0.5f)));
  case SrcMod::Bx2: return fsub(fmul(all(2.0f), v), all(1.0f));
  case SrcMod::Bx2Neg: return fneg(fsub(fmul(all(2.0f), v), all(1.0f)));
  case SrcMod::Comp: return fsub(all(1.0f), v);
  case SrcMod::X2: return fmul(all(2.0f), v);
  case SrcMod::X2Neg: return fneg(fmul(all(2.0f), v));
  case SrcMod::Abs: return glsl1(GLSLstd450FAbs, v);
  case SrcMod::AbsNeg: return fneg(glsl1(GLSLstd450FAbs, v));
  default: return v;
  }
}

Id Emitter::scalar_src(const ir::SrcOperand& s) {
  // Scalar operands carry a replicate swizzle; the w slot is the one the D3D8 reference
  // reads (docs/d3d9-rules.md §4.3), equal to every other slot when the swizzle replicates.
  return comp(load_src(s), 3);
}

void Emitter::store(const PendingStore& st, bool ps1x_range) {
  const uint8_t mask = st.mask & 0xF;
  if (mask == 0) return;
  if (st.dst.file == RegFile::Addr) {
    const Id var = register_var(RegFile::Addr, 0);
    const bool floor_mode = prog.profile == ir::Profile::vs_1_1;
    Id parts[4];
    const Id old = b.op(Op::OpLoad, t_ivec4, {var});
    for (uint32_t i = 0; i < 4; ++i) {
      if (!(mask & (1u << i))) {
        parts[i] = b.op(Op::OpCompositeExtract, t_int, {old, i});
        continue;
      }
      const Id x = comp(st.value, i);
      Id r;
      if (floor_mode) {
        r = glsl1(GLSLstd450Floor, x, 1);
      } else { // sign(x) · floor(|x| + 0.5)
        const Id fl = glsl1(GLSLstd450Floor, fadd(glsl1(GLSLstd450FAbs, x, 1), f(0.5f), 1), 1);
        r = select(cmp(Op::OpFOrdLessThan, x, f(0.0f), 1), fneg(fl, 1), fl, 1);
      }
      parts[i] = legacy_index(r);
    }
    b.op_void(Op::OpStore, {var, b.op(Op::OpCompositeConstruct, t_ivec4,
                                      {parts[0], parts[1], parts[2], parts[3]})});
    return;
  }
  Id v = st.value;
  if (st.mods.shift != 0) {
    const float scale = std::ldexp(1.0f, std::clamp<int>(st.mods.shift, -8, 8));
    v = fmul(v, vec4_const(scale, scale, scale, scale));
  }
  if (ps1x_range) v = legacy_clamp_sym(v, ps1x_max_value());
  if (st.mods.sat) v = legacy_saturate(v);
  if (ps1x_range && opt.conventions.ps1x_fixed_bits > 0)
    v = legacy_fixed_quantise(v, opt.conventions.ps1x_fixed_bits, ps1x_max_value());
  if (st.dst.file == RegFile::DepthOut) writes_depth_ = true;
  const Id var = register_var(st.dst.file, st.dst.index);
  if (mask != 0xF) {
    const Id old = b.op(Op::OpLoad, t_vec4, {var});
    uint32_t sel[4];
    for (uint32_t i = 0; i < 4; ++i) sel[i] = (mask & (1u << i)) ? i : 4 + i;
    v = b.op(Op::OpVectorShuffle, t_vec4, {v, old, sel[0], sel[1], sel[2], sel[3]});
  }
  b.op_void(Op::OpStore, {var, v});
}

} // namespace tierlift::codegen
