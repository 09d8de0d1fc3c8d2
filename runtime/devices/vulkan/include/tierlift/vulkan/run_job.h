// `tierlift run` on the Vulkan device as a library: the pass pass::prepare_pass made (the
// same one the CPU device draws), drawn by Device::draw. The CLI draws it through the effect
// graph's device interface instead (effects/single_pass.h).
#pragma once

#include <string>
#include <vector>

#include "tierlift/pass/setup.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan {

// The process's device for `options`: created on first use and kept until exit (creating it
// is the slow part of a run). A failure is Device::create's (rule kNoDeviceRule or
// kDeviceRule): no Vulkan driver, device or layer, an environment problem rather than a fault
// of the pass.
ir::Result<Device*> process_device(const DeviceOptions& options);

// What run_job_vulkan drew.
struct VulkanRun {
  std::string device_name;
  img::Image image;
  std::vector<pass::ProbeValue> probes;
  double setup_ms = 0, draw_ms = 0;
};

// prepare_pass (errors in the request go to `diags`), then the pass drawn into a new target
// of the request's size and format on process_device(options). A failure is one of: the
// request's first error (rule "run"; its diagnostics are in `diags`); the device's, as
// process_device returns it (rule kNoDeviceRule or kDeviceRule: no Vulkan driver, device or
// layer, an environment problem, exit 2 in the CLI); the draw's (rule kDrawRule).
ir::Result<VulkanRun> run_job_vulkan(const pass::RunRequest& request, pass::RunDiagnostics& diags,
                                     const DeviceOptions& options);

} // namespace tierlift::vulkan
