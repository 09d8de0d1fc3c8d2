// The source modifiers (-, _bias, _bx2, 1-, _x2, _dz, _dw, _abs, !) as one table: how each
// is written, what it computes, and in which order. The parser and printer read the
// spelling, the validator the names, the analytic model the affine columns, and the
// interpreter and the SPIR-V code generator apply the arithmetic through
// apply_source_modifier, one definition over the arithmetic back ends of numeric_rules.h.
//
// Order of a source read (NUMERICS.md): the pre-swizzle divide (_dz/_dw, rule 32), the
// swizzle, then the modifier's operation, then its negation.
#pragma once

#include <cstdint>
#include <iterator>
#include <string_view>

#include "tierlift/ir/numeric_rules.h"
#include "tierlift/ir/program.h"

namespace tierlift::ir {

// The arithmetic a modifier applies after the swizzle (before its negation).
enum class SrcModOp : uint8_t {
  None, // neg, _dz, _dw, ! (the divide happens before the swizzle; ! is boolean)
  Bias, // x − 0.5
  Bx2,  // 2x − 1 (signed scale)
  Comp, // 1 − x
  X2,   // 2x
  Abs,  // |x| (data movement: the sign bit only)
};

struct SrcModInfo {
  SrcMod mod;
  std::string_view prefix; // written before the register: "-", "1-", "!"
  std::string_view suffix; // written after it: "_bias", "_bx2", "_x2", "_dz", "_dw", "_abs"
  std::string_view name;   // in diagnostics: "negate (-)", "-_bias", "1-", …
  SrcModOp op;             // after the swizzle
  bool negate;             // last: the sign bit flips (data movement)
  int8_t divide_by;        // before the swizzle: x, y divided by this component (2, 3), or -1
  // The whole modifier as scale·x + bias, for readers that reason about affine maps (the
  // analytic model); false for _abs, _dz, _dw and !, which are not affine.
  bool affine;
  float scale, bias;
};

// Row i is SrcMod i (the bytecode numbering).
inline constexpr SrcModInfo kSrcMods[] = {
    // mod, prefix, suffix, name, op, negate, divide_by, affine, scale, bias
    {SrcMod::None, "", "", "none", SrcModOp::None, false, -1, true, 1, 0},
    {SrcMod::Neg, "-", "", "negate (-)", SrcModOp::None, true, -1, true, -1, 0},
    {SrcMod::Bias, "", "_bias", "_bias", SrcModOp::Bias, false, -1, true, 1, -0.5f},
    {SrcMod::BiasNeg, "-", "_bias", "-_bias", SrcModOp::Bias, true, -1, true, -1, 0.5f},
    {SrcMod::Bx2, "", "_bx2", "_bx2", SrcModOp::Bx2, false, -1, true, 2, -1},
    {SrcMod::Bx2Neg, "-", "_bx2", "-_bx2", SrcModOp::Bx2, true, -1, true, -2, 1},
    {SrcMod::Comp, "1-", "", "1-", SrcModOp::Comp, false, -1, true, -1, 1},
    {SrcMod::X2, "", "_x2", "_x2", SrcModOp::X2, false, -1, true, 2, 0},
    {SrcMod::X2Neg, "-", "_x2", "-_x2", SrcModOp::X2, true, -1, true, -2, 0},
    {SrcMod::Dz, "", "_dz", "_dz", SrcModOp::None, false, 2, false, 1, 0},
    {SrcMod::Dw, "", "_dw", "_dw", SrcModOp::None, false, 3, false, 1, 0},
    {SrcMod::Abs, "", "_abs", "_abs", SrcModOp::Abs, false, -1, false, 1, 0},
    {SrcMod::AbsNeg, "-", "_abs", "-_abs", SrcModOp::Abs, true, -1, false, 1, 0},
    {SrcMod::Not, "!", "", "!", SrcModOp::None, false, -1, false, 1, 0},
};
static_assert(std::size(kSrcMods) == static_cast<size_t>(SrcMod::Not) + 1);
// Row i describes SrcMod i (the bytecode numbering), so src_mod_info is one index.
constexpr bool src_mod_rows_in_order() {
  for (size_t i = 0; i < std::size(kSrcMods); ++i)
    if (static_cast<size_t>(kSrcMods[i].mod) != i) return false;
  return true;
}
static_assert(src_mod_rows_in_order());

constexpr const SrcModInfo& src_mod_info(SrcMod m) {
  const auto i = static_cast<size_t>(m);
  return kSrcMods[i < std::size(kSrcMods) ? i : 0];
}

// The modifier's operation and negation on one value (a lane or a vector), after the
// swizzle. Each operation is a rule of numeric_rules.h; neg and abs move bits only.
template <class A, class V = typename A::V> V apply_source_modifier(const A& a, SrcMod m, V x) {
  const SrcModInfo& info = src_mod_info(m);
  switch (info.op) {
  case SrcModOp::None: break;
  case SrcModOp::Bias: x = numerics::rule::bias(a, x); break;
  case SrcModOp::Bx2: x = numerics::rule::bx2(a, x); break;
  case SrcModOp::Comp: x = numerics::rule::comp(a, x); break;
  case SrcModOp::X2: x = numerics::rule::x2(a, x); break;
  case SrcModOp::Abs: x = a.abs(x); break;
  }
  return info.negate ? a.neg(x) : x;
}

} // namespace tierlift::ir
