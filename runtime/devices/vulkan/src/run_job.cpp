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

ir::Result<VulkanRun> run_job_vulkan(const pass::RunRequest& request, pass::RunDiagnostics& diags,
                                     const DeviceOptions& options) {
  ir::Result<pass::Pass> prepared = pass::prepare_pass(request);
  pass::add_by_listing(diags, prepared.diagnostics());
  if (!prepared) return ir::fail("", "run", prepared.message());
  ir::Result<Device*> device = process_device(options);
  if (!device) return std::move(device).failure(); // kNoDeviceRule: no driver or device
  VulkanRun out;
  out.device_name = (*device)->name();
  out.image = img::Image(request.width, request.height, request.format);
  ir::Result<pass::DrawReport> r = (*device)->draw(*prepared, out.image);
  if (!r) return std::move(r).failure();
  out.setup_ms = r->setup_ms;
  out.draw_ms = r->draw_ms;
  out.probes = pass::read_probes(out.image, request.probes);
  return out;
}

} // namespace tierlift::vulkan
