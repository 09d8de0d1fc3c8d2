// tierlift check FILE...: parse and validate listings; exit 0 all valid, 1 any invalid,
// 2 usage or I/O error.
#include <fmt/format.h>

#include "commands.h"
#include "front_end.h"
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
    int worst = kExitOk;
    nlohmann::json report = nlohmann::json::array();
    for (const std::string& path : opts->files) {
      LoadedListing l = load_listing(path, opts->fe);
      if (l.io_error) {
        fmt::print(stderr, "tierlift: error: {}\n", l.io_message);
        worst = kExitUsage;
        report.push_back({{"file", path}, {"valid", false}, {"error", l.io_message}});
        continue;
      }
      bool valid = l.program.has_value() && !l.diags.has_errors();
      if (!valid && worst == kExitOk) worst = kExitInvalid;
      if (opts->fe.json) {
        nlohmann::json entry = {
            {"file", path}, {"valid", valid}, {"diagnostics", diagnostics_json(l)}};
        if (l.program) entry["profile"] = ir::profile_name(l.program->profile);
        entry["form"] = as::listing_form_name(l.form);
        if (l.constants) entry["constants"] = constants_json(*l.constants);
        report.push_back(std::move(entry));
      } else {
        print_diagnostics(l);
        if (valid)
          fmt::print("{}: ok ({}, {} instructions{})\n", path, ir::profile_name(l.program->profile),
                     l.program->code.size(),
                     l.diags.warning_count() ? fmt::format(", {} warnings", l.diags.warning_count())
                                             : std::string());
      }
    }
    if (opts->fe.json) fmt::print("{}\n", report.dump(2));
    return worst;
  });
}

} // namespace tierlift::cli
