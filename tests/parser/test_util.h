// Helpers shared by the parser tests.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "tierlift/asm/parser.h"
#include "tierlift/ir/diagnostic.h"

namespace tierlift::as::test {

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

} // namespace tierlift::as::test
