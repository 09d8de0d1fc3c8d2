// The Vulkan device a front end hands to the libraries that draw (glow, report, stress,
// GLSL passes, pixel traces): the one place outside the device's own library that creates one,
// so that no front end includes a device's header.
#pragma once

#include <string>

#include "tierlift/ir/result.h"

namespace tierlift::vulkan {
class Device;
}

namespace tierlift::effects {

// The process's Vulkan device on the GPU whose name contains `gpu` (empty: the first), kept
// until exit (vulkan::process_device: lavapipe stays loaded for LeakSanitizer), or why there
// is none (vulkan::kDeviceRule or kNoDeviceRule: the machine's problem, not the input's).
ir::Result<vulkan::Device*> vulkan_device(const std::string& gpu);
// The physical device's name ("llvmpipe (LLVM 15.0.6, 256 bits)"), for a front end's report.
std::string vulkan_device_name(const vulkan::Device& device);

} // namespace tierlift::effects
