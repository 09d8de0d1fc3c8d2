// One listing from the bytes of a file, whatever its form: assembly text, or a Direct3D 9
// token stream — raw (.bin, .fxo, .vso/.pso as fxc and D3DX write them) or a C array as fxc
// /Fh writes it — told apart by content, never by the file's extension. Every command that
// takes a listing (check, fmt, spirv, run, the scenes' "listings") reads it through here.
//
// Diagnostics on a token stream name the byte offset of the token ("shader.pso:+0x1c:
// error: …"). A file that is neither (a PNG, a D3D10+ DXBC container, an fx_2_0 effect)
// gets one line saying what it looks like and which command takes it (rule binary-input).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/assembly/constant_table.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"
#include "tierlift/ir/source.h"

namespace tierlift::assembly {

enum class ListingForm {
  Text,        // shader assembly
  TokenStream, // raw little-endian DWORDs starting with a version token
  TokenArray,  // C source holding the DWORDs (or bytes) of a token stream
  Binary,      // something else that is not text
};
std::string_view listing_form_name(ListingForm form); // "text", "token stream", ...

// `bytes` without the run of NUL bytes at its end that some tools pad text files with.
std::string_view without_trailing_nuls(std::string_view bytes);

// The form of `bytes`. A C array counts as a TokenArray only when its first value is a
// version token (0xFFFE…/0xFFFF…); anything else that is text is Text.
ListingForm detect_listing_form(std::string_view bytes);

// For ListingForm::Binary: "a PNG image; `tierlift glow --image` and `run --texture` take
// it" and the like.
std::string describe_binary(std::string_view bytes);

struct LoadOptions {
  ParseOptions parse;                 // text only: -D, -I
  std::optional<ir::Profile> profile; // validate against this instead of the version's
  std::optional<ir::Caps2x> caps;     // 2.x features to validate against (fxc's ps_2_a ...)
  bool skip_validation = false;
  // false: apply_windows_leniency (validator.h) before validating — what Windows took is
  // taken, with a warning. true: the documented rules only.
  bool strict = false;
  bool warnings = true; // ValidateOptions::warnings (legal-but-suspicious code)
};

// What loading one listing gives. Not a Result<Listing>: `check` and `disasm` report the
// form, and a token stream's CTAB, of a listing that then fails to disassemble or validate,
// so those are known whatever happens to the program. Only the program can be missing, and
// its Result carries every diagnostic of the load: the errors when it is missing, warnings
// (Windows leniency, the CTAB) beside it when it is there.
struct Loaded {
  ListingForm form = ListingForm::Text;
  std::optional<ConstantTable> constants; // a token stream's CTAB comment
  std::vector<uint32_t> tokens;           // a token stream's tokens
  ir::Result<ir::Program> program;        // read (and validated, unless skipped)
};

// Reads sm.files[file] (its text holds the file's bytes). For a raw token stream the stored
// text is emptied afterwards: its diagnostics carry byte offsets, never lines to quote.
Loaded load_listing(uint32_t file, ir::SourceManager& sm, const LoadOptions& options = {});

// The validation load_listing runs on the program it read (against options.profile or the
// program's own, with options.caps and options.warnings, Windows' leniency taken unless
// strict), for a program loaded with skip_validation and validated later (`tierlift test`
// reads a listing once and validates it as a stage of its own). options.skip_validation is
// not looked at. True when no error was reported.
bool validate_loaded(const ir::Program& program, const LoadOptions& options,
                     ir::DiagnosticSink& diags);

} // namespace tierlift::assembly
