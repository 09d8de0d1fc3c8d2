// The Vulkan device behind the PassDevice interface (built only with tierlift_vulkan).
#include "tierlift/effects/device.h"

#if TIERLIFT_HAVE_VULKAN
#include "tierlift/vulkan/device.h"

namespace tierlift::effects {
namespace {

class VulkanPassDevice final : public PassDevice {
public:
  explicit VulkanPassDevice(vulkan::Device& device) : device_(device) {}
  std::string name() const override { return "vulkan"; }
  std::string draw(const cpu::Pass& pass, img::Image& target) override {
    vulkan::DrawResult r = device_.draw(pass, target);
    return r.ok ? std::string() : r.error;
  }

private:
  vulkan::Device& device_;
};

} // namespace

std::unique_ptr<PassDevice> make_vulkan_pass_device(vulkan::Device& device) {
  return std::make_unique<VulkanPassDevice>(device);
}

} // namespace tierlift::effects
#endif
