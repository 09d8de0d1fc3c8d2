#include "tierlift/effects/glow/builtin_listing.h"

#include <fmt/format.h>

#include "tierlift/assembly/load.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/result_diagnostics.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::effects {

namespace {

// Text or a D3D9 token stream (raw or a C array), told apart by content: a scene's
// "listings" may name a .pso/.vso as well as a .psh/.vsh (assembly::load_listing).
ListingResult parse_and_validate(std::string text, std::string name, bool allow_include,
                                 const ListingOptions& listing) {
  ir::SourceManager sources;
  uint32_t file = sources.add(std::move(name), std::move(text));
  assembly::LoadOptions options;
  options.parse.defines = listing.defines;
  options.parse.include_dirs = listing.include_dirs;
  options.parse.allow_include = allow_include; // built-in text never reads files
  options.skip_validation = listing.skip_validation;
  options.strict = listing.strict;
  options.warnings = false; // Listing 1 declares inputs it never reads; that is the article's
  if (listing.profile) {
    // --profile checks the listings of its own stage only: every pass has one of each. The
    // stage is known once the listing is read, so read it first without validating.
    ir::SourceManager probe_sources = sources;
    assembly::LoadOptions probe = options;
    probe.skip_validation = true;
    assembly::Loaded p = assembly::load_listing(file, probe_sources, probe);
    if (p.program && ir::stage_of(*listing.profile) == p.program->stage())
      options.profile = listing.profile;
  }
  assembly::Loaded r = assembly::load_listing(file, sources, options);
  if (!r.program)
    return ir::fail(sources.files[file].name, "listing",
                    ir::render_text(r.program.diagnostics(), sources));
  // Every effect pass runs on the interpreter and on Vulkan: a 2.x / 3.0 listing is read
  // but cannot run yet, and is refused here with its position.
  if (ir::Status s = ir::check_executable(*r.program, "the interpreter or SPIR-V"); !s)
    return ir::fail(sources.files[file].name, "listing", ir::render_text(s.diagnostics(), sources));
  return std::make_shared<const ir::Program>(std::move(r.program).value());
}

} // namespace

ListingResult builtin_listing(std::string_view path, const ListingOptions& options) {
  std::optional<std::string_view> text = listings::find_embedded(path);
  if (!text)
    return ir::fail(std::string(path), "listing", fmt::format("no built-in listing '{}'", path));
  return parse_and_validate(std::string(*text), std::string(path), false, options);
}

ListingResult glow_listing(std::string_view path,
                           const std::map<std::string, std::string, std::less<>>& files,
                           const ListingOptions& options) {
  auto it = files.find(path);
  if (it == files.end()) return builtin_listing(path, options);
  ir::Result<std::string> text = io::read_bounded(it->second, io::kListingCap);
  if (!text) {
    // "PATH: why" → "PATH: error: why", the form of the other diagnostics.
    std::string why = text.message();
    const std::string head = it->second + ": ";
    if (why.starts_with(head)) why.erase(0, head.size());
    return ir::fail(
        it->second, "io",
        fmt::format("{}: error: {} (it replaces built-in '{}')", it->second, why, path));
  }
  // A UTF-8 byte-order mark is not part of the text; a token stream is read as it stands.
  if (text->starts_with("\xEF\xBB\xBF")) text->erase(0, 3);
  return parse_and_validate(std::move(*text), it->second, true, options);
}

} // namespace tierlift::effects
