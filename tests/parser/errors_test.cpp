// Error positions (line and column, checked exactly), rule ids and recovery.
#include "test_util.h"

namespace tierlift::assembly::test {
namespace {

TEST(ParserErrors, UnknownMnemonic) {
  expect_first_errors({{.text = "vs_1_1\nmov r0, v0\n  frob r0, v0\n",
                        .rule = "unknown-instruction",
                        .line = 3,
                        .col = 3,
                        .length = 4,
                        .message_has = "'frob'"}});
}

TEST(ParserErrors, UnknownMnemonicWithModifiersUnderlinesOnlyTheName) {
  expect_first_errors({{.text = "ps_1_4\nfrob_sat r0, r1\n",
                        .rule = "unknown-instruction",
                        .col = 1,
                        .length = 4}});
}

TEST(ParserErrors, UnknownRegister) {
  expect_first_errors({
      {.text = "vs_1_1\nmov r0, q7\n", .rule = "unknown-register", .line = 2, .col = 9},
      {.text = "vs_1_1\nmov oX0, v0\n", .rule = "unknown-register", .col = 5},
  });
}

TEST(ParserErrors, UnknownModifiers) {
  expect_first_errors({
      {.text = "ps_1_4\nmul_x3 r0, r1, r2\n", .rule = "unknown-modifier", .col = 4, .length = 3},
      {.text = "ps_1_4\nmov r0, r1_bx3\n", .rule = "unknown-modifier", .col = 11},
  });
}

TEST(ParserErrors, BadNumber) {
  expect_first_errors({
      {.text = "vs_1_1\ndef c0, 1.0, 2x, 3, 4\n", .rule = "bad-number", .line = 2, .col = 14},
      {.text = "vs_1_1\ndef c0, 1e39, 0, 0, 0\n", .rule = "bad-number", .col = 9},
      {.text = "vs_2_0\ndefi i0, 1, 2.5, 3, 4\n", .rule = "bad-number", .col = 13},
      {.text = "vs_2_0\ndefb b0, maybe\n", .rule = "bad-number", .col = 10},
  });
}

TEST(ParserErrors, DefWithTooFewOrTooManyValues) {
  expect_first_errors({
      {.text = "vs_1_1\n  def c0, 1, 2, 3\n", .rule = "operand-count", .line = 2, .col = 3},
      {.text = "vs_1_1\ndef c0, 1, 2, 3, 4, 5\n", .rule = "operand-count", .col = 19},
      {.text = "vs_1_1\ndef c0.x, 1, 2, 3, 4\n", .rule = "syntax", .col = 5},
  });
}

TEST(ParserErrors, UnclosedComment) {
  expect_first_errors({{.text = "vs_1_1\nmov r0, v0 /* open\nmov r1, v1\n",
                        .rule = "unclosed-comment",
                        .line = 2,
                        .col = 12}});
}

TEST(ParserErrors, MissingVersion) {
  // One clear error, not one per line.
  expect_first_errors({{.text = "; comment\n\n   mov r0, v0\n",
                        .rule = "missing-version",
                        .line = 3,
                        .col = 4,
                        .errors = 1}});
}

TEST(ParserErrors, EmptyFileAndCommentOnlyFile) {
  for (const char* text : {"", "; only a comment\n", "\n\n", "/* x */"})
    expect_first_errors({{.text = text, .rule = "missing-version", .line = 1, .col = 1}});
}

TEST(ParserErrors, BinaryInputIsOneError) {
  // A NUL with text after it (NUL bytes that only end the file are padding: the text ends
  // there, ShippedForms.TrailingNulBytesEndTheText).
  std::string nul("vs_1_1\nmov r0, v0\nab\0cd\n", 24);
  std::string junk = "vs_1_1\nmov r0, \xFF\xFE\x80 v0\n";
  for (int i = 0; i < 1000; ++i) junk += "\xC3\x28\xA0\xA1 \x90\n";
  expect_first_errors({
      {.text = nul, .rule = "binary-input", .line = 3, .col = 3, .errors = 1},
      {.text = junk, .rule = "binary-input", .line = 2, .col = 9, .errors = 1},
  });
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
  expect_first_errors({
      // Missing comma: mov sees one operand.
      {.text = "vs_1_1\nmov r0 v0\n", .rule = "operand-count"},
      {.text = "vs_1_1\nadd r0, v0, v1 v2\n",
       .rule = "syntax",
       .col = 16,
       .message_has = "missing ','"},
      {.text = "vs_1_1\nmov r0, c[a0.x + 4\n", .rule = "syntax", .col = 10}, // the '[' left open
      {.text = "vs_1_1\nmov r0.yx, v0\n", .rule = "syntax", .col = 8},
      {.text = "vs_1_1\nmov r0, v0.xyzwx\n", .rule = "syntax", .col = 12},
      {.text = "vs_1_1\nmov -r0, v0\n", .rule = "syntax", .col = 5},
      {.text = "vs_1_1\nvs_1_1\n", .rule = "syntax", .line = 2},
      {.text = "vs_1_1\nmov r0, 1-r1_bx2\n", .rule = "syntax"},
      {.text = "vs_1_1\nmov r0, c\n", .rule = "unknown-register", .col = 9},
  });
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
} // namespace tierlift::assembly::test
