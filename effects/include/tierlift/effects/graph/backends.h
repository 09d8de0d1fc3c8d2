// Which ways a command runs (`--backend`): a word (cpu, vulkan, analytic, both, all) or a
// comma list (cpu,analytic; vulkan,cpu), and what "all" becomes on a machine without Vulkan.
// Commands only parse the flag's text; the choice and its note live here.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/result.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::effects {

struct BackendChoice {
  // The ways asked for, in the order every command runs them: cpu, vulkan, analytic.
  std::vector<std::string> ways;
  // "all": every offered way the machine has; Vulkan is left out, with a note, when no
  // device can be created. Anything else names its ways, and a missing Vulkan is an error.
  bool automatic = false;
};

// `text`: one word or a comma list; `offered`: the ways the command has, in run order
// (glow: cpu, vulkan, analytic; run: cpu, vulkan). "both" is cpu and vulkan; "all" is every
// offered way. An unknown or repeated name, or an empty item, is an error that names the
// accepted words.
ir::Result<BackendChoice> parse_backends(std::string_view text,
                                         const std::vector<std::string>& offered);

// The ways that will run, the Vulkan device when one of them is vulkan, and what was left
// out. A failure is an explicit vulkan without a device, in words (rule "device").
struct SelectedWays {
  std::vector<std::string> ways;
  vulkan::Device* vulkan = nullptr;
  // Under "all" without a device: "no Vulkan device: ran cpu and analytic only (why)".
  std::string note;
  std::string left_out_why; // the device's own reason, for the JSON
};
ir::Result<SelectedWays> select_ways(const BackendChoice& choice,
                                     const vulkan::DeviceOptions& options);

} // namespace tierlift::effects
