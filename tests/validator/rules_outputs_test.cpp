// Output-register rules.
#include "validator_test_util.h"

using tierlift::vtest::RuleCase;

namespace {

const RuleCase kCases[] = {
    {"VertexShaderWritesPosition",
     "vs_1_1\nmov oD0, v0\n",
     "output-rule",
     1,
     1,
     {"oPos is never written"},
     "vs_1_1\nmov oPos, v0\nmov oD0, v0\n"},
    {"TexcoordMaskFromX",
     "vs_1_1\nmov oPos, v0\nmov oT0.y, v0\n",
     "output-rule",
     3,
     5,
     {"oT0 together must be .x, .xy, .xyz or .xyzw; they are .y"},
     "vs_1_1\nmov oPos, v0\nmov oT0.x, v0\nmov oT0.y, v0\n"},
    {"Ps20WritesOC0",
     "ps_2_0\nmov oC1, c0\n",
     "output-rule",
     1,
     1,
     {"oC0 is never written"},
     "ps_2_0\nmov oC0, c0\nmov oC1, c0\n"},
    {"ColourOutputOnce",
     "ps_2_0\nmov oC0, c0\nmov oC0, c1\n",
     "output-rule",
     3,
     1,
     {"oC0 may be written once; it was written at line 2"},
     "ps_2_0\nmov oC0, c0\n"},
    {"ColourOutputByMovOnly",
     "ps_2_0\nadd oC0, c0, c1\n",
     "output-rule",
     2,
     1,
     {"oC0 can only be written by mov, not add"},
     "ps_2_0\nadd r0, c0, c1\nmov oC0, r0\n"},
    {"ColourOutputNoSwizzle",
     "ps_2_0\nmov oC0, c0.x\n",
     "output-rule",
     2,
     10,
     {"a mov to oC0 takes no swizzle"},
     "ps_2_0\nmov r0, c0.x\nmov oC0, r0\n"},
    {"ColourOutputNoSourceModifier",
     "ps_2_0\nmov oC0, -c0\n",
     "output-rule",
     2,
     10,
     {"a mov to oC0 takes no source modifier"},
     "ps_2_0\nmov r0, -c0\nmov oC0, r0\n"},
    {"ColourOutputNoSat",
     "ps_2_0\nmov_sat oC0, c0\n",
     "output-rule",
     2,
     1,
     {"_sat is not allowed on a write to oC0"},
     "ps_2_0\nmov_sat r0, c0\nmov oC0, r0\n"},
    {"ColourOutputsInOrder",
     "ps_2_0\nmov oC0, c0\nmov oC2, c0\n",
     "output-rule",
     3,
     5,
     {"oC2 is written, so every oC below it must be written too; oC1 is not"},
     "ps_2_0\nmov oC0, c0\nmov oC2, c0\nmov oC1, c1\n"},
    {"DepthNeedsReplicate",
     "ps_2_0\nmov oC0, c0\nmov oDepth, c0\n",
     "output-rule",
     3,
     13,
     {"oDepth needs a replicate-swizzled source"},
     "ps_2_0\nmov oC0, c0\nmov oDepth, c0.z\n"},
    {"DepthOnce",
     "ps_2_0\nmov oC0, c0\nmov oDepth, c0.z\nmov oDepth, c0.w\n",
     "output-rule",
     4,
     1,
     {"oDepth may be written once"},
     "ps_2_0\nmov oC0, c0\nmov oDepth, c0.w\n"},
};

TIERLIFT_RULE_SUITE(OutputRules, kCases);

// Which oT# a vertex shader writes is its own business: Direct3D hands oTn to the pixel
// shader's texture coordinate n by number, and fxc writes oT1 alone for a shader whose only
// coordinate output is TEXCOORD1 (docs/d3d9-rules.md §3.1). tierlift used to demand oT0..oT(n-1)
// with oTn; these are the listings it refused.
TEST(OutputRulesTaken, TexcoordsNeedNotStartAtZero) {
  using tierlift::vtest::is_clean;
  EXPECT_TRUE(is_clean("vs_1_1\ndcl_position v0\nmov oPos, v0\nmov oT1, v0\n"));
  EXPECT_TRUE(is_clean("vs_1_1\ndcl_position v0\nm4x4 oPos, v0, c0\nmov oT3.xy, v0\n"
                       "mov oT7, v0\n"));
  EXPECT_TRUE(is_clean("vs_2_0\ndcl_position v0\ndcl_texcoord1 v1\nm4x4 oPos, v0, c0\n"
                       "mov oT1.xy, v1\n"));
  // The mask rule of each oT# still holds.
  EXPECT_TRUE(tierlift::vtest::has_error("vs_1_1\ndcl_position v0\nmov oPos, v0\nmov oT2.y, v0\n",
                                         "output-rule", 4, 5, {"oT2 together must be .x, .xy"}));
}

TEST(OutputWarnings, Ps1xR0NeverWritten) {
  const char* text = "ps_1_1\nmov r1, v0\n";
  EXPECT_TRUE(tierlift::vtest::only_warns(text, "output-rule", 1, 1,
                                          {"r0 is the output colour of ps_1_1"}));
}

} // namespace
