// THE opcode table: one row per instruction shape of the eleven profiles. The parser,
// validator, printer, bytecode reader/writer, interpreter and code generator all read it.
// A mnemonic whose operand shape differs by profile has one row per shape (texld in ps_1_4
// takes one source, in ps_2_0 two); find_opcode() picks the row legal in a profile.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "tierlift/ir/profile.h"

namespace tierlift::ir {

// clang-format off
enum class Opcode : uint8_t {
  // arithmetic (shared)
  Nop, Mov, Add, Sub, Mad, Mul, Rcp, Rsq, Dp3, Dp4, Min, Max, Slt, Sge, Exp, Log, Lit, Dst,
  Lrp, Frc, M4x4, M4x3, M3x4, M3x3, M3x2, Pow, Crs, Sgn, Abs, Nrm, SinCos, Mova, Expp, Logp,
  // pixel arithmetic
  Cnd, Cmp, Bem, Dp2Add,
  // flow control (vs_2_0) and phase (ps_1_4)
  Call, CallNz, Loop, Ret, EndLoop, Label, Rep, EndRep, If, Else, EndIf, Phase,
  // texture instructions
  Tex, TexLd14, TexLd, TexLdP, TexLdB, TexCoord, TexCrd, TexKill, TexBem, TexBemL, TexReg2Ar,
  TexReg2Gb, TexReg2Rgb, TexM3x2Pad, TexM3x2Tex, TexM3x2Depth, TexM3x3Pad, TexM3x3Tex,
  TexM3x3, TexM3x3Spec, TexM3x3VSpec, TexDp3, TexDp3Tex, TexDepth,
  // declarations and definitions (kept in Program::decls / Program::defs, not in code)
  Dcl, Def, DefI, DefB,
  // shader models 2.x and 3.0. A comparison is part of the row (bytecode control field
  // gt 1, eq 2, ge 3, lt 4, ne 5, le 6: OpInfo::control), one row per mnemonic as written.
  SinCos3, Break, BreakGt, BreakEq, BreakGe, BreakLt, BreakNe, BreakLe, BreakP,
  IfGt, IfEq, IfGe, IfLt, IfNe, IfLe, SetpGt, SetpEq, SetpGe, SetpLt, SetpNe, SetpLe,
  TexLdL, TexLdD, Dsx, Dsy,
  Count
};
// clang-format on
inline constexpr int kOpcodeCount = static_cast<int>(Opcode::Count);

enum class OpClass : uint8_t {
  Arith,   // counts arithmetic slots
  Texture, // counts texture slots in pixel profiles
  Flow,    // vs_2_0 static flow control, ps_1_4 phase
  Decl,    // dcl, def, defi, defb: no slots
};

// What a source operand position expects.
enum class OperandKind : uint8_t {
  None,
  Vector,    // any readable register, swizzle allowed
  Scalar,    // replicate swizzle needed; bare rcp/rsq text reads .x, a bare token .w (leniency)
  Matrix,    // base register of a matrix macro: no swizzle, no negate
  Sampler,   // s#
  Bool,      // b# (optionally !b# for callnz)
  Int,       // i#
  Label,     // l#
  LoopReg,   // aL
  Const,     // c# only (sincos constants, texm3x3spec eye vector)
  Temp,      // r# only (sgn scratch registers)
  Predicate, // p0 (breakp); if and callnz also take p0 where their row says Bool
};

struct OpInfo {
  Opcode op;
  std::string_view mnemonic;
  uint16_t code;   // bytecode opcode (bits 0–15 of the instruction token)
  uint8_t control; // bits 16–23 (texld: 0 plain, 1 texldp, 2 texldb)
  OpClass cls;
  bool has_dst; // texkill's operand is a destination token in bytecode
  uint8_t num_src;
  std::array<OperandKind, 4> src;
  // Slot cost per profile (index = profile_index), -1 where the row is not legal. For
  // OpClass::Texture rows the cost counts texture slots; extra_arith adds arithmetic slots
  // (texbeml costs one of each).
  std::array<int8_t, kProfileCount> slots;
  uint8_t extra_arith;
  std::string_view summary; // one line for --help and docs
};

std::span<const OpInfo> opcode_table();
const OpInfo& op_info(Opcode op);

inline bool legal_in(const OpInfo& info, Profile p) {
  return info.slots[profile_index(p)] >= 0;
}

// The row for a mnemonic in a profile. When no row is legal in that profile, returns the
// first row with that mnemonic (so the validator can say "not legal in ps_1_1"), and
// nullptr when the mnemonic is unknown.
const OpInfo* find_opcode(std::string_view mnemonic, Profile p);
// Every row with the mnemonic (for diagnostics listing the profiles where it is legal).
std::span<const OpInfo* const> rows_for_mnemonic(std::string_view mnemonic);
// Bytecode lookup: opcode + control field + profile → row.
const OpInfo* find_opcode_by_code(uint16_t code, uint8_t control, Profile p);

} // namespace tierlift::ir
