#include <map>

#include <fmt/format.h>

#include "commands.h"

namespace tierlift::cli {
namespace {
std::map<const CLI::App*, std::function<int()>>& actions() {
  static std::map<const CLI::App*, std::function<int()>> m;
  return m;
}
} // namespace

void set_action(CLI::App* sub, std::function<int()> action) {
  actions()[sub] = std::move(action);
}

int run_selected(CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) {
    auto it = actions().find(sub);
    if (it != actions().end()) return it->second();
  }
  fmt::print(stderr, "tierlift: error: no command given\n\n{}", app.help());
  return kExitUsage;
}

} // namespace tierlift::cli
