// Read and write sets of an instruction, from the opcode table's semantic columns. One
// answer for every consumer: the validator's read-before-write and declaration-mask rules,
// liveness and constant scans in the IR passes, the interpreter's write masks.
#include "tierlift/ir/semantics.h"

namespace tierlift::ir {
namespace {

// The table row; a corrupt opcode value (from a damaged bytecode file) reads as nop.
Opcode checked(const Instruction& ins) {
  const auto v = static_cast<int>(ins.op);
  return v >= 0 && v < kOpcodeCount ? ins.op : Opcode::Nop;
}
const OpInfo& row_of(const Instruction& ins) {
  return op_info(checked(ins));
}
const OpSemantics& sem_of(const Instruction& ins) {
  return op_semantics(checked(ins));
}

uint8_t through_swizzle(uint8_t lanes, uint8_t swz) {
  uint8_t out = 0;
  for (int l = 0; l < 4; ++l)
    if (lanes & (1 << l)) out |= static_cast<uint8_t>(1 << swizzle_component(swz, l));
  return out;
}

bool is_scalar_source(const Instruction& ins, size_t k) {
  const OpInfo& info = row_of(ins);
  return k < info.num_src && info.src[k] == OperandKind::Scalar;
}

} // namespace

uint32_t source_rows(const Instruction& ins, size_t k) {
  const OpSemantics& sem = sem_of(ins);
  return k == 1 && sem.matrix_rows > 0 ? sem.matrix_rows : 1;
}

uint8_t written_mask(const Instruction& ins, Profile p) {
  if (!ins.dst) return 0;
  const OpInfo& info = row_of(ins);
  const uint8_t w = sem_of(ins).writes[profile_index(p)];
  if (ins.op == Opcode::TexCrd) {
    // The 4th (and with _dw the 3rd) channel is undefined afterwards.
    const bool dw = !ins.src.empty() && ins.src[0].mod == SrcMod::Dw;
    return ins.dst->mask & (dw ? (w & 0x3) : w);
  }
  if (info.cls == OpClass::Texture) return w;
  return ins.dst->mask & w;
}

uint8_t source_lanes(const Instruction& ins, size_t k, Profile p, int sampler_dim) {
  const OpSemantics& sem = sem_of(ins);
  const uint8_t m = ins.dst ? ins.dst->mask : kFullMask;
  const uint8_t coords = sampler_dim >= 3 ? 0x7 : 0x3;
  switch (sem.lanes) {
  case LaneRule::Written: return m & sem.writes[profile_index(p)];
  case LaneRule::Fixed: return sem.src_lanes;
  case LaneRule::Lit: return (m & 0x4) ? 0xB : (m & 0x2) ? 0x1 : 0;
  case LaneRule::Dst:
    if (k == 0) return ((m & 0x2) ? 0x2 : 0) | ((m & 0x4) ? 0x4 : 0);
    return ((m & 0x2) ? 0x2 : 0) | ((m & 0x8) ? 0x8 : 0);
  case LaneRule::Cross: {
    uint8_t l = 0;
    if (m & 1) l |= 0x6;
    if (m & 2) l |= 0x5;
    if (m & 4) l |= 0x3;
    return l;
  }
  case LaneRule::Normalize: return 0x7 | (m & 0x8);
  case LaneRule::FirstOnly: return k == 0 ? m : 0;
  case LaneRule::Coordinate: return coords;
  case LaneRule::CoordinateW: return coords | 0x8;
  }
  return m;
}

uint8_t source_read_mask(const Instruction& ins, size_t k, Profile p, int sampler_dim) {
  if (k >= ins.src.size()) return 0;
  const SrcOperand& s = ins.src[k];
  // A scalar operand has a replicate swizzle; any other swizzle is an error or was
  // rewritten by the Windows leniency pass, and the devices take its 4th slot.
  if (is_scalar_source(ins, k)) return static_cast<uint8_t>(1 << swizzle_component(s.swizzle, 3));
  uint8_t comps = through_swizzle(source_lanes(ins, k, p, sampler_dim), s.swizzle);
  // _dw / _dz divide by the register's w / z before the swizzle.
  if (s.mod == SrcMod::Dw) comps |= 0x8;
  if (s.mod == SrcMod::Dz) comps |= 0x4;
  return comps;
}

} // namespace tierlift::ir
