// Text → ir::Program. Runs the D3DX-style preprocessor, then lexes and parses one listing.
//
// Accepted syntax (docs/d3d9-rules.md §1, §4):
// - Case: mnemonics, modifiers, register names, swizzles, usages and the version are read
//   case-insensitively ("MOV", "oPos" = "opos", "R0.XYZW"). Wine's D3DX lexer takes lower
//   case only and whether Microsoft's did is unconfirmed; accepting both loses nothing, and
//   the printer always writes the documented spelling (lower case, oPos/oD0/aL).
// - Comments ";", "//" and "/* */"; white space includes tabs, "\r" and U+00A0.
// - Statements are separated by line ends, but like the D3DX grammar a new statement may
//   also start on the same line after a complete one ("vs_1_1 mov oPos, v0").
// - Columns in diagnostics are 1-based byte offsets (as clang counts them).
// - def values: decimal floats as strtof reads them (optional trailing f), inf, nan, and as
//   an extension "0x7fc00001" = raw bit pattern (so that any NaN prints and re-parses).
// - Rule ids of parser diagnostics: missing-version, unsupported-version, syntax,
//   unknown-instruction, unknown-register, unknown-modifier, operand-count, bad-number,
//   unclosed-comment, binary-input, preprocessor; "too-many-errors" (a note) after 100.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/source.h"

namespace tierlift::assembly {

struct ParseOptions {
  // -D NAME[=VALUE], in command-line order.
  std::vector<std::pair<std::string, std::string>> defines;
  // -I DIR: searched for #include "x" after the including file's own folder.
  std::vector<std::string> include_dirs;
  // false: every #include is an error (fuzzing, untrusted text that must not read files).
  bool allow_include = true;
  // true (--strict): the documented syntax only. false: forms shipped listings use are
  // taken with a warning (docs/d3d9-rules.md §12.8: def values without commas).
  bool strict = false;
};

// Parses sm.files[file]. Every problem becomes a diagnostic with a position; on any error
// the result is nullopt. Never throws on bad input. #include'd files are added to sm.
std::optional<ir::Program> parse_program(uint32_t file, ir::SourceManager& sm,
                                         ir::DiagnosticSink& diags,
                                         const ParseOptions& options = {});

// Convenience for tests and tools: adds `text` to a fresh SourceManager under `name`.
struct ParseResult {
  ir::SourceManager sources;
  ir::DiagnosticSink diags;
  std::optional<ir::Program> program;
};
ParseResult parse_text(std::string text, std::string name = "<text>",
                       const ParseOptions& options = {});

} // namespace tierlift::assembly
