#include "tierlift/effects/builtin_listing.h"

#include <fmt/format.h>

#include "tierlift/asm/parser.h"
#include "tierlift/asm/validator.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::effects {

namespace {

std::shared_ptr<const ir::Program> parse_and_validate(std::string text, std::string name,
                                                      bool allow_include,
                                                      const ListingOptions& listing,
                                                      std::string* error) {
  auto fail = [&](std::string why) -> std::shared_ptr<const ir::Program> {
    if (error) *error = std::move(why);
    return nullptr;
  };
  as::ParseOptions options;
  options.defines = listing.defines;
  options.include_dirs = listing.include_dirs;
  options.allow_include = allow_include; // built-in text never reads files
  as::ParseResult r = as::parse_text(std::move(text), std::move(name), options);
  if (!r.program) return fail(ir::render_text(r.diags, r.sources));
  if (listing.skip_validation) return std::make_shared<const ir::Program>(std::move(*r.program));
  ir::Profile target = r.program->profile;
  if (listing.profile && ir::stage_of(*listing.profile) == r.program->stage())
    target = *listing.profile;
  ir::DiagnosticSink diags;
  as::ValidateOptions vo;
  vo.warnings = false; // Listing 1 declares inputs it never reads; that is the article's text
  if (!as::validate(*r.program, target, diags, vo)) return fail(ir::render_text(diags, r.sources));
  return std::make_shared<const ir::Program>(std::move(*r.program));
}

} // namespace

std::shared_ptr<const ir::Program> builtin_listing(std::string_view path, std::string* error,
                                                   const ListingOptions& options) {
  std::optional<std::string_view> text = listings::find_embedded(path);
  if (!text) {
    if (error) *error = fmt::format("no built-in listing '{}'", path);
    return nullptr;
  }
  return parse_and_validate(std::string(*text), std::string(path), false, options, error);
}

std::shared_ptr<const ir::Program>
glow_listing(std::string_view path, const std::map<std::string, std::string, std::less<>>& files,
             std::string* error, const ListingOptions& options) {
  auto it = files.find(path);
  if (it == files.end()) return builtin_listing(path, error, options);
  std::string why;
  std::optional<std::string> text = io::read_bounded(it->second, io::kListingCap, why);
  if (!text) {
    // "PATH: why" → "PATH: error: why", the form of the other diagnostics.
    const std::string head = it->second + ": ";
    if (why.starts_with(head)) why.erase(0, head.size());
    if (error)
      *error = fmt::format("{}: error: {} (it replaces built-in '{}')", it->second, why, path);
    return nullptr;
  }
  if (text->starts_with("\xEF\xBB\xBF")) text->erase(0, 3); // a UTF-8 byte-order mark
  return parse_and_validate(std::move(*text), it->second, true, options, error);
}

} // namespace tierlift::effects
