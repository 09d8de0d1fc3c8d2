#include "tierlift/vulkan/run_job.h"

namespace tierlift::vulkan {

VulkanRunResult run_job_vulkan(const cpu::RunRequest& request, cpu::RunDiagnostics& diags,
                               const DeviceOptions& options) {
  VulkanRunResult out;
  auto pass = cpu::pass_from_request(request, diags);
  if (!pass) return out;
  std::string error;
  auto device = Device::create(options, &error);
  if (!device) {
    out.no_device = true;
    out.error = error;
    return out;
  }
  out.device_name = device->name();
  out.image = img::Image(request.width, request.height, request.format);
  DrawResult r = device->draw(*pass, out.image);
  out.setup_ms = r.setup_ms;
  out.draw_ms = r.draw_ms;
  if (!r.ok) {
    out.error = r.error;
    return out;
  }
  for (const cpu::ProbePoint& p : request.probes) {
    const float* px = out.image.at(p.x, p.y);
    out.probes.push_back({p.x, p.y, {px[0], px[1], px[2], px[3]}});
  }
  out.ok = true;
  return out;
}

} // namespace tierlift::vulkan
