// Which register components an instruction reads and writes. Read-before-write checks,
// declaration-mask checks and the oT# mask rule all need the same answer, so it lives here
// once: the lanes an operation consumes (docs/d3d9-rules.md §5 semantics), mapped through the
// source swizzle.
#include "context.h"

namespace tierlift::as::detail {
namespace {

using ir::Opcode;

uint8_t through_swizzle(uint8_t lanes, uint8_t swz) {
  uint8_t out = 0;
  for (int l = 0; l < 4; ++l)
    if (lanes & (1 << l)) out |= static_cast<uint8_t>(1 << ir::swizzle_component(swz, l));
  return out;
}

// Scalar operands: with a replicate swizzle every lane is the same component. (A bare
// rcp/rsq source in text is already .x: the parser applies the assembler's rule.) Any
// other swizzle is an error or was rewritten by apply_windows_leniency; the devices' rule,
// the 4th slot, is used for it.
uint8_t scalar_component(const ir::Instruction&, const ir::SrcOperand& s) {
  return static_cast<uint8_t>(1 << ir::swizzle_component(s.swizzle, 3));
}

// Lanes (of the swizzled value) that source k feeds into the result.
uint8_t lanes(const ir::Instruction& ins, size_t k, ir::Profile p, int sampler_dim) {
  const uint8_t m = ins.dst ? ins.dst->mask : ir::kFullMask;
  switch (ins.op) {
  case Opcode::Frc: return p == ir::Profile::vs_1_1 ? (m & 0x3) : m;
  case Opcode::Dp3: return 0x7;
  case Opcode::Dp4: return 0xF;
  case Opcode::Lit: return (m & 0x4) ? 0xB : (m & 0x2) ? 0x1 : 0;
  case Opcode::Dst:
    if (k == 0) return ((m & 0x2) ? 0x2 : 0) | ((m & 0x4) ? 0x4 : 0);
    return ((m & 0x2) ? 0x2 : 0) | ((m & 0x8) ? 0x8 : 0);
  case Opcode::Crs: {
    uint8_t l = 0;
    if (m & 1) l |= 0x6;
    if (m & 2) l |= 0x5;
    if (m & 4) l |= 0x3;
    return l;
  }
  case Opcode::Nrm: return 0x7 | (m & 0x8);
  case Opcode::Dp2Add: return 0x3;
  case Opcode::M4x4:
  case Opcode::M4x3: return 0xF;
  case Opcode::M3x4:
  case Opcode::M3x3:
  case Opcode::M3x2: return 0x7;
  case Opcode::Sgn: return k == 0 ? m : 0; // src1/src2 are scratch, written not read
  case Opcode::Bem: return 0x3;
  case Opcode::TexLd14:
  case Opcode::TexCrd: return 0x7;
  case Opcode::TexLd: return sampler_dim >= 3 ? 0x7 : 0x3;
  case Opcode::TexLdP:
  case Opcode::TexLdB: return (sampler_dim >= 3 ? 0x7 : 0x3) | 0x8;
  case Opcode::TexBem: return 0x3;
  case Opcode::TexBemL: return 0x7;
  case Opcode::TexReg2Ar: return 0x9;
  case Opcode::TexReg2Gb: return 0x6;
  case Opcode::TexReg2Rgb:
  case Opcode::TexM3x2Pad:
  case Opcode::TexM3x2Tex:
  case Opcode::TexM3x2Depth:
  case Opcode::TexM3x3Pad:
  case Opcode::TexM3x3Tex:
  case Opcode::TexM3x3:
  case Opcode::TexM3x3Spec:
  case Opcode::TexM3x3VSpec:
  case Opcode::TexDp3:
  case Opcode::TexDp3Tex: return 0x7;
  default: return m;
  }
}

} // namespace

uint8_t source_read_mask(const ir::Instruction& ins, size_t k, ir::Profile p, int sampler_dim) {
  if (k >= ins.src.size()) return 0;
  const ir::OpInfo& info = info_of(ins);
  const ir::SrcOperand& s = ins.src[k];
  if (k < info.num_src && info.src[k] == ir::OperandKind::Scalar) return scalar_component(ins, s);
  if (ins.op == Opcode::Dp2Add && k == 2) return scalar_component(ins, s);
  if (ins.op == Opcode::SinCos && k == 0) return scalar_component(ins, s);
  uint8_t comps = through_swizzle(lanes(ins, k, p, sampler_dim), s.swizzle);
  // _dw / _dz divide by the register's w / z before the swizzle (docs/d3d9-rules.md §7 step 2).
  if (s.mod == ir::SrcMod::Dw) comps |= 0x8;
  if (s.mod == ir::SrcMod::Dz) comps |= 0x4;
  return comps;
}

uint8_t dest_write_mask(const ir::Instruction& ins, ir::Profile p) {
  if (!ins.dst) return 0;
  const uint8_t m = ins.dst->mask;
  switch (ins.op) {
  case Opcode::M3x2: return m & 0x3;
  case Opcode::M3x3:
  case Opcode::M4x3: return m & 0x7;
  case Opcode::Frc: return p == ir::Profile::vs_1_1 ? (m & 0x3) : m;
  case Opcode::SinCos: return m & 0x3; // d.z is undefined afterwards, d.w untouched
  case Opcode::Crs: return m & 0x7;
  // Pads, texkill, texdepth, texm3x2depth leave nothing readable in their register.
  case Opcode::TexM3x2Pad:
  case Opcode::TexM3x3Pad:
  case Opcode::TexKill:
  case Opcode::TexDepth:
  case Opcode::TexM3x2Depth: return 0;
  case Opcode::TexCrd: {
    bool dw = !ins.src.empty() && ins.src[0].mod == ir::SrcMod::Dw;
    return m & (dw ? 0x3 : 0x7); // the 4th (and with _dw the 3rd) channel is undefined
  }
  default: break;
  }
  if (is_texture_op(ins)) return ir::kFullMask;
  return m;
}

} // namespace tierlift::as::detail
