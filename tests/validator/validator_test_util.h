// Helpers for the validator tests: parse a listing from text, validate it, and check for one
// diagnostic by rule id, exact line:col and message text.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"

namespace tierlift::vtest {

struct Run {
  assembly::ParseResult parsed;
  ir::DiagnosticSink diags;
  bool valid = false;
};

inline Run run(const std::string& text, std::optional<ir::Profile> target = std::nullopt) {
  Run r;
  r.parsed = assembly::parse_text(text, "t.asm");
  if (r.parsed.program)
    r.valid =
        assembly::validate(*r.parsed.program, target.value_or(r.parsed.program->profile), r.diags);
  return r;
}

inline std::string dump(const Run& r) {
  std::string out = ir::render_text(r.parsed.diags, r.parsed.sources);
  out += ir::render_text(r.diags, r.parsed.sources);
  return out.empty() ? "(no diagnostics)" : out;
}

// A diagnostic of `severity` with `rule` at line:col whose message contains every string of
// `mentions`.
inline ::testing::AssertionResult has_diag(const std::string& text, ir::Severity severity,
                                           const std::string& rule, uint32_t line, uint32_t col,
                                           const std::vector<std::string>& mentions,
                                           std::optional<ir::Profile> target = std::nullopt) {
  Run r = run(text, target);
  if (!r.parsed.program)
    return ::testing::AssertionFailure() << "listing does not parse:\n" << dump(r);
  for (const ir::Diagnostic& d : r.diags.all()) {
    if (d.severity != severity || d.rule != rule || d.loc.line != line || d.loc.col != col)
      continue;
    bool all = true;
    for (const std::string& m : mentions) all = all && d.message.find(m) != std::string::npos;
    if (all) return ::testing::AssertionSuccess();
  }
  ::testing::AssertionResult f = ::testing::AssertionFailure();
  f << "no " << (severity == ir::Severity::Error ? "error" : "warning") << " [" << rule << "] at "
    << line << ":" << col << " mentioning";
  for (const std::string& m : mentions) f << " \"" << m << "\"";
  f << "\nlisting:\n" << text << "\ndiagnostics:\n" << dump(r);
  return f;
}

inline ::testing::AssertionResult has_error(const std::string& text, const std::string& rule,
                                            uint32_t line, uint32_t col,
                                            const std::vector<std::string>& mentions = {},
                                            std::optional<ir::Profile> target = std::nullopt) {
  return has_diag(text, ir::Severity::Error, rule, line, col, mentions, target);
}

inline ::testing::AssertionResult has_warning(const std::string& text, const std::string& rule,
                                              uint32_t line, uint32_t col,
                                              const std::vector<std::string>& mentions = {}) {
  return has_diag(text, ir::Severity::Warning, rule, line, col, mentions);
}

// Parses and validates with no error (warnings allowed).
inline ::testing::AssertionResult is_clean(const std::string& text) {
  Run r = run(text);
  if (!r.parsed.program)
    return ::testing::AssertionFailure() << "listing does not parse:\n" << dump(r);
  if (r.diags.has_errors())
    return ::testing::AssertionFailure() << "listing:\n" << text << "\nerrors:\n" << dump(r);
  return ::testing::AssertionSuccess();
}

// Valid (is_clean), with the warning `rule` at line:col mentioning every string of
// `mentions`: a listing a device takes with a remark.
inline ::testing::AssertionResult only_warns(const std::string& text, const std::string& rule,
                                             uint32_t line, uint32_t col,
                                             const std::vector<std::string>& mentions) {
  ::testing::AssertionResult clean = is_clean(text);
  if (!clean) return clean;
  return has_warning(text, rule, line, col, mentions);
}

// Parses, and validation reports exactly `n` errors.
inline ::testing::AssertionResult has_errors(const std::string& text, size_t n) {
  Run r = run(text);
  if (!r.parsed.program)
    return ::testing::AssertionFailure() << "listing does not parse:\n" << dump(r);
  if (r.diags.error_count() != n)
    return ::testing::AssertionFailure() << r.diags.error_count() << " errors, not " << n << ":\n"
                                         << dump(r);
  return ::testing::AssertionSuccess();
}

// A case of the rule tables: `bad` breaks the rule (error `rule` at line:col mentioning
// `mentions`), `good` is the nearest listing that keeps it (no error at all).
struct RuleCase {
  const char* name;
  const char* bad;
  const char* rule;
  uint32_t line, col;
  std::vector<std::string> mentions;
  const char* good;
};

inline void PrintTo(const RuleCase& c, std::ostream* os) {
  *os << c.name;
}

inline std::string case_name(const ::testing::TestParamInfo<RuleCase>& info) {
  return info.param.name;
}

// Repeats `line` n times (each followed by a newline).
inline std::string repeat(const std::string& line, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += line + "\n";
  return s;
}

} // namespace tierlift::vtest

// One TEST_P body shared by every rule table.
#define TIERLIFT_RULE_SUITE(Suite, Cases)                                                          \
  class Suite : public ::testing::TestWithParam<::tierlift::vtest::RuleCase> {};                   \
  TEST_P(Suite, BrokenListingIsReported) {                                                         \
    const auto& c = GetParam();                                                                    \
    EXPECT_TRUE(::tierlift::vtest::has_error(c.bad, c.rule, c.line, c.col, c.mentions));           \
  }                                                                                                \
  TEST_P(Suite, KeptListingIsClean) {                                                              \
    EXPECT_TRUE(::tierlift::vtest::is_clean(GetParam().good));                                     \
  }                                                                                                \
  INSTANTIATE_TEST_SUITE_P(Rules, Suite, ::testing::ValuesIn(Cases), ::tierlift::vtest::case_name)
