// dcl and def rules: missing declarations, declaration masks, duplicates, warnings.
#include "validator_test_util.h"

using tierlift::vtest::RuleCase;

namespace {

const RuleCase kCases[] = {
    {"Vs20InputMustBeDeclared",
     "vs_2_0\ndcl_position v0\nmov oPos, v1\n",
     "declaration",
     3,
     11,
     {"v1 is used but not declared", "vs_2_0"},
     "vs_2_0\ndcl_position v1\nmov oPos, v1\n"},
    // vs_1_1 without any dcl is D3D8 style (declaration in the API); with one dcl, all count.
    {"Vs11OnceDeclaringAllMustBe",
     "vs_1_1\ndcl_position v0\nmov oPos, v0\nmov oD0, v1\n",
     "declaration",
     4,
     10,
     {"v1 is used but not declared"},
     "vs_1_1\nmov oPos, v0\nmov oD0, v1\n"},
    {"Ps20SamplerMustBeDeclared",
     "ps_2_0\ndcl t0\ntexld r0, t0, s0\nmov oC0, r0\n",
     "declaration",
     3,
     15,
     {"s0 is used but not declared", "ps_2_0"},
     "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n"},
    {"Ps20TexcoordMustBeDeclared",
     "ps_2_0\nmov r0, t1\nmov oC0, r0\n",
     "declaration",
     2,
     9,
     {"t1 is used but not declared"},
     "ps_2_0\ndcl t1\nmov r0, t1\nmov oC0, r0\n"},
    {"Ps20ReadOutsideDeclaredMask",
     "ps_2_0\ndcl t0.xy\nmov r0, t0\nmov oC0, r0\n",
     "declaration",
     3,
     9,
     {"t0.zw is read, but dcl t0.xy declares only .xy"},
     "ps_2_0\ndcl t0.xy\nmov r0.xy, t0\nmov r0.zw, c0\nmov oC0, r0\n"},
    {"DeclaredTwice",
     "vs_1_1\ndcl_position v0\ndcl_normal v0\nmov oPos, v0\n",
     "declaration",
     3,
     1,
     {"v0 is declared twice"},
     "vs_1_1\ndcl_position v0\ndcl_normal v1\nmov oPos, v0\n"},
    {"SameUsageTwice",
     "vs_1_1\ndcl_position v0\ndcl_position v1\nmov oPos, v0\nmov oD0, v1\n",
     "declaration",
     3,
     1,
     {"same usage"},
     "vs_1_1\ndcl_position v0\ndcl_color v1\nmov oPos, v0\nmov oD0, v1\n"},
    {"SamplerNeedsType",
     "ps_2_0\ndcl t0\ndcl s0\ntexld r0, t0, s0\nmov oC0, r0\n",
     "declaration",
     3,
     1,
     {"s0 needs a texture type"},
     "ps_2_0\ndcl t0\ndcl_cube s0\ntexld r0, t0, s0\nmov oC0, r0\n"},
};

TIERLIFT_RULE_SUITE(DeclarationRules, kCases);

TEST(DeclarationWarnings, DeclaredInputNeverRead) {
  EXPECT_TRUE(tierlift::vtest::has_warning("vs_2_0\ndcl_position v0\ndcl_normal v1\nmov oPos, v0\n",
                                           "unused-input", 3, 1,
                                           {"v1 is declared but never read"}));
}

TEST(DeclarationWarnings, ConstantDefinedTwiceLastWins) {
  const char* text = "ps_1_1\ndef c0, 1, 0, 0, 1\ndef c0, 0, 1, 0, 1\nmov r0, c0\n";
  EXPECT_TRUE(tierlift::vtest::only_warns(text, "definition", 3, 1,
                                          {"c0 is defined twice", "last definition"}));
}

TEST(DeclarationWarnings, Ps1xConstantOutsideClampRange) {
  EXPECT_TRUE(tierlift::vtest::has_warning("ps_1_1\ndef c0, 2, 0, 0, 1\nmov r0, c0\n", "definition",
                                           2, 1, {"clamps constants to [-1, 1]", "c0.x = 2"}));
}

TEST(DeclarationWarnings, WarningsCanBeSwitchedOff) {
  auto pr =
      tierlift::assembly::parse_text("vs_2_0\ndcl_position v0\ndcl_normal v1\nmov oPos, v0\n");
  ASSERT_TRUE(pr.program);
  tierlift::ir::DiagnosticSink sink;
  tierlift::assembly::ValidateOptions opt;
  opt.warnings = false;
  EXPECT_TRUE(tierlift::assembly::validate(*pr.program, pr.program->profile, sink, opt));
  EXPECT_EQ(sink.all().size(), 0u);
}

TEST(DeclarationRulesExtra, DclIsNotInPs1x) {
  EXPECT_TRUE(tierlift::vtest::has_error("ps_2_0\ndcl t0\nmov r0, t0\nmov oC0, r0\n",
                                         "not-in-profile", 2, 1, {"dcl is not available in ps_1_4"},
                                         tierlift::ir::Profile::ps_1_4));
}

} // namespace
