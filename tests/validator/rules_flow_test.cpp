// vs_2_0 static flow control.
#include "validator_test_util.h"

using tierlift::vtest::has_error;
using tierlift::vtest::is_clean;
using tierlift::vtest::repeat;
using tierlift::vtest::RuleCase;

namespace {

const RuleCase kCases[] = {
    {"IfNeedsEndif",
     "vs_2_0\ndcl_position v0\ndefb b0, true\nif b0\nmov oPos, v0\n",
     "flow",
     4,
     1,
     {"if is never closed by endif"},
     "vs_2_0\ndcl_position v0\ndefb b0, true\nif b0\nmov oPos, v0\nelse\nmov oPos, -v0\nendif\n"},
    {"ElseNeedsIf",
     "vs_2_0\ndcl_position v0\nmov oPos, v0\nelse\n",
     "flow",
     4,
     1,
     {"else without a matching if"},
     "vs_2_0\ndcl_position v0\nif b0\nmov oPos, v0\nelse\nmov oPos, v0\nendif\n"},
    {"BlocksNestProperly",
     "vs_2_0\ndcl_position v0\ndefi i0, 2, 0, 1, 0\nloop aL, i0\nif b0\nendloop\nendif\n"
     "mov oPos, v0\n",
     "flow",
     6,
     1,
     {"endloop does not match", "the innermost open block is if at line 5"},
     "vs_2_0\ndcl_position v0\ndefi i0, 2, 0, 1, 0\nloop aL, i0\nif b0\nendif\nendloop\n"
     "mov oPos, v0\n"},
    {"LoopNestingDepthOne",
     "vs_2_0\ndcl_position v0\ndefi i0, 2, 0, 1, 0\nrep i0\nrep i0\nendrep\nendrep\nmov oPos, v0\n",
     "flow",
     5,
     1,
     {"vs_2_0 allows loop/rep nesting depth 1"},
     "vs_2_0\ndcl_position v0\ndefi i0, 2, 0, 1, 0\nrep i0\nendrep\nrep i0\nendrep\nmov oPos, "
     "v0\n"},
    {"NoNestedCalls",
     "vs_2_0\ndcl_position v0\ncall l0\nmov oPos, v0\nret\nlabel l0\ncall l1\nret\nlabel l1\nret\n",
     "flow",
     7,
     1,
     {"call nesting depth 1"},
     "vs_2_0\ndcl_position v0\ncall l0\ncall l1\nmov oPos, v0\nret\nlabel l0\nret\nlabel "
     "l1\nret\n"},
    {"LabelFollowsRet",
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l0\nlabel l0\nret\n",
     "flow",
     5,
     1,
     {"label must directly follow a ret"},
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l0\nret\nlabel l0\nret\n"},
    {"LabelRange",
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l16\nret\nlabel l16\nret\n",
     "register-range",
     4,
     6,
     {"l16 is out of range: vs_2_0 has l0..l15"},
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l15\nret\nlabel l15\nret\n"},
    {"ForwardCallsOnly",
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l1\nret\nlabel l0\nret\nlabel l1\ncall l0\nret\n",
     "flow",
     9,
     6,
     {"only allows forward calls: label l0 is at line 6"},
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l1\ncall l0\nret\nlabel l0\nret\nlabel "
     "l1\nret\n"},
    {"CalledLabelExists",
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l3\nret\n",
     "flow",
     4,
     6,
     {"label l3 is not defined"},
     "vs_2_0\ndcl_position v0\nmov oPos, v0\ncall l3\nret\nlabel l3\nret\n"},
    {"LoopCounterOnlyInsideLoop",
     "vs_2_0\ndcl_position v0\nmov oPos, c[aL + 1]\n",
     "flow",
     3,
     1,
     {"aL is only valid inside a loop"},
     "vs_2_0\ndcl_position v0\ndefi i0, 2, 0, 1, 0\nloop aL, i0\nmov r0, c[aL + 1]\nendloop\n"
     "mov oPos, v0\n"},
    {"NothingAfterMainRet",
     "vs_2_0\ndcl_position v0\nmov oPos, v0\nret\nmov oD0, v0\n",
     "flow",
     5,
     1,
     {"code after ret is unreachable"},
     "vs_2_0\ndcl_position v0\nmov oPos, v0\nmov oD0, v0\nret\n"},
    {"RepCountRange",
     "vs_2_0\ndcl_position v0\ndefi i0, 300, 0, 0, 0\nrep i0\nendrep\nmov oPos, v0\n",
     "flow",
     4,
     5,
     {"i0.x = 300 is the iteration count and must be in 0..255"},
     "vs_2_0\ndcl_position v0\ndefi i0, 255, 0, 0, 0\nrep i0\nendrep\nmov oPos, v0\n"},
    {"LoopStepRange",
     "vs_2_0\ndcl_position v0\ndefi i0, 2, 0, 200, 0\nloop aL, i0\nendloop\nmov oPos, v0\n",
     "flow",
     4,
     10,
     {"i0.z = 200 is the step of aL and must be in -128..127"},
     "vs_2_0\ndcl_position v0\ndefi i0, 2, 0, -128, 0\nloop aL, i0\nendloop\nmov oPos, v0\n"},
    {"SubroutineEndsWithRet",
     "vs_2_0\ndcl_position v0\nmov oPos, v0\nret\nlabel l0\nmov r0, v0\n",
     "flow",
     6,
     1,
     {"a subroutine must end with ret"},
     "vs_2_0\ndcl_position v0\nmov oPos, v0\nret\nlabel l0\nmov r0, v0\nret\n"},
};

TIERLIFT_RULE_SUITE(FlowRules, kCases);

TEST(FlowRulesExtra, StaticFlowControlCount) {
  std::string head = "vs_2_0\ndcl_position v0\ndefb b0, true\n";
  EXPECT_TRUE(is_clean(head + repeat("if b0\nendif", 16) + "mov oPos, v0\n"));
  // 16 pairs fill lines 4..35; the 17th if is on line 36.
  EXPECT_TRUE(has_error(head + repeat("if b0\nendif", 17) + "mov oPos, v0\n", "flow", 36, 1,
                        {"vs_2_0 allows 16 static flow-control instructions", "this is the 17th"}));
}

// Microsoft's vertex nesting tables give vs_2_x the same static flow count of 16, and count
// the else of an if b# (in vs_2_0 too); if p0 and if_comp are dynamic and do not count.
TEST(FlowRulesExtra, StaticFlowCountOfVs2x) {
  std::string head = "vs_2_x\ndcl_position v0\ndefb b0, true\n";
  EXPECT_TRUE(is_clean(head + repeat("if b0\nendif", 16) + "mov oPos, v0\n"));
  EXPECT_TRUE(has_error(head + repeat("if b0\nendif", 17) + "mov oPos, v0\n", "flow", 36, 1,
                        {"vs_2_x allows 16 static flow-control instructions", "this is the 17th"}));
  // 8 if/else/endif: 16 counted, at the limit; a 9th if is the 17th (line 4 + 8 * 3 = 28).
  EXPECT_TRUE(is_clean(head + repeat("if b0\nelse\nendif", 8) + "mov oPos, v0\n"));
  EXPECT_TRUE(has_error(head + repeat("if b0\nelse\nendif", 8) + "if b0\nendif\nmov oPos, v0\n",
                        "flow", 28, 1, {"this is the 17th"}));
  const std::string v0 = "vs_2_0\ndcl_position v0\ndefb b0, true\n";
  EXPECT_TRUE(has_error(v0 + repeat("if b0\nelse\nendif", 8) + "if b0\nendif\nmov oPos, v0\n",
                        "flow", 28, 1, {"vs_2_0 allows 16"}));
  // Dynamic ifs are not counted: 17 if_gt blocks after 16 if b# are fine.
  EXPECT_TRUE(is_clean(head + repeat("if b0\nendif", 16) + repeat("if_gt c0.x, c1.x\nendif", 17) +
                       "mov oPos, v0\n"));
}

} // namespace
