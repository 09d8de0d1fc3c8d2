// tierlift listings: check every built-in listing (the article's Listings 1–4) and print it
// in canonical form.
#include <fmt/format.h>

#include "commands.h"
#include "report.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/effects/glow/stage_states.h"
#include "tierlift/ir/profile.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::cli {

void register_listings_command(CLI::App& app) {
  struct Opts {
    bool quiet = false, json = false;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand(
      "listings", "Check the built-in listings (GPU Gems ch. 21 Listings 1-4) and print them");
  sub->add_flag("-q,--quiet", opts->quiet, "Only the verdict line of each listing");
  sub->add_flag("--json", opts->json,
                "Print one JSON document on standard output (docs/command-line.md)");
  set_action(sub, [opts] {
    Report report("listings", opts->json);
    int result = kExitOk;
    nlohmann::json entries = nlohmann::json::array();
    for (const auto& l : listings::embedded_listings()) {
      if (l.path.ends_with(".frag")) continue; // GLSL (glsl/), not assembly: tierlift/glsl reads it
      const std::string path = "listings/" + std::string(l.path);
      if (path.ends_with(".tss")) { // texture-stage states: validated and lowered
        ir::Result<effects::tss::Lowered> lowered =
            effects::tss::load_stage_states(std::string(l.text), path);
        nlohmann::json entry = {{"file", path}, {"valid", lowered.ok()}};
        if (!lowered) {
          if (!report.json()) fmt::print(stderr, "{}", lowered.message());
          if (!report.json()) fmt::print("{}: INVALID\n", path);
          entries.push_back(std::move(entry));
          result = kExitInvalid;
          continue;
        }
        entry["profile"] = "tss";
        if (!opts->quiet) entry["text"] = lowered->vs_text + lowered->ps_text;
        entries.push_back(std::move(entry));
        if (report.json()) continue;
        fmt::print("{}: ok (texture-stage states, {} texture stages; lowered to vs_1_1 + "
                   "ps_1_1)\n",
                   path, lowered->texture_stages);
        if (!opts->quiet) fmt::print("{}{}\n", lowered->vs_text, lowered->ps_text);
        continue;
      }
      auto parsed = assembly::parse_text(std::string(l.text), path);
      bool ok = parsed.program && assembly::validate(*parsed.program, parsed.diags);
      report.diagnostics(parsed.diags, parsed.sources);
      nlohmann::json entry = {{"file", path}, {"valid", ok}};
      if (!ok) {
        if (!report.json()) fmt::print("{}: INVALID\n", path);
        entries.push_back(std::move(entry));
        result = kExitInvalid;
        continue;
      }
      entry["profile"] = ir::profile_name(parsed.program->profile);
      entry["instructions"] = parsed.program->code.size();
      std::string text = assembly::print_program(*parsed.program);
      if (!opts->quiet) entry["text"] = text;
      entries.push_back(std::move(entry));
      if (report.json()) continue;
      fmt::print("{}: ok ({}, {} instructions)\n", path, ir::profile_name(parsed.program->profile),
                 parsed.program->code.size());
      if (!opts->quiet) fmt::print("{}\n", text);
    }
    report.result()["listings"] = std::move(entries);
    return report.finish(result);
  });
}

} // namespace tierlift::cli
