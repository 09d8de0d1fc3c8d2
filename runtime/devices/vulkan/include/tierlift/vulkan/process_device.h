// The process's Vulkan device: made once per option set and kept until the process exits.
#pragma once

#include "tierlift/ir/result.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan {

// The process's device for `options`: created on first use and kept until exit (creating it
// is the slow part of a run). A failure is Device::create's (rule kNoDeviceRule or
// kDeviceRule): no Vulkan driver, device or layer, an environment problem rather than a fault
// of the pass.
ir::Result<Device*> process_device(const DeviceOptions& options);

} // namespace tierlift::vulkan
