#include "tierlift/vulkan/process_device.h"

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

} // namespace tierlift::vulkan
