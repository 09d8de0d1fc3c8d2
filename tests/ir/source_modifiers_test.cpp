// The source-modifier table and the rule templates on fp32: each modifier's spelling and
// value against hand-computed results, and the rules a back end can only
// get right by running the operations in the documented order.
#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <string>

#include "tierlift/ir/numerics.h"
#include "tierlift/ir/source_modifiers.h"

using namespace tierlift::ir;
namespace num = tierlift::ir::numerics;

namespace {
std::string spelled(SrcMod m) {
  const SrcModInfo& i = src_mod_info(m);
  return std::string(i.prefix) + "r0" + std::string(i.suffix);
}
float modified(SrcMod m, float x) {
  return apply_source_modifier(num::FloatArith<num::kKeep>{}, m, x);
}
} // namespace

TEST(SourceModifiers, SpellingOfEachModifier) {
  EXPECT_EQ(spelled(SrcMod::None), "r0");
  EXPECT_EQ(spelled(SrcMod::Neg), "-r0");
  EXPECT_EQ(spelled(SrcMod::Bias), "r0_bias");
  EXPECT_EQ(spelled(SrcMod::BiasNeg), "-r0_bias");
  EXPECT_EQ(spelled(SrcMod::Bx2), "r0_bx2");
  EXPECT_EQ(spelled(SrcMod::Bx2Neg), "-r0_bx2");
  EXPECT_EQ(spelled(SrcMod::Comp), "1-r0");
  EXPECT_EQ(spelled(SrcMod::X2), "r0_x2");
  EXPECT_EQ(spelled(SrcMod::X2Neg), "-r0_x2");
  EXPECT_EQ(spelled(SrcMod::Dz), "r0_dz");
  EXPECT_EQ(spelled(SrcMod::Dw), "r0_dw");
  EXPECT_EQ(spelled(SrcMod::Abs), "r0_abs");
  EXPECT_EQ(spelled(SrcMod::AbsNeg), "-r0_abs");
  EXPECT_EQ(spelled(SrcMod::Not), "!r0");
  EXPECT_EQ(src_mod_info(SrcMod::Neg).name, "negate (-)");
}

TEST(SourceModifiers, ValueOfEachModifier) {
  EXPECT_EQ(modified(SrcMod::None, 0.75f), 0.75f);
  EXPECT_EQ(modified(SrcMod::Neg, 0.75f), -0.75f);
  EXPECT_EQ(modified(SrcMod::Bias, 0.75f), 0.25f);     // x − 0.5
  EXPECT_EQ(modified(SrcMod::BiasNeg, 0.75f), -0.25f); // −(x − 0.5)
  EXPECT_EQ(modified(SrcMod::Bx2, 0.75f), 0.5f);       // 2x − 1
  EXPECT_EQ(modified(SrcMod::Bx2Neg, 0.75f), -0.5f);
  EXPECT_EQ(modified(SrcMod::Comp, 0.75f), 0.25f); // 1 − x
  EXPECT_EQ(modified(SrcMod::X2, 0.75f), 1.5f);
  EXPECT_EQ(modified(SrcMod::X2Neg, 0.75f), -1.5f);
  EXPECT_EQ(modified(SrcMod::Abs, -0.75f), 0.75f);
  EXPECT_EQ(modified(SrcMod::AbsNeg, 0.75f), -0.75f);
  // _dz/_dw divide before the swizzle and ! is boolean: nothing after the swizzle.
  EXPECT_EQ(modified(SrcMod::Dz, 0.75f), 0.75f);
  EXPECT_EQ(modified(SrcMod::Dw, 0.75f), 0.75f);
  EXPECT_EQ(modified(SrcMod::Not, 0.75f), 0.75f);
  EXPECT_EQ(src_mod_info(SrcMod::Dz).divide_by, 2);
  EXPECT_EQ(src_mod_info(SrcMod::Dw).divide_by, 3);
}

TEST(SourceModifiers, AffineColumnsAgreeWithTheArithmetic) {
  int affine = 0;
  for (const SrcModInfo& m : kSrcMods) {
    if (!m.affine) continue;
    ++affine;
    for (float x : {0.75f, -0.25f, 3.0f})
      EXPECT_EQ(m.scale * x + m.bias, modified(m.mod, x)) << m.name; // exact in fp32
  }
  EXPECT_EQ(affine, 9); // all but _dz, _dw, _abs, -_abs and !
}

TEST(SourceModifiers, NegateAndAbsMoveBitsOnly) {
  // A NaN keeps its payload; only the sign bit changes (NUMERICS.md rule 13: data movement).
  const float nan = std::bit_cast<float>(0x7FC01234u);
  EXPECT_EQ(std::bit_cast<uint32_t>(modified(SrcMod::Neg, nan)), 0xFFC01234u);
  EXPECT_EQ(std::bit_cast<uint32_t>(modified(SrcMod::AbsNeg, nan)), 0xFFC01234u);
  // Under Flush a denormal still negates to a denormal, while _x2 (arithmetic) flushes it.
  const float tiny = 1e-40f;
  const auto flush = num::FloatArith<num::kFlush>{};
  EXPECT_EQ(apply_source_modifier(flush, SrcMod::Neg, tiny), -tiny);
  EXPECT_EQ(std::bit_cast<uint32_t>(apply_source_modifier(flush, SrcMod::X2, tiny)), 0u);
  EXPECT_EQ(modified(SrcMod::X2, tiny), std::ldexp(tiny, 1)); // kept: exact doubling
}

TEST(NumericRules, ProjectDivideOnBothSides) {
  const auto a = num::FloatArith<num::kKeep>{};
  float x = 3.0f, y = -1.0f;
  num::rule::project_divide(a, x, y, 2.0f);
  EXPECT_EQ(x, 1.5f);
  EXPECT_EQ(y, -0.5f);
  x = 3.0f, y = -1.0f;
  num::rule::project_divide(a, x, y, -0.0f); // rule 32: a zero divisor gives 1.0
  EXPECT_EQ(x, 1.0f);
  EXPECT_EQ(y, 1.0f);
}

TEST(NumericRules, MovaAndIndexRange) {
  const auto a = num::FloatArith<num::kKeep>{};
  EXPECT_EQ(num::rule::mova_round(a, 2.5f), 3.0f); // ties away from zero
  EXPECT_EQ(num::rule::mova_round(a, -2.5f), -3.0f);
  EXPECT_EQ(num::rule::mova_round(a, -2.49f), -2.0f);
  EXPECT_EQ(num::rule::index_range(a, std::nanf("")), 0.0f);
  EXPECT_EQ(num::rule::index_range(a, 1e30f), 1048576.0f);
  EXPECT_EQ(num::rule::index_range(a, -1e30f), -1048576.0f);
}

TEST(NumericRules, BumpOffsetSumsInOrder) {
  // base + m_r·r + m_g·g, left to right: (2^24 + 1) + 1 rounds twice back to 2^24 (ties to
  // even), where adding the two products first would give 2^24 + 2.
  const auto a = num::FloatArith<num::kKeep>{};
  const float big = 16777216.0f; // 2^24: adding 1 is a tie that rounds to even
  EXPECT_EQ(num::rule::bump_offset(a, big, 1.0f, 1.0f, 1.0f, 1.0f), big);
  EXPECT_EQ(num::rule::bump_luminance(a, 0.5f, 4.0f, -3.0f), -1.0f); // not clamped to [0, 1]
}
