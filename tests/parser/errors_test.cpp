// Error positions (line and column, checked exactly), rule ids and recovery.
#include "test_util.h"

namespace tierlift::as::test {
namespace {

TEST(ParserErrors, UnknownMnemonic) {
  auto e = first_error("vs_1_1\nmov r0, v0\n  frob r0, v0\n");
  EXPECT_EQ(e.rule, "unknown-instruction");
  EXPECT_EQ(e.line, 3u);
  EXPECT_EQ(e.col, 3u);
  EXPECT_EQ(e.length, 4u);
  EXPECT_NE(e.message.find("'frob'"), std::string::npos) << e.message;
}

TEST(ParserErrors, UnknownMnemonicWithModifiersUnderlinesOnlyTheName) {
  auto e = first_error("ps_1_4\nfrob_sat r0, r1\n");
  EXPECT_EQ(e.rule, "unknown-instruction");
  EXPECT_EQ(e.col, 1u);
  EXPECT_EQ(e.length, 4u);
}

TEST(ParserErrors, UnknownRegister) {
  auto e = first_error("vs_1_1\nmov r0, q7\n");
  EXPECT_EQ(e.rule, "unknown-register");
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.col, 9u);
  auto e2 = first_error("vs_1_1\nmov oX0, v0\n");
  EXPECT_EQ(e2.rule, "unknown-register");
  EXPECT_EQ(e2.col, 5u);
}

TEST(ParserErrors, UnknownModifiers) {
  auto e = first_error("ps_1_4\nmul_x3 r0, r1, r2\n");
  EXPECT_EQ(e.rule, "unknown-modifier");
  EXPECT_EQ(e.col, 4u);
  EXPECT_EQ(e.length, 3u);
  auto s = first_error("ps_1_4\nmov r0, r1_bx3\n");
  EXPECT_EQ(s.rule, "unknown-modifier");
  EXPECT_EQ(s.col, 11u);
}

TEST(ParserErrors, BadNumber) {
  auto e = first_error("vs_1_1\ndef c0, 1.0, 2x, 3, 4\n");
  EXPECT_EQ(e.rule, "bad-number");
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.col, 14u);
  auto big = first_error("vs_1_1\ndef c0, 1e39, 0, 0, 0\n");
  EXPECT_EQ(big.rule, "bad-number");
  EXPECT_EQ(big.col, 9u);
  auto i = first_error("vs_2_0\ndefi i0, 1, 2.5, 3, 4\n");
  EXPECT_EQ(i.rule, "bad-number");
  EXPECT_EQ(i.col, 13u);
  auto b = first_error("vs_2_0\ndefb b0, maybe\n");
  EXPECT_EQ(b.rule, "bad-number");
  EXPECT_EQ(b.col, 10u);
}

TEST(ParserErrors, DefWithTooFewOrTooManyValues) {
  auto few = first_error("vs_1_1\n  def c0, 1, 2, 3\n");
  EXPECT_EQ(few.rule, "operand-count");
  EXPECT_EQ(few.line, 2u);
  EXPECT_EQ(few.col, 3u);
  auto many = first_error("vs_1_1\ndef c0, 1, 2, 3, 4, 5\n");
  EXPECT_EQ(many.rule, "operand-count");
  EXPECT_EQ(many.col, 19u);
  auto mask = first_error("vs_1_1\ndef c0.x, 1, 2, 3, 4\n");
  EXPECT_EQ(mask.rule, "syntax");
  EXPECT_EQ(mask.col, 5u);
}

TEST(ParserErrors, UnclosedComment) {
  auto e = first_error("vs_1_1\nmov r0, v0 /* open\nmov r1, v1\n");
  EXPECT_EQ(e.rule, "unclosed-comment");
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.col, 12u);
}

TEST(ParserErrors, MissingVersion) {
  auto e = first_error("; comment\n\n   mov r0, v0\n");
  EXPECT_EQ(e.rule, "missing-version");
  EXPECT_EQ(e.line, 3u);
  EXPECT_EQ(e.col, 4u);
  EXPECT_EQ(e.errors, 1u); // one clear error, not one per line
}

TEST(ParserErrors, EmptyFileAndCommentOnlyFile) {
  for (const char* text : {"", "; only a comment\n", "\n\n", "/* x */"}) {
    auto e = first_error(text);
    EXPECT_EQ(e.rule, "missing-version") << text;
    EXPECT_EQ(e.line, 1u) << text;
    EXPECT_EQ(e.col, 1u) << text;
  }
}

TEST(ParserErrors, BinaryInputIsOneError) {
  std::string nul("vs_1_1\nmov r0, v0\nab\0cd\n", 21);
  auto e = first_error(nul);
  EXPECT_EQ(e.rule, "binary-input");
  EXPECT_EQ(e.line, 3u);
  EXPECT_EQ(e.col, 3u);
  EXPECT_EQ(e.errors, 1u);
  std::string junk = "vs_1_1\nmov r0, \xFF\xFE\x80 v0\n";
  for (int i = 0; i < 1000; ++i) junk += "\xC3\x28\xA0\xA1 \x90\n";
  auto j = first_error(junk);
  EXPECT_EQ(j.rule, "binary-input");
  EXPECT_EQ(j.line, 2u);
  EXPECT_EQ(j.col, 9u);
  EXPECT_EQ(j.errors, 1u);
}

TEST(ParserErrors, InvalidUtf8InCommentsIsFine) {
  must_parse("vs_1_1 ; Latin-1 \xB2 in a comment\nmov oPos, v0 // \xFF\n/* \xC0 */\n");
}

TEST(ParserErrors, SeveralErrorsRecoverAtTheNextLine) {
  ParseResult r = parse_text("vs_1_1\nfoo r0\nmov r0, v0\nmov q1, v0\nadd r0\nmov r1, v1\n");
  ASSERT_FALSE(r.program);
  ASSERT_EQ(r.diags.error_count(), 3u) << ir::render_text(r.diags, r.sources);
  EXPECT_EQ(r.diags.all()[0].loc.line, 2u);
  EXPECT_EQ(r.diags.all()[1].loc.line, 4u);
  EXPECT_EQ(r.diags.all()[2].loc.line, 5u);
}

TEST(ParserErrors, SyntaxErrors) {
  auto e = first_error("vs_1_1\nmov r0 v0\n"); // missing comma: mov sees one operand
  EXPECT_EQ(e.rule, "operand-count");
  auto extra = first_error("vs_1_1\nadd r0, v0, v1 v2\n");
  EXPECT_EQ(extra.rule, "syntax");
  EXPECT_EQ(extra.col, 16u);
  EXPECT_NE(extra.message.find("missing ','"), std::string::npos) << extra.message;
  auto b = first_error("vs_1_1\nmov r0, c[a0.x + 4\n");
  EXPECT_EQ(b.rule, "syntax");
  EXPECT_EQ(b.col, 10u); // the '[' left open
  auto m = first_error("vs_1_1\nmov r0.yx, v0\n");
  EXPECT_EQ(m.rule, "syntax");
  EXPECT_EQ(m.col, 8u);
  auto s = first_error("vs_1_1\nmov r0, v0.xyzwx\n");
  EXPECT_EQ(s.rule, "syntax");
  EXPECT_EQ(s.col, 12u);
  auto d = first_error("vs_1_1\nmov -r0, v0\n");
  EXPECT_EQ(d.rule, "syntax");
  EXPECT_EQ(d.col, 5u);
  auto v = first_error("vs_1_1\nvs_1_1\n");
  EXPECT_EQ(v.rule, "syntax");
  EXPECT_EQ(v.line, 2u);
  auto c = first_error("vs_1_1\nmov r0, 1-r1_bx2\n");
  EXPECT_EQ(c.rule, "syntax");
  auto x = first_error("vs_1_1\nmov r0, c\n");
  EXPECT_EQ(x.rule, "unknown-register");
  EXPECT_EQ(x.col, 9u);
}

TEST(ParserErrors, RenderedDiagnosticHasFileLineColAndCaret) {
  ParseResult r = parse_text("vs_1_1\nmov r0, q7\n", "shader.vsh");
  ASSERT_FALSE(r.program);
  EXPECT_EQ(ir::render_text(r.diags, r.sources),
            "shader.vsh:2:9: error: unknown register 'q7' [unknown-register]\n"
            "    mov r0, q7\n"
            "            ^~\n");
}

} // namespace
} // namespace tierlift::as::test
