// What a text file that is no token stream is, for the commands that want one (`disasm`):
// "assembly text" is the wrong word for an empty file or for a C array that does not read.
#pragma once

#include <string>
#include <string_view>

#include "tierlift/ir/diagnostic.h"

namespace tierlift::assembly {

// For a file detect_listing_form calls ListingForm::Text: "an empty file" (nothing but white
// space), "a C array that does not hold a token stream" (braces, or a first word that is a
// number, as fxc /Fh and hand-written arrays start; why is added to `why`, positioned in
// `file`), or "" when it reads as assembly text.
std::string describe_text_form(std::string_view bytes, ir::DiagnosticSink& why, uint32_t file = 0);

} // namespace tierlift::assembly
