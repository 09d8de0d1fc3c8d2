// Rule `gradient-in-divergent-flow` (NUMERICS.md rule F8): dsx/dsy inside flow that may differ
// between the pixels of a 2x2 quad warn, as fxc warns; gradients in flow on constants or
// outside flow do not.
#include "validator_test_util.h"

using tierlift::vtest::only_warns;

namespace {

namespace ir = tierlift::ir;

size_t gradient_warnings(const std::string& text) {
  tierlift::vtest::Run r = tierlift::vtest::run(text);
  EXPECT_TRUE(r.parsed.program) << tierlift::vtest::dump(r);
  EXPECT_FALSE(r.diags.has_errors()) << tierlift::vtest::dump(r);
  size_t n = 0;
  for (const ir::Diagnostic& d : r.diags.all())
    n += d.severity == ir::Severity::Warning && d.rule == "gradient-in-divergent-flow";
  return n;
}

const char* kHead = "ps_3_0\ndefi i0, 3, 0, 0, 0\ndefb b0, true\ndcl_texcoord0 v0\n";

TEST(GradientRules, DsxInsideIfCompWarns) {
  const std::string text = std::string(kHead) + "if_lt v0.x, c0.x\n" // line 5
                                                "  dsx r0, v0\n"     // line 6
                                                "endif\nmov oC0, r0\n";
  EXPECT_TRUE(only_warns(text, "gradient-in-divergent-flow", 6, 3, {"dsx", "if_lt", "line 5"}));
  EXPECT_EQ(gradient_warnings(text), 1u);
}

TEST(GradientRules, DsyInTheElseOfIfPredicateWarns) {
  const std::string text = std::string(kHead) +
                           "setp_gt p0.x, v0.x, c0.x\nif p0.x\nmov r0, c1\nelse\n"
                           "dsy r0, v0\n" // line 9
                           "endif\nmov oC0, r0\n";
  EXPECT_TRUE(only_warns(text, "gradient-in-divergent-flow", 9, 1, {"dsy", "if"}));
}

TEST(GradientRules, LoopsAPixelCanLeaveByItselfWarn) {
  // break_comp, and a plain break inside if_comp: the loop's later iterations may run in some
  // pixels of the quad only.
  for (const char* exit : {"break_ge r1.x, c0.x\n", "if_ge r1.x, c0.x\nbreak\nendif\n"}) {
    const std::string text = std::string(kHead) + "mov r1, c2\nrep i0\n" + exit +
                             "dsx r0, v0\nadd r1, r1, r0\nendrep\nmov oC0, r1\n";
    EXPECT_EQ(gradient_warnings(text), 1u) << text;
  }
}

TEST(GradientRules, FlowOnConstantsAndPlainCodeAreQuiet) {
  const std::string text = std::string(kHead) + "dsx r0, v0\n"
                                                "if b0\ndsy r1, v0\nendif\n"
                                                "rep i0\ndsx r2, r0\nadd r0, r0, r2\nendrep\n"
                                                "if_lt v0.x, c0.x\nmov r0, c1\nendif\n"
                                                "dsy r3, r0\nadd oC0, r3, r1\n";
  EXPECT_EQ(gradient_warnings(text), 0u);
}

// texld, texldp and texldb take their level of detail from the coordinate's gradients across
// the quad (NUMERICS.md M5): inside divergent flow they warn as dsx does; texldl and texldd,
// given their lod or gradients, do not, nor does texld outside such flow.
TEST(GradientRules, ImplicitLodReadsInDivergentFlowWarn) {
  const std::string head = std::string(kHead) + "dcl_2d s0\n";
  for (const char* read : {"texld r0, v0, s0\n", "texldp r0, v0, s0\n", "texldb r0, v0, s0\n"}) {
    const std::string text = head + "if_lt v0.x, c0.x\n" + read + "endif\nmov oC0, r0\n";
    EXPECT_EQ(gradient_warnings(text), 1u) << text;
    EXPECT_TRUE(only_warns(text, "gradient-in-divergent-flow", 7, 1, {"if_lt", "level of detail"}))
        << text;
  }
  const std::string quiet = head + "texld r1, v0, s0\nif_lt v0.x, c0.x\n"
                                   "texldl r0, v0, s0\ntexldd r2, v0, s0, c1, c2\n"
                                   "add r0, r0, r2\nendif\nadd oC0, r0, r1\n";
  EXPECT_EQ(gradient_warnings(quiet), 0u);
}

} // namespace
