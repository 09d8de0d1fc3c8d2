// What the listing-reading subcommands share: reading a file (or standard input), the
// preprocessor/profile/validation flags, and printing diagnostics as text or JSON.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "tierlift/asm/load.h"
#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"

namespace tierlift::cli {

struct FrontEndOptions {
  std::vector<std::string> defines;      // -D NAME[=VALUE]
  std::vector<std::string> include_dirs; // -I DIR
  std::string profile;                   // --profile: validate against this instead
  bool skip_validation = false;          // --skip-validation (fxc /Vd)
  bool json = false;                     // --json
  bool strict = false;                   // --strict: the documented rules only
};

// Adds -D, -I, --profile, --json, --strict and (when asked) --skip-validation.
void add_front_end_options(CLI::App* sub, FrontEndOptions& options, bool skip_validation_flag);
// --strict alone (commands that take only some of the front-end flags).
void add_strict_flag(CLI::App* sub, FrontEndOptions& options);

struct LoadedListing {
  ir::SourceManager sources;
  ir::DiagnosticSink diags;
  std::optional<ir::Program> program; // set when it parsed (and validated, unless skipped)
  as::ListingForm form = as::ListingForm::Text; // text or token stream (detected by content)
  std::optional<as::ConstantTable> constants;   // a token stream's CTAB
  bool io_error = false;                        // could not be read: exit 2
  std::string io_message;
};

// Reads `path` ("-" = standard input) — assembly text or a D3D9 token stream, told apart
// by content (as::load_listing) — and validates it unless skipped.
LoadedListing load_listing(const std::string& path, const FrontEndOptions& options);

// Reads a whole file as bytes; "-" reads standard input. nullopt + message on failure.
std::optional<std::string> read_file(const std::string& path, std::string& error);
// Writes to a temporary file beside `path`, then renames it over `path`, so a failed or
// interrupted write never leaves a half-written output.
bool write_file_atomically(const std::string& path, std::string_view bytes, std::string& error);

// Diagnostics of one listing as JSON (the objects of ir::render_json).
nlohmann::json diagnostics_json(const LoadedListing& listing);
// A CTAB as JSON: [{"name", "registers", "set", "index", "count", "type"}].
nlohmann::json constants_json(const as::ConstantTable& table);
// Text diagnostics to stderr.
void print_diagnostics(const LoadedListing& listing);

} // namespace tierlift::cli
