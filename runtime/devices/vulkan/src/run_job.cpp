#include "tierlift/vulkan/run_job.h"

#include <map>
#include <mutex>

namespace tierlift::vulkan {
namespace {

// One device per option set, kept for the life of the process: creating it is the slow
// part of a run, and keeping the driver loaded until exit lets LeakSanitizer attribute
// lavapipe's own process-lifetime allocations to its module (tests/lsan.supp) instead of
// to an unloaded "<unknown module>".
Device* process_device(const DeviceOptions& options, std::string* error) {
  static std::mutex mutex;
  // Held through a never-freed pointer, so the devices stay reachable at exit.
  static auto* devices = new std::map<std::pair<bool, std::string>, Device*>();
  std::lock_guard<std::mutex> lock(mutex);
  auto key = std::make_pair(options.validation, options.gpu_filter);
  if (auto it = devices->find(key); it != devices->end()) return it->second;
  std::unique_ptr<Device> device = Device::create(options, error);
  if (!device) return nullptr;
  return (*devices)[key] = device.release(); // intentionally never destroyed
}

} // namespace

VulkanRunResult run_job_vulkan(const cpu::RunRequest& request, cpu::RunDiagnostics& diags,
                               const DeviceOptions& options) {
  VulkanRunResult out;
  auto pass = cpu::pass_from_request(request, diags);
  if (!pass) return out;
  std::string error;
  Device* device = process_device(options, &error);
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
