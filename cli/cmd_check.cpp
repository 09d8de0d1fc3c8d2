// tierlift check FILE...: parse and validate listings; exit 0 all valid, 1 any invalid,
// 2 usage or I/O error.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
#include "report.h"
#include "tierlift/ir/profile.h"

namespace tierlift::cli {

void register_check_command(CLI::App& app) {
  struct Opts {
    std::vector<std::string> files;
    FrontEndOptions fe;
  };
  auto opts = std::make_shared<Opts>();
  CLI::App* sub = app.add_subcommand("check", "Parse and validate listings against their profile");
  sub->add_option("files", opts->files, "Listings to check ('-' reads standard input)")->required();
  add_front_end_options(sub, opts->fe, false);
  set_action(sub, [opts] {
    Report report("check", opts->fe.json);
    int worst = kExitOk;
    nlohmann::json files = nlohmann::json::array();
    for (const std::string& path : opts->files) {
      ir::Result<LoadedListing> loaded = load_listing(path, opts->fe);
      if (!loaded) {
        report.error("io", loaded.message(), path);
        worst = kExitUsage;
        files.push_back({{"file", path}, {"valid", false}});
        continue;
      }
      LoadedListing& l = *loaded;
      bool valid = l.program.has_value() && !l.diags.has_errors();
      if (!valid && worst == kExitOk) worst = kExitInvalid;
      report.diagnostics(l.diags, l.sources);
      nlohmann::json entry = {{"file", path}, {"valid", valid}};
      entry["form"] = assembly::listing_form_name(l.form);
      if (l.program) {
        entry["profile"] = ir::profile_name(l.program->profile);
        entry["instructions"] = l.program->code.size();
      }
      if (l.constants) entry["constants"] = constants_json(*l.constants);
      files.push_back(std::move(entry));
      if (valid && !report.json())
        fmt::print("{}: ok ({}, {} instructions{})\n", path, ir::profile_name(l.program->profile),
                   l.program->code.size(),
                   l.diags.warning_count() ? fmt::format(", {} warnings", l.diags.warning_count())
                                           : std::string());
    }
    report.result()["files"] = std::move(files);
    return report.finish(worst);
  });
}

} // namespace tierlift::cli
