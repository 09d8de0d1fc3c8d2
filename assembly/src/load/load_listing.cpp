// Any listing file → validated IR (load.h): detect the form, read it, apply Windows'
// leniency unless strict, validate.
#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/load.h"
#include "tierlift/assembly/validator.h"

namespace tierlift::assembly {
namespace {

struct Read {
  std::optional<ir::Program> program;
  std::optional<ConstantTable> constants;
  std::vector<uint32_t> tokens;
};

Read read_tokens(uint32_t file, ir::SourceManager& sm, ir::DiagnosticSink& diags,
                 ListingForm form) {
  Read out;
  auto tokens = read_token_file(sm.files[file].text, diags, file);
  // A raw stream has no lines to quote; a C array keeps its text for the scanner's own
  // line:col diagnostics (already reported above).
  if (form == ListingForm::TokenStream) sm.files[file].text.clear();
  if (!tokens) return out;
  out.tokens = *tokens;
  out.program = disassemble(*tokens, diags, file);
  if (out.program) out.constants = read_constant_table(*tokens, diags, file);
  return out;
}

// The program, validated unless skipped; nullopt after reporting errors to `diags`.
std::optional<ir::Program> check_program(std::optional<ir::Program> program,
                                         ir::DiagnosticSink& diags, const LoadOptions& options) {
  if (!program) return std::nullopt;
  ir::Profile profile = options.profile.value_or(program->profile);
  if (ir::stage_of(profile) != program->stage()) {
    diags.error(program->version_loc, "profile",
                fmt::format("--profile {} is a {} profile, but the listing is {}",
                            ir::profile_name(profile), ir::is_vertex(profile) ? "vertex" : "pixel",
                            ir::profile_name(program->profile)));
    return std::nullopt;
  }
  if (!options.strict) apply_windows_leniency(*program, profile, diags);
  if (!options.skip_validation && !validate_loaded(*program, options, diags)) return std::nullopt;
  return program;
}

} // namespace

bool validate_loaded(const ir::Program& program, const LoadOptions& options,
                     ir::DiagnosticSink& diags) {
  ValidateOptions vo;
  vo.warnings = options.warnings;
  vo.caps = options.caps;
  vo.windows_leniency = !options.strict;
  return validate(program, options.profile.value_or(program.profile), diags, vo);
}

Loaded load_listing(uint32_t file, ir::SourceManager& sm, const LoadOptions& options) {
  // The readers and the validator report into a sink of their own; what it holds at the end
  // becomes the program's Result, so nothing is reported twice or through a second channel.
  ir::DiagnosticSink diags;
  const ListingForm form = detect_listing_form(sm.files[file].text);
  // Text padded with NUL bytes reads as the text before them; the lines and columns of what
  // is left are unchanged.
  if (form == ListingForm::Text || form == ListingForm::TokenArray)
    sm.files[file].text.resize(without_trailing_nuls(sm.files[file].text).size());
  Read read;
  switch (form) {
  case ListingForm::Binary:
    diags.error(ir::SourceLoc{file, 0, 0, 0}, "binary-input",
                fmt::format("this is {}", describe_binary(sm.files[file].text)));
    sm.files[file].text.clear();
    break;
  case ListingForm::TokenStream:
  case ListingForm::TokenArray: read = read_tokens(file, sm, diags, form); break;
  case ListingForm::Text: {
    ParseOptions parse = options.parse;
    parse.strict = parse.strict || options.strict;
    read.program = parse_program(file, sm, diags, parse);
    break;
  }
  }
  std::optional<ir::Program> program = check_program(std::move(read.program), diags, options);
  // Every failing path above reports an error; the guard keeps a Failure from ever being
  // empty should a reader one day return nothing silently.
  if (!program && !diags.has_errors())
    diags.error(ir::SourceLoc{file, 0, 0, 0}, "internal", "the listing could not be read");
  if (!program || diags.has_errors())
    return Loaded{form, std::move(read.constants), std::move(read.tokens), ir::fail(diags)};
  ir::Result<ir::Program> ok(std::move(*program));
  for (const ir::Diagnostic& d : diags.all()) ok.add(d);
  return Loaded{form, std::move(read.constants), std::move(read.tokens), std::move(ok)};
}

} // namespace tierlift::assembly
