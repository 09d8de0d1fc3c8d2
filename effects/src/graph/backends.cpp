// --backend: words and lists (backends.h).
#include "tierlift/effects/graph/backends.h"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "tierlift/vulkan/process_device.h"

namespace tierlift::effects {
namespace {

ir::Failure usage(std::string message) {
  return ir::fail("--backend", "usage", std::move(message));
}

bool offers(const std::vector<std::string>& offered, const std::string& way) {
  return std::find(offered.begin(), offered.end(), way) != offered.end();
}

std::string accepted(const std::vector<std::string>& offered) {
  std::string words = fmt::format("{}", fmt::join(offered, ", "));
  if (offers(offered, "cpu") && offers(offered, "vulkan")) words += ", both";
  return words + ", all, or a comma list such as " +
         fmt::format("{}", fmt::join(offered.begin(), offered.begin() + 2, ","));
}

} // namespace

ir::Result<BackendChoice> parse_backends(std::string_view text,
                                         const std::vector<std::string>& offered) {
  BackendChoice choice;
  if (text == "all") {
    choice.ways = offered;
    choice.automatic = true;
    return choice;
  }
  std::vector<std::string> named;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item(
        text.substr(start, comma == std::string_view::npos ? comma : comma - start));
    std::vector<std::string> ways;
    if (item == "both" && offers(offered, "cpu") && offers(offered, "vulkan"))
      ways = {"cpu", "vulkan"};
    else if (offers(offered, item))
      ways = {item};
    else
      return usage(fmt::format("--backend '{}': {} is not a way; expected {}", text,
                               item.empty() ? "an empty item" : "'" + item + "'",
                               accepted(offered)));
    for (const std::string& w : ways) {
      if (std::find(named.begin(), named.end(), w) != named.end())
        return usage(fmt::format("--backend '{}': {} is named twice", text, w));
      named.push_back(w);
    }
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  // Run order, whatever the order of the list: the agreement table's pairs read the same.
  for (const std::string& w : offered)
    if (std::find(named.begin(), named.end(), w) != named.end()) choice.ways.push_back(w);
  return choice;
}

ir::Result<SelectedWays> select_ways(const BackendChoice& choice,
                                     const vulkan::DeviceOptions& options) {
  SelectedWays out;
  out.ways = choice.ways;
  if (!offers(out.ways, "vulkan")) return out;
  ir::Result<vulkan::Device*> device = vulkan::process_device(options);
  if (device) {
    out.vulkan = *device;
    return out;
  }
  if (!choice.automatic)
    return ir::fail("--backend", "device",
                    fmt::format("--backend names vulkan: {}", device.message()));
  out.ways.erase(std::find(out.ways.begin(), out.ways.end(), "vulkan"));
  out.left_out_why = device.message();
  out.note = fmt::format("no Vulkan device: ran {} only ({})", fmt::join(out.ways, " and "),
                         device.message());
  return out;
}

} // namespace tierlift::effects
