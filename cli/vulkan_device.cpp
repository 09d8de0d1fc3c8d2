#include "vulkan_device.h"

#include "tierlift/vulkan/process_device.h"

namespace tierlift::cli {

vulkan::Device* vulkan_device(const std::string& gpu, Report& report) {
  vulkan::DeviceOptions options;
  options.gpu_filter = gpu;
  ir::Result<vulkan::Device*> device = vulkan::process_device(options);
  if (!device) {
    report.error("device", device.message());
    return nullptr;
  }
  return *device;
}

} // namespace tierlift::cli
