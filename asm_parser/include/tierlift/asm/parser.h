// Text → ir::Program. Runs the D3DX-style preprocessor, then lexes and parses one listing.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/source.h"

namespace tierlift::as {

struct ParseOptions {
  // -D NAME[=VALUE], in command-line order.
  std::vector<std::pair<std::string, std::string>> defines;
  // -I DIR: searched for #include "x" after the including file's own folder.
  std::vector<std::string> include_dirs;
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

}  // namespace tierlift::as
