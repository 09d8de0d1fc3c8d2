// Any listing file → validated IR (load.h): detect the form, read it, apply Windows'
// leniency unless strict, validate.
#include <fmt/format.h>

#include "tierlift/asm/bytecode.h"
#include "tierlift/asm/load.h"
#include "tierlift/asm/validator.h"

namespace tierlift::as {
namespace {

std::optional<ir::Program> read_tokens(uint32_t file, ir::SourceManager& sm,
                                       ir::DiagnosticSink& diags, LoadResult& out) {
  auto tokens = read_token_file(sm.files[file].text, diags, file);
  // A raw stream has no lines to quote; a C array keeps its text for the scanner's own
  // line:col diagnostics (already reported above).
  if (out.form == ListingForm::TokenStream) sm.files[file].text.clear();
  if (!tokens) return std::nullopt;
  out.tokens = *tokens;
  auto program = disassemble(*tokens, diags, file);
  if (program) out.constants = read_constant_table(*tokens, diags, file);
  return program;
}

} // namespace

LoadResult load_listing(uint32_t file, ir::SourceManager& sm, ir::DiagnosticSink& diags,
                        const LoadOptions& options) {
  LoadResult out;
  out.form = detect_listing_form(sm.files[file].text);
  std::optional<ir::Program> program;
  switch (out.form) {
  case ListingForm::Binary:
    diags.error(ir::SourceLoc{file, 0, 0, 0}, "binary-input",
                fmt::format("this is {}", describe_binary(sm.files[file].text)));
    sm.files[file].text.clear();
    return out;
  case ListingForm::TokenStream:
  case ListingForm::TokenArray: program = read_tokens(file, sm, diags, out); break;
  case ListingForm::Text: program = parse_program(file, sm, diags, options.parse); break;
  }
  if (!program) return out;
  ir::Profile profile = options.profile.value_or(program->profile);
  if (ir::stage_of(profile) != program->stage()) {
    diags.error(program->version_loc, "profile",
                fmt::format("--profile {} is a {} profile, but the listing is {}",
                            ir::profile_name(profile), ir::is_vertex(profile) ? "vertex" : "pixel",
                            ir::profile_name(program->profile)));
    return out;
  }
  if (!options.strict) apply_windows_leniency(*program, profile, diags);
  ValidateOptions vo;
  vo.warnings = options.warnings;
  if (!options.skip_validation && !validate(*program, profile, diags, vo)) return out;
  out.program = std::move(program);
  return out;
}

} // namespace tierlift::as
