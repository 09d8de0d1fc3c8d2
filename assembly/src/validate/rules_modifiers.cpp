// Instruction modifiers (_sat, shifts, _pp, _centroid), source modifiers and source swizzles,
// each gated by profile and instruction (docs/d3d9-rules.md §4.1–§4.3, §4.5, §5.5).
#include <map>

#include "context.h"
#include "tierlift/ir/source_modifiers.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::OperandKind;
using ir::RegFile;
using ir::SrcMod;

const uint8_t kXyz = ir::make_swizzle(0, 1, 2, 2);
const uint8_t kXyw = ir::make_swizzle(0, 1, 3, 3);

std::string shift_text(int shift) {
  switch (shift) {
  case 1: return "_x2";
  case 2: return "_x4";
  case 3: return "_x8";
  case -1: return "_d2";
  case -2: return "_d4";
  case -3: return "_d8";
  default: return fmt::format("shift {}", shift);
  }
}

std::string_view srcmod_text(SrcMod m) {
  return ir::src_mod_info(m).name;
}

void check_instr_mods(Ctx& c, const ir::Instruction& ins) {
  const ir::InstrMods& m = ins.mods;
  std::string_view mn = mnemonic(ins);
  if (m.shift != 0) {
    if (!c.ps1x())
      c.error(ins.loc, "modifier",
              fmt::format("{} is not allowed in {}: result shifts exist only in ps_1_x",
                          shift_text(m.shift), c.pname()));
    else if (m.shift > 3 || m.shift < -3 || ((m.shift == 3 || m.shift <= -2) && !c.ps14()))
      c.error(ins.loc, "modifier",
              fmt::format("{} is not allowed in {}; it allows _x2, _x4 and _d2{}",
                          shift_text(m.shift), c.pname(), c.ps14() ? ", _x8, _d4, _d8" : ""));
    else if (!is_arith_op(ins))
      c.error(ins.loc, "modifier",
              fmt::format("{} applies only to arithmetic instructions, not {}", shift_text(m.shift),
                          mn));
  }
  if (m.sat) {
    if (c.vs() && !c.vs30())
      c.error(ins.loc, "modifier",
              fmt::format("_sat is not allowed in {} (vs_3_0 only)", c.pname()));
    else if (!is_arith_op(ins))
      c.error(ins.loc, "modifier", fmt::format("_sat is not allowed on {}", mn));
    else if (c.target == ir::Profile::ps_2_0 && (ins.op == Opcode::Frc || ins.op == Opcode::SinCos))
      c.error(ins.loc, "modifier", fmt::format("_sat is not allowed on {} in ps_2_0", mn));
  }
  if (m.pp && !c.ps2up())
    c.error(ins.loc, "modifier",
            fmt::format("_pp is not allowed in {}: partial precision is a ps_2_0 hint", c.pname()));
  if (m.centroid) c.error(ins.loc, "modifier", "_centroid is only allowed on ps_2_0 declarations");
}

bool bx2_allowed_on_texture_op(const Ctx& c, Opcode op) {
  const bool m3x = ir::texm_rows(op) != 0; // the texm3x2* / texm3x3* rows
  if (c.target == ir::Profile::ps_1_1) return m3x;
  // ps_1_2/1_3: every tex* source but these four (the texbem allowance is a doc conflict;
  // the instruction pages' exclusion is used).
  return op != Opcode::TexReg2Ar && op != Opcode::TexReg2Gb && op != Opcode::TexBem &&
         op != Opcode::TexBemL;
}

// The source modifier is legal here, or an error message.
std::string srcmod_problem(const Ctx& c, const ir::Instruction& ins, size_t k, int& dz_count) {
  const ir::SrcOperand& s = ins.src[k];
  const SrcMod m = s.mod;
  if (m == SrcMod::None) return {};
  const ir::OpInfo& info = info_of(ins);
  OperandKind kind = k < info.num_src ? info.src[k] : OperandKind::Vector;
  std::string_view name = srcmod_text(m);
  if (m == SrcMod::Not) {
    // 2.x/3.0: the predicate may be negated where it is read (if !p0.x, breakp !p0.x).
    if (s.file == RegFile::Predicate &&
        (kind == OperandKind::Bool || kind == OperandKind::Predicate))
      return {};
    return ins.op == Opcode::CallNz && k == 1 ? ""
                                              : "! (boolean not) is only allowed on callnz's b#";
  }
  if ((m == SrcMod::Abs || m == SrcMod::AbsNeg) && c.sm3()) return {};
  if (m == SrcMod::Abs || m == SrcMod::AbsNeg)
    return fmt::format("_abs is a vs_3_0/ps_3_0 modifier, not available in {}; use the abs "
                       "instruction",
                       c.pname());
  if (kind == OperandKind::Matrix) return "the matrix operand of a matrix macro takes no modifier";
  if (c.vs() || c.ps2up()) {
    if (m == SrcMod::Neg && (kind == OperandKind::Vector || kind == OperandKind::Scalar ||
                             kind == OperandKind::Temp || kind == OperandKind::Const))
      return (c.ps2up() && is_texture_op(ins)) ? "texture instructions take no source modifier"
                                               : "";
    if (m == SrcMod::Neg) return fmt::format("{} cannot be negated", reg_name(s.file, s.index));
    return fmt::format("{} is not allowed in {}, which only has negate", name, c.pname());
  }
  // ps_1_x from here.
  if (c.ps14() && s.file == RegFile::Const)
    return "ps_1_4 allows no source modifier on a constant register";
  if (c.ps14() && (ins.op == Opcode::TexLd14 || ins.op == Opcode::TexCrd)) {
    if (m == SrcMod::Dw && s.file == RegFile::Texture) return {};
    if (m == SrcMod::Dz && ins.op == Opcode::TexLd14 && s.file == RegFile::Temp) {
      if (++dz_count == 3) return "_dz may be used at most twice per shader; this is the 3rd";
      return {};
    }
    return fmt::format("{} takes only _dw on t# (or _dz on r# for texld), not {}", mnemonic(ins),
                       name);
  }
  if (m == SrcMod::Dz || m == SrcMod::Dw)
    return fmt::format("{} is only allowed on ps_1_4 texld/texcrd sources", name);
  if (is_texture_op(ins)) {
    if (c.ps11_13() && m == SrcMod::Bx2 && k == 0 && bx2_allowed_on_texture_op(c, ins.op))
      return {};
    return fmt::format("{} takes no source modifier{} in {}", mnemonic(ins),
                       c.ps11_13() && bx2_allowed_on_texture_op(c, ins.op) ? " but _bx2" : "",
                       c.pname());
  }
  if ((m == SrcMod::X2 || m == SrcMod::X2Neg) && !c.ps14())
    return fmt::format("{} is a ps_1_4 source modifier, not available in {}", name, c.pname());
  return {};
}

bool ps_swizzle_ok(const Ctx& c, uint8_t swz, uint8_t dst_mask) {
  if (swz == ir::kIdentitySwizzle) return true;
  bool rep = ir::is_replicate(swz);
  int comp = swz & 3;
  if (c.ps11_13()) return rep && (comp == 3 || (comp == 2 && dst_mask == 0x8));
  if (c.ps14()) return rep;
  if (c.caps.arbitrary_swizzle) return true; // ps_2_x with the cap, ps_3_0
  // ps_2_0
  return rep || swz == ir::make_swizzle(1, 2, 0, 3) || swz == ir::make_swizzle(2, 0, 1, 3) ||
         swz == ir::make_swizzle(3, 2, 1, 0);
}

std::string allowed_swizzles(const Ctx& c) {
  if (c.ps11_13()) return "identity, .a (alpha replicate) and .b when the destination is .a";
  if (c.ps14()) return "identity and the replicates .x .y .z .w";
  if (c.target == ir::Profile::ps_2_x)
    return "identity, the replicates .x .y .z .w, .yzxw, .zxyw and .wzyx (these caps have no "
           "arbitrary swizzles)";
  return "identity, the replicates .x .y .z .w, .yzxw, .zxyw and .wzyx";
}

// The swizzle is legal here, or an error message.
std::string swizzle_problem(const Ctx& c, const ir::Instruction& ins, size_t k) {
  const ir::SrcOperand& s = ins.src[k];
  const ir::OpInfo& info = info_of(ins);
  OperandKind kind = k < info.num_src ? info.src[k] : OperandKind::Vector;
  const uint8_t swz = s.swizzle;
  const bool identity = swz == ir::kIdentitySwizzle;
  std::string sw = swizzle_name(swz);
  switch (kind) {
  // Matrix macros: no swizzle on the matrix operand. The m3x2/m3x3/m4x3/m4x4 pages forbid
  // swizzles "in general" (doc conflict); src0 follows the profile's swizzle rules, as the
  // sheet's §4.3 table reads.
  case OperandKind::Matrix:
    return identity ? "" : "the matrix operand of a matrix macro takes no swizzle";
  // p0 read by if, callnz, breakp: one component (.x .y .z .w) or all four.
  case OperandKind::Predicate:
  case OperandKind::Bool:
    if (s.file == RegFile::Predicate)
      return identity || ir::is_replicate(swz)
                 ? ""
                 : fmt::format("p0 is read as one component (.x .y .z .w), not {}", sw);
    return identity ? "" : fmt::format("{} takes no swizzle", reg_name(s.file, s.index));
  case OperandKind::Sampler:
  case OperandKind::Int:
  case OperandKind::Label:
  case OperandKind::LoopReg:
    return identity ? "" : fmt::format("{} takes no swizzle", reg_name(s.file, s.index));
  case OperandKind::Scalar:
    if (ir::is_replicate(swz)) return {};
    // An identity swizzle only comes from a token stream (the parser gives a bare rcp/rsq
    // source .x); apply_windows_leniency rewrites it to .w unless --strict.
    return fmt::format("source {} of {} is a scalar and needs a replicate swizzle (.x, .y, .z "
                       "or .w), not {}",
                       k + 1, info.mnemonic, sw);
  default: break;
  }
  if (ins.op == Opcode::Crs && !identity) return "crs takes no swizzle on its sources";
  if (c.ps2up() && !c.caps.arbitrary_swizzle && is_texture_op(ins) && !identity)
    return fmt::format("{} takes no swizzle on its sources", info.mnemonic);
  if (c.ps11_13() && is_texture_op(ins) && !identity)
    return fmt::format("{} takes no swizzle on its sources", info.mnemonic);
  if (c.ps14() && (ins.op == Opcode::TexLd14 || ins.op == Opcode::TexCrd)) {
    if (s.file == RegFile::Texture) {
      if (s.mod == SrcMod::Dw) return swz == kXyw ? "" : "_dw needs the .xyw selector (tN_dw.xyw)";
      return (identity || swz == kXyz || swz == kXyw)
                 ? ""
                 : fmt::format("{} reads t# as .xyz or .xyw only, not {}", info.mnemonic, sw);
    }
    return (identity || swz == kXyz)
               ? ""
               : fmt::format("{} reads r# as .xyz only, not {}", info.mnemonic, sw);
  }
  if (c.vs()) return {};
  uint8_t dst_mask = ins.dst ? ins.dst->mask : ir::kFullMask;
  if (ps_swizzle_ok(c, swz, dst_mask)) return {};
  return fmt::format("swizzle {} is not allowed in {}; it allows {}", sw, c.pname(),
                     allowed_swizzles(c));
}

// ps_1_4: every texld/texcrd read of one t# uses the same selector (.xyz or .xyw; _dw.xyw
// counts as .xyw). docs/d3d9-rules.md §3.4.
void check_t_selectors(Ctx& c) {
  std::map<uint32_t, uint8_t> first;
  for (const ir::Instruction& ins : c.prog.code) {
    if (ins.op != Opcode::TexLd14 && ins.op != Opcode::TexCrd) continue;
    if (ins.src.empty() || ins.src[0].file != RegFile::Texture) continue;
    const ir::SrcOperand& s = ins.src[0];
    uint8_t sel = s.swizzle == kXyw ? kXyw : kXyz;
    auto [it, fresh] = first.insert({s.index, sel});
    if (!fresh && it->second != sel)
      c.error(s.loc, "swizzle",
              fmt::format("every read of {} must use the same selector; it was read as {} "
                          "before, here as {}",
                          reg_name(s.file, s.index), it->second == kXyw ? ".xyw" : ".xyz",
                          sel == kXyw ? ".xyw" : ".xyz"));
  }
}

} // namespace

void check_modifiers(Ctx& c) {
  int dz_count = 0;
  for (const ir::Instruction& ins : c.prog.code) {
    check_instr_mods(c, ins);
    for (size_t k = 0; k < ins.src.size(); ++k) {
      std::string p = srcmod_problem(c, ins, k, dz_count);
      if (!p.empty()) c.error(ins.src[k].loc, "modifier", p);
      std::string q = swizzle_problem(c, ins, k);
      if (!q.empty()) c.error(ins.src[k].loc, "swizzle", q);
    }
  }
  if (c.ps14()) check_t_selectors(c);
}

} // namespace tierlift::assembly::detail
