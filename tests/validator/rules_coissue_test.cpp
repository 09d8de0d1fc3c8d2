// Co-issue legality.
#include "validator_test_util.h"

using tierlift::vtest::RuleCase;

namespace {

const RuleCase kCases[] = {
    {"OnlyInPs1x",
     "ps_2_0\nmov r0.rgb, c0\n+mov r0.a, c1\nmov oC0, r0\n",
     "coissue",
     3,
     2,
     {"co-issue (+) exists only in ps_1_1..ps_1_4, not in ps_2_0"},
     "ps_2_0\nmov r0.rgb, c0\nmov r0.a, c1\nmov oC0, r0\n"},
    {"NeedsAPartner",
     "ps_1_1\n+mov r0.a, v0\n",
     "coissue",
     2,
     2,
     {"must follow the instruction it pairs with"},
     "ps_1_1\nmov r0.rgb, v0\n+mov r0.a, v0\n"},
    {"ColourAndAlphaHalves",
     "ps_1_1\nmov r0.rgb, v0\n+mov r0.rgb, v1\n",
     "coissue",
     3,
     2,
     {"one half writing .rgb and the other .a", "these write .xyz and .xyz"},
     "ps_1_1\nmov r0.rgb, v0\n+mov r0.a, v1\n"},
    {"Ps14ColourHalfMayBeASubset",
     "ps_1_4\nmov r0, v0\nmov r1.rg, v0\n+mov r1.rgba, v1\n",
     "coissue",
     4,
     2,
     {"colour components (.rgb or a subset)"},
     "ps_1_4\nmov r0.b, v0\nmov r0.rg, v0\n+mov r0.a, v1\n"},
    {"NoDp4",
     "ps_1_2\nmov r0, v0\ndp4 r1.rgb, v0, v1\n+mov r1.a, v0\n",
     "coissue",
     3,
     1,
     {"dp4 cannot be co-issued"},
     "ps_1_2\nmov r0, v0\ndp3 r1.rgb, v0, v1\n+mov r1.a, v0\n"},
    {"NoTextureInstruction",
     "ps_1_1\ntex t0\n+tex t1\nmov r0, t0\n",
     "coissue",
     3,
     2,
     {"tex cannot be co-issued"},
     "ps_1_1\ntex t0\ntex t1\nmov r0, t0\n"},
    {"Dp3OnlyInColourHalf",
     "ps_1_4\nmov r0.rgb, v0\n+dp3 r0.a, v0, v1\n",
     "coissue",
     3,
     2,
     {"dp3 runs in the colour pipe"},
     "ps_1_4\ndp3 r0.rgb, v0, v1\n+mov r0.a, v0\n"},
    {"NoBem",
     "ps_1_4\ntexld r1, t0\ntexld r2, t1\nbem r3.rg, r1, r2\n+mov r3.a, r1\nphase\ntexld r0, r3\n",
     "coissue",
     4,
     1,
     {"bem cannot be co-issued"},
     "ps_1_4\ntexld r1, t0\ntexld r2, t1\nbem r2.rg, r1, r2\nphase\ntexld r0, r2\n"},
};

TIERLIFT_RULE_SUITE(CoissueRules, kCases);

} // namespace
