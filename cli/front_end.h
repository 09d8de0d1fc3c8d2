// What the listing-reading subcommands share: reading a file (or standard input), the
// preprocessor/profile/validation flags, and printing diagnostics as text or JSON.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "tierlift/assembly/load.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::cli {

struct FrontEndOptions {
  std::vector<std::string> defines;      // -D NAME[=VALUE]
  std::vector<std::string> include_dirs; // -I DIR
  std::string profile;                   // --profile: validate against this instead
  bool skip_validation = false;          // --skip-validation (fxc /Vd)
  bool json = false;                     // --json
  bool strict = false;                   // --strict: the documented rules only
};

// Adds -D, -I (one value each, repeatable), --profile, --strict, --skip-validation (when
// asked) and --json (when asked: run and glow print results, not only diagnostics, under it).
void add_front_end_options(CLI::App* sub, FrontEndOptions& options, bool skip_validation_flag,
                           bool json_flag = true);
// --strict alone (commands that take only some of the front-end flags).
void add_strict_flag(CLI::App* sub, FrontEndOptions& options);

// -D NAME[=VALUE] words as (NAME, VALUE) pairs; a bare NAME is defined as 1.
std::vector<std::pair<std::string, std::string>>
split_defines(const std::vector<std::string>& defines);

struct LoadedListing {
  ir::SourceManager sources;
  ir::DiagnosticSink diags;
  std::optional<ir::Program> program; // set when it parsed (and validated, unless skipped)
  assembly::ListingForm form =
      assembly::ListingForm::Text;                  // text or token stream (detected by content)
  std::optional<assembly::ConstantTable> constants; // a token stream's CTAB
};

// Reads `path` ("-" = standard input) within io::kListingCap — assembly text (a UTF-8
// byte-order mark is skipped) or a D3D9 token stream, told apart by content
// (assembly::load_listing) — parses it, and validates it unless skipped.
// `cap` is the reader's limit (disasm reads within io::kTokenFileCap).
// A listing that could not be read, or a bad flag, is a failure (rule "io": exit 2); one that
// was read carries its own diagnostics (LoadedListing::diags), whether it parsed or not.
ir::Result<LoadedListing> load_listing(const std::string& path, const FrontEndOptions& options,
                                       const io::ReadCap& cap = io::kListingCap);

// True when `backend` ("the interpreter", "SPIR-V") can run the listing's program; otherwise
// adds its positioned "not-supported" error to the listing's diagnostics (shader models 2.x
// and 3.0 are checked, printed and assembled, not yet executed).
bool check_executable(LoadedListing& listing, std::string_view backend);

// OK when `output` ("-" = standard output) may be written: it is none of `inputs` (same
// device and inode). Commands check this before doing any work, so nothing is touched.
ir::Status output_conflict(const std::string& output, const std::vector<std::string>& inputs);
// After loading: OK when `output` is none of the files `listing` #included (directly or
// through another include); the refusal names both. Nothing has been written yet.
ir::Status refuse_included(const std::string& output, const LoadedListing& listing);
// The listing a command writes `output` from: load_listing, then refuse_included. On a
// failure `failed_path` names the file it is about (the listing, or the output).
ir::Result<LoadedListing> load_writing_to(const std::string& path, const FrontEndOptions& options,
                                          const std::string& output, std::string& failed_path);
// output_conflict, and also refuses "-o -" together with --json (both want standard
// output).
ir::Status check_output(const std::string& output, const std::vector<std::string>& inputs,
                        bool json);
// io::write_output: "-" is standard output, FIFOs and devices are written through, anything
// else goes through a temporary file renamed into place. "" on success.
std::string write_output(const std::string& path, std::string_view bytes);

// A CTAB as JSON: [{"name", "registers", "set", "index", "count", "type"}].
nlohmann::json constants_json(const assembly::ConstantTable& table);

} // namespace tierlift::cli
