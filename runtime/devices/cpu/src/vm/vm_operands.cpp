// Operand fetch and store in the order of docs/d3d9-rules.md §7: fetch (ps_1_x constant clamp,
// relative addressing), pre-swizzle _dz/_dw, swizzle, post-swizzle modifiers with negate
// last; store: shift, ps_1_x range clamp, _sat, fixed-point quantise, write mask.
#include <string>

#include "tierlift/ir/numerics.h"
#include "tierlift/ir/source_modifiers.h"
#include "vm_internal.h"

namespace tierlift::cpu::vm {

namespace num = ir::numerics;
using ir::RegFile;
using ir::SrcMod;
using num::Denormals;

int flat_slot(RegFile file, uint32_t index, ir::ShaderStage stage) {
  const bool vertex = stage == ir::ShaderStage::Vertex;
  auto in = [&](int base, uint32_t count) {
    return index < count ? base + static_cast<int>(index) : -1;
  };
  switch (file) {
  case RegFile::Temp: return in(kTempBase, kTempCount);
  case RegFile::Input: return in(kInputBase, kInputCount);
  case RegFile::Texture: return in(kTexBase, kTexCount);
  case RegFile::RastOut: return vertex ? in(kOutBase + kOutPos, 3) : -1;
  case RegFile::AttrOut: return vertex ? in(kOutBase + kOutD0, 2) : -1;
  case RegFile::TexCrdOut: return vertex ? in(kOutBase + kOutT0, 8) : -1;
  case RegFile::ColorOut: return vertex ? -1 : in(kOutBase + kOutC0, 4);
  case RegFile::DepthOut: return vertex ? -1 : in(kOutBase + kOutDepth, 1);
  case RegFile::Misc: return vertex ? -1 : in(kMiscBase, kMiscCount);
  default: return -1;
  }
}

SrcDesc decode_src(const ir::SrcOperand& op, const Prepared& p) {
  SrcDesc s;
  for (int i = 0; i < 4; ++i) s.swz[i] = ir::swizzle_component(op.swizzle, i);
  s.identity = op.swizzle == ir::kIdentitySwizzle;
  s.mod = op.mod;
  if (op.file == RegFile::Const) {
    s.clamp_const = p.ps1x;
    s.slot = static_cast<uint16_t>(op.index > 0xFFFF ? 0xFFFF : op.index);
    if (op.rel) {
      s.kind = SrcKind::ConstRel;
      s.rel = op.rel->file == RegFile::Loop ? 4 : static_cast<int8_t>(op.rel->component & 3);
    } else {
      s.kind = SrcKind::Const;
      if (op.index < p.const_defs.size() && p.const_defs[op.index])
        s.def = &*p.const_defs[op.index];
    }
    return s;
  }
  if (op.file == RegFile::Input && op.rel) { // vs_3_0/ps_3_0 v[aL + n]: the input table
    s.kind = SrcKind::InputRel;
    s.slot = static_cast<uint16_t>(op.index > 0xFFFF ? 0xFFFF : op.index);
    s.rel = op.rel->file == RegFile::Loop ? 4 : static_cast<int8_t>(op.rel->component & 3);
    return s;
  }
  int slot = flat_slot(op.file, op.index, p.program.stage());
  if (slot < 0) {
    // Samplers, labels, i#, b#, aL are not read as vectors: they stay Zero and the
    // executor reads the operand itself.
    s.kind = SrcKind::Zero;
    return s;
  }
  s.kind = SrcKind::Slot;
  s.slot = static_cast<uint16_t>(slot);
  s.simple = s.identity && s.mod == SrcMod::None;
  return s;
}

ir::Result<DstDesc> decode_dst(const ir::DstOperand& op, const ir::InstrMods& mods,
                               const Prepared& p) {
  DstDesc d;
  d.mask = op.mask & 0xF;
  d.sat = mods.sat;
  d.scale = std::ldexp(1.0f, mods.shift);
  d.flush = p.flush;
  if (op.file == RegFile::Addr) {
    d.kind = p.vs11 ? DstKind::AddrFloor : DstKind::AddrRound;
    return d;
  }
  if (op.file == RegFile::Output && op.rel) { // vs_3_0 o[aL + n]: the output table
    d.kind = DstKind::OutputRel;
    d.slot = static_cast<uint16_t>(op.index > 0xFFFF ? 0xFFFF : op.index);
    d.rel = op.rel->file == RegFile::Loop ? 4 : static_cast<int8_t>(op.rel->component & 3);
    return d; // never `plain`: the store resolves the slot
  }
  int slot = flat_slot(op.file, op.index, p.program.stage());
  if (slot < 0)
    return ir::fail("cpu", std::string(kVmRule),
                    "destination " + ir::register_name(op.file, op.index) +
                        " is not writable in this profile");
  d.kind = DstKind::Slot;
  d.slot = static_cast<uint16_t>(slot);
  if (slot >= kOutBase) d.out_bit = static_cast<uint16_t>(1u << (slot - kOutBase));
  if (p.ps1x && (op.file == RegFile::Temp || op.file == RegFile::Texture)) {
    d.range = true;
    d.max_value = p.conv.ps1x_max_value;
    d.fixed_bits = p.conv.ps1x_fixed_bits;
  }
  d.plain = d.scale == 1.0f && !d.sat && !d.range && d.fixed_bits == 0;
  return d;
}

Vec4 constant_value(int32_t index, const Invocation& inv) {
  const Prepared& p = *inv.prog;
  if (index < 0 || index >= p.const_limit) return {0, 0, 0, 0};
  auto i = static_cast<size_t>(index);
  if (i < p.const_defs.size() && p.const_defs[i]) return *p.const_defs[i];
  if (i < inv.consts->f.size()) return inv.consts->f[i];
  return {0, 0, 0, 0};
}

namespace {

Vec4 load(const SrcDesc& s, const Invocation& inv) {
  switch (s.kind) {
  case SrcKind::Slot: return inv.reg[s.slot];
  case SrcKind::Const:
    if (s.def) return *s.def;
    return s.slot < inv.consts->f.size() ? inv.consts->f[s.slot] : Vec4{0, 0, 0, 0};
  case SrcKind::ConstRel: {
    int32_t off = s.rel == 4 ? inv.al : inv.a0[s.rel];
    return constant_value(static_cast<int32_t>(s.slot) + off, inv);
  }
  case SrcKind::InputRel: {
    // Outside the table or an undeclared v#: (0, 0, 0, 0) (NUMERICS.md F13).
    const auto& table = inv.prog->rel_inputs;
    const int64_t k = int64_t{s.slot} + (s.rel == 4 ? inv.al : inv.a0[s.rel]);
    if (k < 0 || k >= static_cast<int64_t>(table.size()) || table[static_cast<size_t>(k)] < 0)
      break;
    return inv.reg[table[static_cast<size_t>(k)]];
  }
  case SrcKind::Zero: break;
  }
  return {0, 0, 0, 0};
}

} // namespace

template <Denormals D> Vec4 modify_src(const SrcDesc& s, Vec4 v) {
  const num::FloatArith<D> a;
  if (s.clamp_const)
    for (float& x : v) x = num::legacy_ps1x_const<D>(x);
  if (s.mod != SrcMod::None) {
    const ir::SrcModInfo& info = ir::src_mod_info(s.mod);
    if (info.divide_by >= 0) num::rule::project_divide(a, v[0], v[1], v[info.divide_by]);
  }
  if (!s.identity) v = Vec4{v[s.swz[0]], v[s.swz[1]], v[s.swz[2]], v[s.swz[3]]};
  if (s.mod != SrcMod::None)
    for (float& x : v) x = ir::apply_source_modifier(a, s.mod, x);
  return v;
}
template Vec4 modify_src<Denormals::Keep>(const SrcDesc& s, Vec4 v);
template Vec4 modify_src<Denormals::Flush>(const SrcDesc& s, Vec4 v);

namespace {

template <Denormals D> void store_modified(const DstDesc& d, const Vec4& value, Invocation& inv) {
  switch (d.kind) {
  case DstKind::None: return;
  case DstKind::AddrFloor:
    for (int i = 0; i < 4; ++i)
      if (d.mask & (1 << i)) inv.a0[i] = num::legacy_mov_a0_floor<D>(value[i]);
    return;
  case DstKind::AddrRound:
    for (int i = 0; i < 4; ++i)
      if (d.mask & (1 << i)) inv.a0[i] = num::legacy_mova_round<D>(value[i]);
    return;
  case DstKind::Slot: break;
  case DstKind::OutputRel: {
    // Outside the table or an undeclared o#: nothing is written (NUMERICS.md F13).
    const auto& table = inv.prog->rel_outputs;
    const int64_t k = int64_t{d.slot} + (d.rel == 4 ? inv.al : inv.a0[d.rel]);
    if (k < 0 || k >= static_cast<int64_t>(table.size()) || table[static_cast<size_t>(k)] < 0)
      return;
    DstDesc resolved = d;
    resolved.kind = DstKind::Slot;
    resolved.slot = static_cast<uint16_t>(table[static_cast<size_t>(k)]);
    resolved.out_bit = static_cast<uint16_t>(1u << (resolved.slot - kOutBase));
    store_modified<D>(resolved, value, inv);
    return;
  }
  }
  Vec4& r = inv.reg[d.slot];
  for (int i = 0; i < 4; ++i) {
    if (!(d.mask & (1 << i))) continue;
    r[i] = dst_transform<D>(d, value[i]);
  }
  inv.out_written |= d.out_bit;
}

} // namespace

Vec4 fetch_general(const SrcDesc& s, const Invocation& inv) {
  return inv.prog->flush ? modify_src<Denormals::Flush>(s, load(s, inv))
                         : modify_src<Denormals::Keep>(s, load(s, inv));
}

void store_general(const DstDesc& d, const Vec4& value, Invocation& inv) {
  if (d.flush)
    store_modified<Denormals::Flush>(d, value, inv);
  else
    store_modified<Denormals::Keep>(d, value, inv);
}

} // namespace tierlift::cpu::vm
