// Reads of never-written registers, component by component; dependent-read depth.
#include "validator_test_util.h"

using tierlift::vtest::RuleCase;

namespace {

const RuleCase kCases[] = {
    {"TempComponentsReadBeforeWritten",
     "vs_1_1\nmov r1.x, v0\nadd oPos, r1, v0\n",
     "read-before-write",
     3,
     11,
     {"r1.yzw is read before it is written"},
     "vs_1_1\nmov r1.x, v0\nadd oPos, r1.x, v0\n"},
    // dp3 reads .xyz only, dp4 all four.
    {"Dp4ReadsW",
     "vs_1_1\nmov r1.xyz, v0\ndp4 oPos, r1, r1\n",
     "read-before-write",
     3,
     11,
     {"r1.w is read before it is written"},
     "vs_1_1\nmov r1.xyz, v0\ndp3 oPos, r1, r1\n"},
    // A per-component operation reads only the components its mask writes.
    {"MaskLimitsReads",
     "vs_1_1\nmov r1.xy, v0\nadd oPos.xyz, r1, v0\nmov oPos.w, v0\n",
     "read-before-write",
     3,
     15,
     {"r1.z is read before it is written"},
     "vs_1_1\nmov r1.xy, v0\nadd oPos.xy, r1, v0\nmov oPos.zw, v0\n"},
    // Both halves of a pair read before either writes.
    {"CoissuedHalvesReadFirst",
     "ps_1_4\nmov r1.rgb, v0\n+mov r1.a, r1.r\nmov r0, r1\n",
     "read-before-write",
     3,
     12,
     {"r1.x is read before it is written"},
     "ps_1_4\nmov r1.rgb, v0\n+mov r1.a, v0.r\nmov r0, r1\n"},
    {"PhaseDropsAlpha",
     "ps_1_4\ntexld r1, t0\nphase\nmov r0, r1\n",
     "read-before-write",
     4,
     9,
     {"r1.w is read before it is written", "alpha"},
     "ps_1_4\ntexld r1, t0\nphase\nmov r0.rgb, r1\n+mov r0.a, v0\n"},
    {"AddressRegisterBeforeUse",
     "vs_1_1\nmov oPos, c[a0.x + 1]\n",
     "read-before-write",
     2,
     13,
     {"a0.x is read before it is written"},
     "vs_1_1\nmov a0.x, v0.x\nmov oPos, c[a0.x + 1]\n"},
    {"Ps11TextureRegisterBeforeTex",
     "ps_1_1\nmov r0, t0\n",
     "read-before-write",
     2,
     9,
     {"t0.xyzw is read before it is written"},
     "ps_1_1\ntex t0\nmov r0, t0\n"},
    {"TexdepthConsumesR5",
     "ps_1_4\ntexcrd r5.rgb, t0\nphase\ntexdepth r5\nmov r0, r5\n",
     "read-before-write",
     5,
     9,
     {"r5.xyzw is read before it is written", "texdepth left it unusable"},
     "ps_1_4\ntexcrd r5.rgb, t0\nphase\ntexdepth r5\nmov r0, c0\n"},
    // A 2D sampler reads .xy of the coordinate register, a cube map .xyz.
    {"SamplerDimensionDecidesComponents",
     "ps_2_0\ndcl t0\ndcl_cube s0\nmov r2.xy, t0\ntexld r0, r2, s0\nmov oC0, r0\n",
     "read-before-write",
     5,
     11,
     {"r2.z is read before it is written"},
     "ps_2_0\ndcl t0\ndcl_2d s0\nmov r2.xy, t0\ntexld r0, r2, s0\nmov oC0, r0\n"},
    {"CallBringsInSubroutineWrites",
     "vs_2_0\ndcl_position v0\nmov oPos, r0\ncall l0\nret\nlabel l0\nmov r0, v0\nret\n",
     "read-before-write",
     3,
     11,
     {"r0.xyzw is read before it is written"},
     "vs_2_0\ndcl_position v0\ncall l0\nmov oPos, r0\nret\nlabel l0\nmov r0, v0\nret\n"},
    {"Ps20DependentReadDepth",
     "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\ntexld r0, r0, s0\ntexld r0, r0, s0\n"
     "texld r0, r0, s0\ntexld r0, r0, s0\nmov oC0, r0\n",
     "dependent-read",
     8,
     1,
     {"ps_2_0 allows 4 levels of dependent texture reads"},
     "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\ntexld r0, r0, s0\ntexld r0, r0, s0\n"
     "texld r0, r0, s0\nmov oC0, r0\n"},
};

TIERLIFT_RULE_SUITE(DataflowRules, kCases);

// Every missing component is reported, and every error of a listing in one run.
TEST(DataflowRulesExtra, AllErrorsInOneRun) {
  EXPECT_TRUE(tierlift::vtest::has_errors("vs_1_1\nadd r0, r1, r2\nmov oPos, r3\n", 3));
}

} // namespace
