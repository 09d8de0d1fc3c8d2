// Operand fetch and store in the order of docs/d3d9-rules.md §7, the same order the interpreter
// uses (runtime/devices/cpu/src/vm/vm_operands.cpp): fetch (constant defs override the uniform
// block, relative addressing with out-of-range → 0, ps_1_x constant clamp), pre-swizzle
// _dz/_dw, swizzle, post-swizzle modifiers with negate last; store: shift, ps_1_x range
// clamp, _sat, fixed-point quantise, write mask.
#include <spirv/unified1/GLSL.std.450.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <string_view>

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/numerics.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/sm3_interface.h"
#include "tierlift/ir/source_modifiers.h"

namespace tierlift::codegen {

using ir::RegFile;
using ir::SrcMod;
using spv::Op;
using SC = spv::StorageClass;

namespace {
// TEST ONLY, a planted translation bug: with TIERLIFT_TEST_PLANT=drop-negate in the
// environment, every source modifier loses its negation here (-r0 reads r0, -r0_bx2 reads
// r0_bx2). The generated corpus must find it and the reducer shrink it
// (tests/vulkan/generated_plant_test.cpp, docs/generate.md). This is the one place the
// variable is read; nothing else sets it.
SrcMod planted(SrcMod m) {
  const char* plant = std::getenv("TIERLIFT_TEST_PLANT");
  if (!plant || std::string_view(plant) != "drop-negate") return m;
  switch (m) {
  case SrcMod::Neg: return SrcMod::None;
  case SrcMod::BiasNeg: return SrcMod::Bias;
  case SrcMod::Bx2Neg: return SrcMod::Bx2;
  case SrcMod::X2Neg: return SrcMod::X2;
  case SrcMod::AbsNeg: return SrcMod::Abs;
  default: return m;
  }
}

// The four components hold the same bits (NaN payloads and zero signs included).
bool replicated(const std::array<float, 4>& v) {
  const auto x = std::bit_cast<uint32_t>(v[0]);
  return x == std::bit_cast<uint32_t>(v[1]) && x == std::bit_cast<uint32_t>(v[2]) &&
         x == std::bit_cast<uint32_t>(v[3]);
}
} // namespace

Id Emitter::load_const(uint32_t index, const std::optional<ir::RelAddr>& rel) {
  // NUMERICS.md rule 13: under Rounding::Llvmpipe a def's denormals load as zeros of their
  // sign, as the interpreter loads them (runtime/devices/cpu/src/vm/vm_program.cpp): the driver
  // would fold def-only arithmetic with denormals kept, the same arithmetic at run time
  // flushes them.
  const bool flush = opt.conventions.rounding == ir::Rounding::Llvmpipe;
  auto loaded = [&](const ir::ConstDef& d) {
    std::array<float, 4> v;
    for (int i = 0; i < 4; ++i) v[i] = flush ? ir::numerics::flush_denormal(d.f(i)) : d.f(i);
    return v;
  };
  auto def_value = [&](const ir::ConstDef& d) {
    const std::array<float, 4> v = loaded(d);
    return vec4_const(v[0], v[1], v[2], v[3]);
  };
  // CodegenOptions::defs_in_block: the def is read from its slot in the block, where the
  // device writes its value, so lavapipe's compiler folds no arithmetic on it.
  auto in_block = [&](uint32_t slot, const ir::ConstDef& d) {
    if (!opt.defs_in_block || slot >= relative_limit()) return false;
    block_defs_[slot] = loaded(d);
    return true;
  };
  const Id ptr_vec4 = b.type_pointer(SC::Uniform, t_vec4);
  if (!rel) {
    const ir::ConstDef* def = defs_.find(RegFile::Const, index);
    if (def && !in_block(index, *def)) return def_value(*def);
    // Far beyond any device's constant count (bad input the validator would reject): read
    // 0 rather than declare a gigantic block, as the interpreter's missing registers do.
    if (index >= 65536) return vec4_const(0, 0, 0, 0);
    consts_read_.insert(index);
    // CodegenOptions::known_*_constants: the value this register will hold, if known.
    const auto& known =
        prog.stage() == ir::ShaderStage::Vertex ? opt.known_vs_constants : opt.known_ps_constants;
    const std::array<float, 4>* k =
        known && !def && index < known->size() ? &(*known)[index] : nullptr;
    Id value;
    if (k && replicated(*k)) {
      // x stands for all four components.
      const Id x =
          b.op(Op::OpAccessChain, b.type_pointer(SC::Uniform, t_float),
               {uniform_var_, b.const_uint(kMemberFloat), b.const_uint(index), b.const_uint(0)});
      value = splat(b.op(Op::OpLoad, t_float, {x}));
    } else {
      const Id chain = b.op(Op::OpAccessChain, ptr_vec4,
                            {uniform_var_, b.const_uint(kMemberFloat), b.const_uint(index)});
      value = b.op(Op::OpLoad, t_vec4, {chain});
    }
    if (k) {
      uint8_t never_zero = 0;
      for (int c = 0; c < 4; ++c)
        if (ir::numerics::never_compares_zero((*k)[static_cast<size_t>(c)]))
          never_zero |= static_cast<uint8_t>(1u << c);
      set_never_zero(value, never_zero);
    }
    return value;
  }
  const_relative_ = true;
  const Id offset = relative_offset(*rel);
  const auto limit = static_cast<int32_t>(relative_limit());
  const Id idx = b.op(Op::OpIAdd, t_int, {b.const_int(static_cast<int32_t>(index)), offset});
  const Id ge0 = b.op(Op::OpSGreaterThanEqual, t_bool, {idx, b.const_int(0)});
  const Id lt = b.op(Op::OpSLessThan, t_bool, {idx, b.const_int(limit)});
  const Id in_range = b.op(Op::OpLogicalAnd, t_bool, {ge0, lt});
  const Id safe = b.op(Op::OpSelect, t_int, {in_range, idx, b.const_int(0)});
  const Id chain =
      b.op(Op::OpAccessChain, ptr_vec4, {uniform_var_, b.const_uint(kMemberFloat), safe});
  Id value = b.op(Op::OpLoad, t_vec4, {chain});
  for (const auto& [k, d] : defs_.floats) {
    if (in_block(k, d)) continue; // the block holds it at k
    const Id hit = b.op(Op::OpIEqual, t_bool, {idx, b.const_int(static_cast<int32_t>(k))});
    value = b.op(Op::OpSelect, t_vec4, {bsplat(hit), def_value(d), value});
  }
  // SPIR-V 1.3 selects need a condition as wide as the result.
  return b.op(Op::OpSelect, t_vec4, {bsplat(in_range), value, vec4_const(0, 0, 0, 0)});
}

Id Emitter::relative_offset(const ir::RelAddr& rel) {
  if (rel.file == RegFile::Loop) return b.op(Op::OpLoad, t_int, {loop_var()});
  const Id a0 = b.op(Op::OpLoad, t_ivec4, {register_var(RegFile::Addr, 0)});
  return b.op(Op::OpCompositeExtract, t_int, {a0, static_cast<uint32_t>(rel.component & 3)});
}

// v[aL + n] in a vs_3_0/ps_3_0: the declared inputs by v# number (plan.relative_inputs),
// each read as a plain read of its linked register would read it, chosen by the index; an
// index outside the table or on an undeclared v# reads (0, 0, 0, 0) (NUMERICS.md F13). A
// select chain rather than a Private array: a program declares at most 16 inputs.
Id Emitter::load_relative_input(uint32_t index, const ir::RelAddr& rel) {
  const Id idx =
      b.op(Op::OpIAdd, t_int, {b.const_int(static_cast<int32_t>(index)), relative_offset(rel)});
  Id value = vec4_const(0, 0, 0, 0);
  for (size_t k = 0; k < plan.relative_inputs.size(); ++k) {
    const auto& link = plan.relative_inputs[k];
    if (!link) continue;
    const Id hit = b.op(Op::OpIEqual, t_bool, {idx, b.const_int(static_cast<int32_t>(k))});
    const Id v = load_register(link->first, link->second, std::nullopt);
    value = b.op(Op::OpSelect, t_vec4, {bsplat(hit), v, value});
  }
  return value;
}

uint32_t Emitter::relative_limit() const {
  // Relative reads may reach any constant the device offers (the relative-reach pass, which
  // the interpreter reads too); outside → (0, 0, 0, 0).
  return ir::relative_constant_limit(prog.profile);
}

Id Emitter::loop_var() {
  if (!aL_var_) {
    aL_var_ = b.global_variable(b.type_pointer(SC::Private, t_int), SC::Private, b.const_int(0));
    b.name(aL_var_, "aL");
  }
  return aL_var_;
}

Id Emitter::load_int_const(uint32_t index) {
  if (const ir::ConstDef* d = defs_.find(RegFile::ConstInt, index)) {
    const Id parts[] = {b.const_int(d->i(0)), b.const_int(d->i(1)), b.const_int(d->i(2)),
                        b.const_int(d->i(3))};
    return b.const_composite(t_ivec4, parts);
  }
  const Id chain = b.op(Op::OpAccessChain, b.type_pointer(SC::Uniform, t_ivec4),
                        {uniform_var_, b.const_uint(kMemberInt), b.const_uint(index)});
  return b.op(Op::OpLoad, t_ivec4, {chain});
}

Id Emitter::load_bool_const(uint32_t index) {
  if (const ir::ConstDef* d = defs_.find(RegFile::ConstBool, index)) return b.const_bool(d->b());
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
    if (rel) return load_relative_input(index, *rel);
    const Id v = b.op(Op::OpLoad, t_vec4, {input_var(file, index)});
    // Pixel colour inputs are saturated on input before ps_3_0 (NUMERICS.md 26); a ps_3_0
    // colour is a float register (F6).
    const bool saturated =
        prog.stage() == ir::ShaderStage::Pixel && ir::saturates_colors(prog.profile);
    return saturated ? rule::saturate(arith(4), v) : v;
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
  case RegFile::Misc: return misc_input(index);
  default: break;
  }
  return vec4_const(0, 0, 0, 0); // samplers, labels, i#, b#: read by their instructions
}

Id Emitter::load_src(const ir::SrcOperand& s, uint32_t index_offset) {
  Id v = load_register(s.file, s.index + index_offset, s.rel);
  // Only a swizzle and a sign change keep a never-zero component so (Emitter::never_zero_);
  // the ps_1_x clamp and the other modifiers may make zeros.
  const uint8_t nonzero_read =
      (s.mod == SrcMod::None || s.mod == SrcMod::Neg) && !ir::is_ps1x(prog.profile) ? never_zero(v)
                                                                                    : uint8_t{0};
  if (s.file == RegFile::Const && ir::is_ps1x(prog.profile) && !const_within_unit(s))
    v = rule::clamp_sym(arith(4), v, splat(f(1.0f)));
  if (const int8_t by = ir::src_mod_info(s.mod).divide_by; by >= 0) {
    Id x = comp(v, 0), y = comp(v, 1);
    rule::project_divide(arith(1), x, y, comp(v, static_cast<uint32_t>(by)));
    v = compose(x, y, comp(v, 2), comp(v, 3));
  }
  if (s.swizzle != ir::kIdentitySwizzle) {
    v = b.op(Op::OpVectorShuffle, t_vec4,
             {v, v, ir::swizzle_component(s.swizzle, 0), ir::swizzle_component(s.swizzle, 1),
              ir::swizzle_component(s.swizzle, 2), ir::swizzle_component(s.swizzle, 3)});
  }
  const Id out = ir::apply_source_modifier(arith(4), planted(s.mod), v);
  uint8_t swizzled = 0;
  for (int c = 0; c < 4; ++c)
    swizzled |=
        static_cast<uint8_t>(((nonzero_read >> ir::swizzle_component(s.swizzle, c)) & 1) << c);
  set_never_zero(out, swizzled);
  return out;
}

// Whether the clamp of a ps_1_x constant read to [−1, 1] changes nothing: with its values
// known (CodegenOptions::known_ps_constants), each component is ±0 or a normal number of magnitude
// at most 1 (a denormal would be flushed by the clamp's min/max).
bool Emitter::const_within_unit(const ir::SrcOperand& s) const {
  if (!opt.known_ps_constants || s.rel) return false;
  const auto value = ir::constant_value(defs_, s.index, *opt.known_ps_constants);
  if (!value) return false;
  for (const float x : *value)
    if (!(std::fabs(x) <= 1.0f) || (!ir::numerics::signed_zero(x) && std::fabs(x) < FLT_MIN))
      return false;
  return true;
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
      parts[i] =
          to_index(floor_mode ? rule::mov_a0_floor(arith(1), x) : rule::mova_round(arith(1), x));
      if (st.pred) // predicated: the old value where the predicate does not hold
        parts[i] = b.op(Op::OpSelect, t_int,
                        {b.op(Op::OpCompositeExtract, t_bool, {st.pred, i}), parts[i],
                         b.op(Op::OpCompositeExtract, t_int, {old, i})});
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
  if (ps1x_range && !st.within_ps1x_range)
    v = rule::clamp_sym(arith(4), v, splat(ps1x_max_value()));
  if (st.mods.sat) v = rule::saturate(arith(4), v);
  if (ps1x_range && opt.conventions.ps1x_fixed_bits > 0) {
    const float scale = std::ldexp(1.0f, std::clamp(opt.conventions.ps1x_fixed_bits, 1, 23));
    v = rule::fixed_quantise(arith(4), v, splat(f(scale)), splat(ps1x_max_value()));
  }
  if (st.dst.file == RegFile::DepthOut) writes_depth_ = true;
  if (st.dst.rel) {
    // o[aL + n] in a vs_3_0: every declared output by o# number (plan.relative_outputs) is
    // written where the index names it and keeps its value elsewhere; an index outside the
    // table or on an undeclared o# writes nothing (NUMERICS.md F13). Selects, not branches.
    const Id idx =
        b.op(Op::OpIAdd, t_int,
             {b.const_int(static_cast<int32_t>(st.dst.index)), relative_offset(*st.dst.rel)});
    for (size_t k = 0; k < plan.relative_outputs.size(); ++k) {
      const auto& link = plan.relative_outputs[k];
      if (!link) continue;
      const Id hit = b.op(Op::OpIEqual, t_bool, {idx, b.const_int(static_cast<int32_t>(k))});
      write_register(register_var(link->first, link->second), v, st, hit);
    }
    return;
  }
  write_register(register_var(st.dst.file, st.dst.index), v, st);
}

void Emitter::write_register(Id var, Id v, const PendingStore& st, Id hit) {
  const uint8_t mask = st.mask & 0xF;
  if (st.pred) // predicated: the old value where the predicate does not hold
    v = b.op(Op::OpSelect, t_vec4, {st.pred, v, b.op(Op::OpLoad, t_vec4, {var})});
  if (mask != 0xF || hit) {
    const Id old = b.op(Op::OpLoad, t_vec4, {var});
    if (mask != 0xF) {
      uint32_t sel[4];
      for (uint32_t i = 0; i < 4; ++i) sel[i] = (mask & (1u << i)) ? i : 4 + i;
      v = b.op(Op::OpVectorShuffle, t_vec4, {v, old, sel[0], sel[1], sel[2], sel[3]});
    }
    if (hit) v = b.op(Op::OpSelect, t_vec4, {bsplat(hit), v, old});
  }
  b.op_void(Op::OpStore, {var, v});
}

} // namespace tierlift::codegen
