// `tierlift run --backend vulkan`: the Vulkan device behind the one device interface
// (tierlift/pass/device.h), drawing the pass pass::prepare_pass made (the same one the CPU
// device draws).
#pragma once

#include <string>
#include <vector>

#include "tierlift/pass/device.h"
#include "tierlift/pass/setup.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan {

// The process's device for `options`: created on first use and kept until exit (creating it
// is the slow part of a run). A failure is Device::create's (rule kNoDeviceRule or
// kDeviceRule): no Vulkan driver, device or layer, an environment problem rather than a fault
// of the pass.
ir::Result<Device*> process_device(const DeviceOptions& options);

class PassDevice final : public pass::Device {
public:
  explicit PassDevice(vulkan::Device& device) : device_(device) {}
  std::string name() const override { return "vulkan"; }
  pass::Capabilities capabilities() const override { return kCapabilities; }
  // Errors: rule "vulkan", the message starting "vulkan: ".
  ir::Result<pass::DrawReport> draw(const pass::Pass& pass, img::Image& target) override;
  vulkan::Device& device() { return device_; }

private:
  // Spelled out: inside this class, plain `Device` names the base pass::Device.
  vulkan::Device& device_;
};

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
