// Call nesting in the 2.x and 3.0 profiles. Limits from Microsoft's flow-control nesting
// tables ("Flow Control Nesting Limits" for vertex shaders, "Flow Control Limitations" for
// pixel shaders): vs_3_0 and ps_3_0 nest calls 4 deep; vs_2_x and ps_2_x as deep as the
// device's StaticFlowControlDepth (1..4 vertex, 0..4 pixel), independently of loop/rep.
#include <gtest/gtest.h>

#include <string>

#include "validator_test_util.h"

using namespace tierlift;
using tierlift::vtest::has_error;
using tierlift::vtest::is_clean;

namespace {

// main calls l1, l1 calls l2, ..., l(n-1) calls ln: the call in l(d-1) is at depth d.
// Lines: 1 version, 2..3 the output, then main's call and ret, then three lines a routine.
std::string chain(const std::string& profile, int n) {
  std::string out = profile + "\n";
  const bool vs = profile[0] == 'v';
  out += vs ? (profile == "vs_3_0" ? "dcl_position o0\nmov o0, c0\n"
                                   : "dcl_position v0\nmov oPos, v0\n")
            : "mov oC0, c0\nnop\n";
  out += "call l1\nret\n";
  for (int i = 1; i <= n; ++i) {
    out += "label l" + std::to_string(i) + "\n";
    if (i < n) out += "call l" + std::to_string(i + 1) + "\n";
    out += "ret\n";
  }
  return out;
}

// The line of the call made at depth d (d >= 2) in chain(): inside l(d-1).
uint32_t call_line(int d) {
  return d == 1 ? 4 : static_cast<uint32_t>(7 + 3 * (d - 2));
}

// Validation under explicit 2.x caps; the errors of rule "call-nesting" as "line:col message".
std::string call_errors(const std::string& text, ir::Profile target, ir::Caps2x caps) {
  auto parsed = assembly::parse_text(text, "t.asm");
  EXPECT_TRUE(parsed.program.has_value());
  if (!parsed.program) return "?";
  assembly::ValidateOptions o;
  o.caps = caps;
  ir::DiagnosticSink diags;
  assembly::validate(*parsed.program, target, diags, o);
  std::string out;
  for (const ir::Diagnostic& d : diags.all())
    if (d.rule == "call-nesting")
      out += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + " " + d.message + "\n";
  return out;
}

} // namespace

TEST(CallNesting, ThreeZeroAllowsFourLevels) {
  for (const char* profile : {"ps_3_0", "vs_3_0"}) {
    SCOPED_TRACE(profile);
    EXPECT_TRUE(is_clean(chain(profile, 4)));
    EXPECT_TRUE(has_error(chain(profile, 5), "call-nesting", call_line(5), 1,
                          {std::string(profile) + " allows call nesting depth 4",
                           "this call is at depth 5", "main -> l1 -> l2 -> l3 -> l4 -> l5"}));
  }
}

TEST(CallNesting, TwoXFollowsStaticFlowControlDepth) {
  // Defaults: the most a 2.x device may report, 4.
  EXPECT_TRUE(is_clean(chain("ps_2_x", 4)));
  EXPECT_TRUE(is_clean(chain("vs_2_x", 4)));
  EXPECT_TRUE(has_error(chain("vs_2_x", 5), "call-nesting", call_line(5), 1,
                        {"vs_2_x allows call nesting depth 4"}));
  // A device reporting StaticFlowControlDepth 2: two levels, not three.
  ir::Caps2x caps = ir::default_caps(ir::Profile::ps_2_x);
  caps.static_depth = 2;
  EXPECT_EQ(call_errors(chain("ps_2_x", 2), ir::Profile::ps_2_x, caps), "");
  EXPECT_EQ(call_errors(chain("ps_2_x", 3), ir::Profile::ps_2_x, caps),
            "10:1 ps_2_x allows call nesting depth 2; this call is at depth 3 (main -> l1 -> l2 "
            "-> l3)\n");
  // fxc's vs_2_a nests calls one deep, as vs_2_0 does.
  auto vs2a = ir::caps_preset("vs_2_a");
  ASSERT_TRUE(vs2a.has_value());
  EXPECT_EQ(call_errors(chain("vs_2_x", 1), ir::Profile::vs_2_x, vs2a->second), "");
  EXPECT_EQ(call_errors(chain("vs_2_x", 2), ir::Profile::vs_2_x, vs2a->second),
            "7:1 vs_2_x allows call nesting depth 1; this call is at depth 2 (main -> l1 -> l2)\n");
}

// Depth counts along chains, not calls: many calls from main, or a subroutine called from
// two depths, are measured by the deepest chain, and each call is reported once.
TEST(CallNesting, DeepestChainCounts) {
  const std::string wide = "ps_3_0\nmov oC0, c0\ncall l1\ncall l2\ncall l3\ncall l4\ncall l5\n"
                           "ret\nlabel l1\nret\nlabel l2\nret\nlabel l3\nret\nlabel l4\nret\n"
                           "label l5\nret\n";
  EXPECT_TRUE(is_clean(wide));
  // l9 is called from main (depth 1) and from l4 (depth 5): the second call is refused.
  std::string text = chain("ps_3_0", 4);
  text.replace(text.find("call l1\n"), 8, "call l1\ncall l9\n");
  text.replace(text.rfind("ret\n"), 4, "call l9\nret\nlabel l9\nret\n");
  EXPECT_EQ(call_errors(text, ir::Profile::ps_3_0, ir::default_caps(ir::Profile::ps_3_0)),
            "17:1 ps_3_0 allows call nesting depth 4; this call is at depth 5 (main -> l1 -> l2 "
            "-> l3 -> l4 -> l9)\n");
}

TEST(CallNesting, RecursionIsRefused) {
  EXPECT_TRUE(has_error("ps_3_0\nmov oC0, c0\ncall l1\nret\nlabel l1\ncall l1\nret\n",
                        "call-nesting", 6, 1, {"l1 calls l1 again (main -> l1 -> l1)"}));
  EXPECT_TRUE(has_error("vs_2_x\ndcl_position v0\nmov oPos, v0\ncall l1\nret\nlabel l1\ncall "
                        "l2\nret\nlabel l2\ncall l1\nret\n",
                        "call-nesting", 10, 1, {"l2 calls l1 again (main -> l1 -> l2 -> l1)"}));
}
