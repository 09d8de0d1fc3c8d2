// The Vulkan device a command draws on, for every command that takes --gpu.
#pragma once

#include <string>

#include "report.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::cli {

// The process's device for `gpu` (vulkan::process_device: kept until exit, so lavapipe stays
// loaded for LeakSanitizer), or nullptr after reporting why not as a "device" error; the
// caller then finishes with kExitUsage.
vulkan::Device* vulkan_device(const std::string& gpu, Report& report);

} // namespace tierlift::cli
