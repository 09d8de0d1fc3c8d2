// Destination and source parameter tokens → IR operands. Every bit the IR cannot hold must
// be clear, so that assemble(disassemble(t)) gives t back bit for bit.
#include <fmt/format.h>

#include "token_layout.h"
#include "token_reader.h"

namespace tierlift::assembly::bc {
namespace {

// Registers whose name fixes the number: anything else could not be printed and re-read.
bool nameable(ir::RegFile file, uint32_t index) {
  switch (file) {
  case ir::RegFile::RastOut: return index <= ir::kRastPts;
  case ir::RegFile::Addr:
  case ir::RegFile::DepthOut:
  case ir::RegFile::Predicate:
  case ir::RegFile::Loop: return index == 0;
  case ir::RegFile::Misc: return index <= ir::kMiscFace;
  default: return true;
  }
}

} // namespace

bool TokenReader::param_common(uint32_t tok, size_t at, const char* what, ir::RegFile& file,
                               uint32_t& index) {
  if (!(tok & kParamBit))
    return fail(at, fmt::format("{} token without bit 31 (operand missing?)", what));
  if (tok & kParamReserved) return fail(at, fmt::format("reserved bits 14-15 set in {}", what));
  uint8_t type = decode_regtype(tok);
  auto f = ir::regfile_from_bytecode(type, p_.profile);
  if (!f) return fail(at, fmt::format("register type {} is not used by these profiles", type));
  index = tok & kRegNumMask;
  if (!nameable(*f, index))
    return fail(at, fmt::format("register type {} has no register number {}", type, index));
  file = *f;
  return true;
}

bool TokenReader::dst(uint32_t tok, size_t at, ir::DstOperand& out, ir::InstrMods& mods) {
  if (!param_common(tok, at, "destination", out.file, out.index)) return false;
  if ((tok & kRelativeBit) && p_.profile != ir::Profile::vs_3_0)
    return fail(at, "relative addressing of a destination is only in vs_3_0 (o[a0.x + n])");
  uint32_t resmod = (tok & kResultModMask) >> kResultModShift;
  if (resmod & ~(kResultSat | kResultPp | kResultCentroid))
    return fail(at, fmt::format("unknown result modifier bits 0x{:X}", resmod));
  int shift = decode_shift(tok);
  if (shift < -3 || shift > 3)
    return fail(at, fmt::format("shift field {} is not x2, x4, x8, d2, d4 or d8",
                                (tok & kShiftMask) >> kShiftShift));
  out.mask = static_cast<uint8_t>((tok & kMaskMask) >> kMaskShift);
  // No assembler writes an empty mask, and no text could spell one.
  if (out.mask == 0) return fail(at, "empty write mask");
  out.loc = loc_at(at);
  mods.sat = (resmod & kResultSat) != 0;
  mods.pp = (resmod & kResultPp) != 0;
  mods.centroid = (resmod & kResultCentroid) != 0;
  mods.shift = static_cast<int8_t>(shift);
  if (!(tok & kRelativeBit)) return true;
  ir::SrcOperand address; // relative() fills the RelAddr of a source; the destination takes it
  if (!relative(address)) return false;
  out.rel = address.rel;
  return true;
}

bool TokenReader::src(uint32_t tok, size_t at, ir::SrcOperand& out) {
  if (!param_common(tok, at, "source", out.file, out.index)) return false;
  uint32_t mod = (tok & kSrcModMask) >> kSrcModShift;
  if (mod > static_cast<uint32_t>(ir::SrcMod::Not))
    return fail(at, fmt::format("unknown source modifier {}", mod));
  out.swizzle = static_cast<uint8_t>((tok & kSwizzleMask) >> kSwizzleShift);
  out.mod = static_cast<ir::SrcMod>(mod);
  out.loc = loc_at(at);
  if (!(tok & kRelativeBit)) return true;
  if (p_.stage() != ir::ShaderStage::Vertex && p_.profile != ir::Profile::ps_3_0)
    return fail(at, "relative addressing in a pixel shader before ps_3_0");
  if (!has_length_field(p_.profile)) {
    // vs_1_1: the bit alone; a0.x is implied and no address token follows.
    out.rel = ir::RelAddr{ir::RegFile::Addr, 0, loc_at(at), std::nullopt};
    return true;
  }
  return relative(out);
}

// SM2+: the token after a relative operand names a0 or aL with a replicate swizzle.
bool TokenReader::relative(ir::SrcOperand& out) {
  uint32_t tok = 0;
  size_t at = 0;
  if (!next(tok, at)) return false;
  ir::RegFile file{};
  uint32_t index = 0;
  if (!param_common(tok, at, "relative address", file, index)) return false;
  if (file != ir::RegFile::Addr && file != ir::RegFile::Loop)
    return fail(at, "relative address register is not a0 or aL");
  if (tok & (kRelativeBit | kSrcModMask))
    return fail(at, "relative address token with a modifier or relative bit");
  // Any swizzle: Microsoft's assembler writes "a0.xyww" as it stands and the identity for a
  // bare a0 and for aL; the first component selected is the one added. It is kept so that
  // the tokens assemble back unchanged.
  uint8_t swz = static_cast<uint8_t>((tok & kSwizzleMask) >> kSwizzleShift);
  if (file == ir::RegFile::Loop && swz != ir::kIdentitySwizzle && !ir::is_replicate(swz))
    return fail(at, "the aL address token takes the identity or a replicate swizzle");
  out.rel = ir::RelAddr{file, static_cast<uint8_t>(file == ir::RegFile::Loop ? 0 : swz & 3),
                        loc_at(at), swz};
  return true;
}

} // namespace tierlift::assembly::bc
