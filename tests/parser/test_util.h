// Helpers shared by the parser tests.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "tierlift/assembly/parser.h"
#include "tierlift/ir/diagnostic.h"

namespace tierlift::assembly::test {

// Parses and fails the test (with rendered diagnostics) when parsing did not succeed.
inline ir::Program must_parse(const std::string& text, const ParseOptions& opts = {}) {
  ParseResult r = parse_text(text, "<test>", opts);
  EXPECT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources) << "in:\n" << text;
  return r.program.value_or(ir::Program{});
}

// The first error of a parse that must fail.
struct FirstError {
  std::string rule;
  uint32_t line = 0, col = 0, length = 0;
  std::string message;
  size_t errors = 0;
};
inline FirstError first_error(const std::string& text, const ParseOptions& opts = {}) {
  ParseResult r = parse_text(text, "<test>", opts);
  FirstError e;
  EXPECT_FALSE(r.program.has_value()) << "expected a parse error in:\n" << text;
  e.errors = r.diags.error_count();
  for (const auto& d : r.diags.all())
    if (d.severity == ir::Severity::Error) {
      e.rule = d.rule;
      e.line = d.loc.line;
      e.col = d.loc.col;
      e.length = d.loc.length;
      e.message = d.message;
      break;
    }
  return e;
}

// One expected first error; a field left unset is not checked, since many cases pin
// only the rule or the column that the case is about.
struct ErrorCase {
  std::string text = {};
  std::string rule = {};
  std::optional<uint32_t> line = {}, col = {}, length = {};
  std::optional<size_t> errors = {};
  std::string message_has = {}; // a part the message must contain; empty: not checked
};
inline void expect_first_errors(std::initializer_list<ErrorCase> cases,
                                const ParseOptions& opts = {}) {
  for (const ErrorCase& c : cases) {
    SCOPED_TRACE("in:\n" + c.text);
    FirstError e = first_error(c.text, opts);
    EXPECT_EQ(e.rule, c.rule);
    if (c.line) {
      EXPECT_EQ(e.line, *c.line);
    }
    if (c.col) {
      EXPECT_EQ(e.col, *c.col);
    }
    if (c.length) {
      EXPECT_EQ(e.length, *c.length);
    }
    if (c.errors) {
      EXPECT_EQ(e.errors, *c.errors);
    }
    if (!c.message_has.empty()) {
      EXPECT_NE(e.message.find(c.message_has), std::string::npos) << e.message;
    }
  }
}

} // namespace tierlift::assembly::test
