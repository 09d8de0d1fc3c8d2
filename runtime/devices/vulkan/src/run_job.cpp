#include "tierlift/vulkan/run_job.h"

#include <map>
#include <mutex>

namespace tierlift::vulkan {

// One device per option set, kept for the life of the process: creating it is the slow
// part of a run, and keeping the driver loaded until exit lets LeakSanitizer attribute
// lavapipe's own process-lifetime allocations to its module (tests/lsan.supp) instead of
// to an unloaded "<unknown module>".
ir::Result<Device*> process_device(const DeviceOptions& options) {
  static std::mutex mutex;
  // Held through a never-freed pointer, so the devices stay reachable at exit.
  static auto* devices = new std::map<std::pair<bool, std::string>, Device*>();
  std::lock_guard<std::mutex> lock(mutex);
  auto key = std::make_pair(options.validation, options.gpu_filter);
  if (auto it = devices->find(key); it != devices->end()) return it->second;
  ir::Result<std::unique_ptr<Device>> device = Device::create(options);
  if (!device) return std::move(device).failure();
  return (*devices)[key] = device->release(); // intentionally never destroyed
}

VulkanRunResult run_job_vulkan(const pass::RunRequest& request, pass::RunDiagnostics& diags,
                               const DeviceOptions& options) {
  VulkanRunResult out;
  ir::Result<pass::Pass> prepared = pass::prepare_pass(request);
  pass::add_by_listing(diags, prepared.diagnostics());
  if (!prepared) return out;
  ir::Result<Device*> device = process_device(options);
  if (!device) {
    out.no_device = true;
    out.error = device.message();
    return out;
  }
  out.device_name = (*device)->name();
  out.image = img::Image(request.width, request.height, request.format);
  DrawResult r = (*device)->draw(*prepared, out.image);
  out.setup_ms = r.setup_ms;
  out.draw_ms = r.draw_ms;
  if (!r.ok) {
    out.error = r.error;
    return out;
  }
  out.probes = pass::read_probes(out.image, request.probes);
  out.ok = true;
  return out;
}

} // namespace tierlift::vulkan
