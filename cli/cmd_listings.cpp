// tierlift listings: the main job until the glow lands — check every built-in listing
// (the article's Listings 1–4) and print it in canonical form.
#include <fmt/format.h>

#include "commands.h"
#include "tierlift/asm/parser.h"
#include "tierlift/asm/printer.h"
#include "tierlift/asm/validator.h"
#include "tierlift/ir/profile.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::cli {

void register_listings_command(CLI::App& app) {
  auto quiet = std::make_shared<bool>(false);
  CLI::App* sub = app.add_subcommand(
      "listings", "Check the built-in listings (GPU Gems ch. 21 Listings 1-4) and print them");
  sub->add_flag("-q,--quiet", *quiet, "Only the verdict line of each listing");
  set_action(sub, [quiet] {
    int result = kExitOk;
    for (const auto& l : listings::embedded_listings()) {
      auto parsed = as::parse_text(std::string(l.text), "listings/" + std::string(l.path));
      bool ok = parsed.program && as::validate(*parsed.program, parsed.diags);
      std::fputs(ir::render_text(parsed.diags, parsed.sources).c_str(), stderr);
      if (!ok) {
        fmt::print("listings/{}: INVALID\n", l.path);
        result = kExitInvalid;
        continue;
      }
      fmt::print("listings/{}: ok ({}, {} instructions)\n", l.path,
                 ir::profile_name(parsed.program->profile), parsed.program->code.size());
      if (!*quiet) fmt::print("{}\n", as::print_program(*parsed.program));
    }
    return result;
  });
}

} // namespace tierlift::cli
