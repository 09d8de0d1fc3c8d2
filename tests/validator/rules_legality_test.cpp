// Operand kinds from the opcode table, and source positions that carry no data.
#include <tuple>

#include "validator_test_util.h"

using tierlift::vtest::RuleCase;

namespace {

const RuleCase kCases[] = {
    {"IfTakesBool",
     "vs_2_0\ndcl_position v0\nif c0\nendif\nmov oPos, v0\n",
     "operand-kind",
     3,
     4,
     {"source 1 of if must be a boolean constant b#, not c0"},
     "vs_2_0\ndcl_position v0\nif b0\nendif\nmov oPos, v0\n"},
    {"RepTakesInt",
     "vs_2_0\ndcl_position v0\nrep b0\nendrep\nmov oPos, v0\n",
     "operand-kind",
     3,
     5,
     {"source 1 of rep must be an integer constant i#, not b0"},
     "vs_2_0\ndcl_position v0\nrep i0\nendrep\nmov oPos, v0\n"},
    {"CallTakesLabel",
     "vs_2_0\ndcl_position v0\ncall r0\nmov oPos, v0\n",
     "operand-kind",
     3,
     6,
     {"source 1 of call must be a label l#, not r0"},
     "vs_2_0\ndcl_position v0\ncall l0\nmov oPos, v0\nret\nlabel l0\nret\n"},
    {"LoopTakesLoopCounter",
     "vs_2_0\ndcl_position v0\nloop i0, i0\nendloop\nmov oPos, v0\n",
     "operand-kind",
     3,
     6,
     {"source 1 of loop must be the loop counter aL, not i0"},
     "vs_2_0\ndcl_position v0\nloop aL, i0\nendloop\nmov oPos, v0\n"},
    {"TexM3x3SpecTakesConst",
     "ps_1_1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, t1\nmov r0, t3\n",
     "operand-kind",
     5,
     21,
     {"source 2 of texm3x3spec must be a float constant c#, not t1"},
     "ps_1_1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c0\nmov r0, t3\n"},
    {"NotOnlyOnCallnz",
     "vs_2_0\ndcl_position v0\nif !b0\nendif\nmov oPos, v0\n",
     "modifier",
     3,
     4,
     {"! (boolean not) is only allowed on callnz's b#"},
     "vs_2_0\ndcl_position v0\ncallnz l0, !b0\nmov oPos, v0\nret\nlabel l0\nret\n"},
    {"A0OnlyAsRelativeIndex",
     "vs_1_1\nmov a0.x, v0\nmov oPos, a0\n",
     "register-access",
     3,
     11,
     {"a0 can only be read as a relative index"},
     "vs_1_1\nmov a0.x, v0\nmov oPos, c[a0.x]\n"},
};

TIERLIFT_RULE_SUITE(OperandKindRules, kCases);

// A wrong register in a label position is one error, not three.
TEST(OperandKindRulesExtra, NoFollowUpErrors) {
  EXPECT_TRUE(tierlift::vtest::has_errors("vs_2_0\ndcl_position v0\ncall r0\nmov oPos, v0\n", 1));
}

} // namespace

namespace {

// All problems of one listing come back in one run, in source order.
TEST(ValidatorReport, AllErrorsInSourceOrder) {
  auto r = tierlift::vtest::run(
      "ps_1_3\ntex t0\nmov r0, t0\ntex t1\nmul_x8 r0.xy, t0.x, c9\n+add r1.a, t1, t1\n");
  ASSERT_TRUE(r.parsed.program);
  const auto& all = r.diags.all();
  // order (4:1), modifier (5:1), write-mask (5:8), swizzle (5:15), register-range (5:21),
  // coissue (6:2): counted by hand from the listing.
  ASSERT_GE(all.size(), 6u) << tierlift::vtest::dump(r);
  for (size_t i = 1; i < all.size(); ++i) {
    EXPECT_TRUE(std::tie(all[i - 1].loc.line, all[i - 1].loc.col) <=
                std::tie(all[i].loc.line, all[i].loc.col))
        << tierlift::vtest::dump(r);
  }
  EXPECT_EQ(all.front().rule, "order");
  EXPECT_EQ(all.back().rule, "coissue");
}

} // namespace
