// `tierlift run --backend vulkan`: the same pass run_job() draws on the CPU device, built by
// cpu::pass_from_request from the same request, drawn on the Vulkan device instead.
#pragma once

#include <string>
#include <vector>

#include "tierlift/cpu/run_job.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan {

struct VulkanRunResult {
  bool ok = false;
  bool no_device = false; // no Vulkan driver/device/layer: an environment problem (exit 2)
  std::string error;
  std::string device_name;
  img::Image image;
  std::vector<cpu::ProbeValue> probes;
  double setup_ms = 0, draw_ms = 0;
};

// Errors in the request go to `diags` as in cpu::run_job; device problems to `error`.
VulkanRunResult run_job_vulkan(const cpu::RunRequest& request, cpu::RunDiagnostics& diags,
                               const DeviceOptions& options);

} // namespace tierlift::vulkan
