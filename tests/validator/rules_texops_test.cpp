// ps_1_1–1_3 texture-instruction rules.
#include "validator_test_util.h"

using tierlift::vtest::RuleCase;

namespace {

const RuleCase kCases[] = {
    {"SourceBeforeDestination",
     "ps_1_1\ntex t1\ntexbem t0, t1\nmov r0, t0\n",
     "texture-op",
     3,
     12,
     {"must be a lower-numbered t# than the destination (m > n)"},
     "ps_1_1\ntex t0\ntexbem t1, t0\nmov r0, t1\n"},
    {"M3x2PadNeedsFinalRow",
     "ps_1_1\ntex t0\ntexm3x2pad t1, t0\nmov r0, t0\n",
     "texture-op",
     3,
     1,
     {"texm3x2pad t1 must be followed by texm3x2tex or texm3x2depth t2"},
     "ps_1_1\ntex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\nmov r0, t2\n"},
    {"M3x2TexNeedsPad",
     "ps_1_1\ntex t0\ntexm3x2tex t2, t0\nmov r0, t2\n",
     "texture-op",
     3,
     1,
     {"texm3x2tex t2 must directly follow texm3x2pad t1"},
     "ps_1_3\ntex t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\nmov r0, t0\n"},
    {"M3x3NeedsTwoPads",
     "ps_1_1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3tex t3, t0\nmov r0, t3\n",
     "texture-op",
     4,
     1,
     {"texm3x3tex t3 must directly follow texm3x3pad t1 and texm3x3pad t2"},
     "ps_1_1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3tex t3, t0\nmov r0, t3\n"},
    {"M3x2RowsShareTheSource",
     "ps_1_1\ntex t0\ntex t1\ntexm3x2pad t2, t0\ntexm3x2tex t3, t1\nmov r0, t3\n",
     "texture-op",
     4,
     1,
     {"with the same source"},
     "ps_1_1\ntex t0\ntex t1\ntexm3x2pad t2, t1\ntexm3x2tex t3, t1\nmov r0, t3\n"},
    {"BumpSourceOnlyReadByBump",
     "ps_1_1\ntex t0\ntexbem t1, t0\nmov r0, t0\n",
     "texture-op",
     4,
     9,
     {"t0 was read by texbem/texbeml"},
     "ps_1_1\ntex t0\ntexbem t1, t0\ntexbeml t2, t0\nmul r0, t1, t2\n"},
};

TIERLIFT_RULE_SUITE(TextureOpRules, kCases);

} // namespace
