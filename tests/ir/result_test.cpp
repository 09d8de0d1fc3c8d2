// ir::Result / ir::Status: a value or the diagnostics that say why not, and how a
// diagnostic without a position renders (its subject in the file name's place).
#include <gtest/gtest.h>

#include "tierlift/ir/result.h"

namespace ir = tierlift::ir;

namespace {

ir::SourceLoc at(uint32_t line, uint32_t col, uint32_t length) {
  ir::SourceLoc loc;
  loc.line = line;
  loc.col = col;
  loc.length = length;
  return loc;
}

ir::Result<int> parse_digit(char c) {
  if (c < '0' || c > '9') return ir::fail("input", "digit", std::string("not a digit: ") + c);
  return c - '0';
}

TEST(Result, CarriesTheValueOrTheError) {
  ir::Result<int> good = parse_digit('7');
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(*good, 7);
  EXPECT_TRUE(good.diagnostics().empty());

  ir::Result<int> bad = parse_digit('x');
  ASSERT_FALSE(bad.ok());
  ASSERT_EQ(bad.diagnostics().size(), 1u);
  EXPECT_EQ(bad.message(), "not a digit: x");
  EXPECT_EQ(bad.diagnostics()[0].rule, "digit");
  EXPECT_EQ(bad.diagnostics()[0].subject, "input");
}

TEST(Result, FailureHandsOnToTheCaller) {
  auto twice = [](char c) -> ir::Result<int> {
    ir::Result<int> d = parse_digit(c);
    if (!d) return std::move(d).failure();
    return 2 * *d;
  };
  EXPECT_EQ(*twice('4'), 8);
  EXPECT_EQ(twice('?').message(), "not a digit: ?");
}

TEST(Result, SinkErrorsBecomeTheFailure) {
  ir::DiagnosticSink sink;
  sink.warning({}, "w", "a warning first");
  sink.error(at(3, 5, 2), "e", "the error");
  ir::Status s = ir::fail(sink);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.diagnostics().size(), 2u);
  EXPECT_EQ(s.message(), "the error");
  EXPECT_TRUE(ir::ok_status().ok());
}

TEST(Result, SubjectRendersInTheFileNamesPlace) {
  ir::SourceManager sm;
  ir::Status s = ir::fail("scene.png", "io", "cannot open: No such file or directory");
  EXPECT_EQ(ir::render_text(s.diagnostics()[0], sm),
            "scene.png: error: cannot open: No such file or directory [io]\n");
  sm.add("a.psh", "ps_2_0\nmov oC0, r9\n");
  ir::Status p = ir::fail_at(at(2, 10, 2), "reg", "bad register");
  EXPECT_EQ(ir::render_text(p.diagnostics()[0], sm),
            "a.psh:2:10: error: bad register [reg]\n    mov oC0, r9\n             ^~\n");
}

// A rendered message quotes its source line: fail_rendered keeps it whole, where fail cuts a
// word past kMaxEchoedWord bytes (a 50 MB token must not reach standard error).
TEST(Result, RenderedFailureKeepsItsTextWhole) {
  const std::string word(ir::kMaxEchoedWord + 1, 'x');
  const std::string text = "a.frag:1:1: error: '" + word + "' undeclared\n  " + word + "\n  ^\n";
  ir::Status kept = ir::fail_rendered("a.frag", "glsl", text);
  ASSERT_FALSE(kept.ok());
  EXPECT_EQ(kept.message(), text);
  EXPECT_EQ(kept.diagnostics()[0].rule, "glsl");
  EXPECT_EQ(kept.diagnostics()[0].subject, "a.frag");
  EXPECT_NE(ir::Status(ir::fail("a.frag", "glsl", text)).message(), text);
}

} // namespace
