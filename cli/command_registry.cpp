#include <map>

#include <fmt/format.h>

#include "commands.h"
#include "report.h"
#include "tierlift/effects/graph/memory_plan.h"

namespace tierlift::cli {
namespace {
std::map<const CLI::App*, std::function<int()>>& actions() {
  static std::map<const CLI::App*, std::function<int()>> m;
  return m;
}
// The commands that plan memory against TIERLIFT_MEMORY_LIMIT (effects/memory_plan.h).
bool plans_memory(const std::string& command) {
  return command == "glow" || command == "run" || command == "report";
}

// Whether the parsed subcommand was given --json (an error before its action runs says so
// in the same one document).
bool json_requested(const CLI::App* sub) {
  const CLI::Option* json = sub->get_option_no_throw("--json");
  return json && json->count() > 0;
}
} // namespace

void set_action(CLI::App* sub, std::function<int()> action) {
  actions()[sub] = std::move(action);
}

void refuse_empty_outputs(CLI::App& app) {
  const CLI::Validator non_empty(
      [](std::string& value) {
        return value.empty() ? std::string("an empty file name (give a file, or '-' where the "
                                           "command writes standard output)")
                             : std::string();
      },
      "", "non-empty");
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    if (CLI::Option* output = sub->get_option_no_throw("--output")) output->check(non_empty);
}

int run_selected(CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) {
    auto it = actions().find(sub);
    if (it == actions().end()) continue;
    if (plans_memory(sub->get_name()))
      if (auto limit = effects::memory_limit_from_env(); !limit) {
        Report report(sub->get_name(), json_requested(sub));
        report.error("usage", limit.message());
        return report.finish(kExitUsage);
      }
    return it->second();
  }
  fmt::print(stderr, "tierlift: error: no command given\n\n{}", app.help());
  return kExitUsage;
}

} // namespace tierlift::cli
