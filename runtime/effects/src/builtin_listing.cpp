#include "tierlift/effects/builtin_listing.h"

#include <fmt/format.h>

#include "tierlift/asm/parser.h"
#include "tierlift/asm/validator.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::effects {

std::shared_ptr<const ir::Program> builtin_listing(std::string_view path, std::string* error) {
  auto fail = [&](std::string why) -> std::shared_ptr<const ir::Program> {
    if (error) *error = std::move(why);
    return nullptr;
  };
  std::optional<std::string_view> text = listings::find_embedded(path);
  if (!text) return fail(fmt::format("no built-in listing '{}'", path));
  as::ParseOptions options;
  options.allow_include = false; // built-in text never reads files
  as::ParseResult r = as::parse_text(std::string(*text), std::string(path), options);
  if (!r.program) return fail(ir::render_text(r.diags, r.sources));
  ir::DiagnosticSink diags;
  as::ValidateOptions vo;
  vo.warnings = false; // Listing 1 declares inputs it never reads; that is the article's text
  if (!as::validate(*r.program, r.program->profile, diags, vo))
    return fail(ir::render_text(diags, r.sources));
  return std::make_shared<const ir::Program>(std::move(*r.program));
}

} // namespace tierlift::effects
