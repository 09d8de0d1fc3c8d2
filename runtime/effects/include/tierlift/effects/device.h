// What runs one pass of an effect graph: the CPU device (cpu::draw) or the Vulkan device
// (vulkan::Device::draw). Both take the same cpu::Pass.
#pragma once

#include <memory>
#include <string>

#include "tierlift/cpu/draw.h"
#include "tierlift/image/image.h"

namespace tierlift::vulkan {
class Device;
}

namespace tierlift::effects {

class PassDevice {
public:
  virtual ~PassDevice() = default;
  virtual std::string name() const = 0; // "cpu", "vulkan"
  // Draws into `target` (its format is the store rule). Empty string on success, else why.
  virtual std::string draw(const cpu::Pass& pass, img::Image& target) = 0;
};

class CpuPassDevice final : public PassDevice {
public:
  explicit CpuPassDevice(unsigned threads = 0) : threads_(threads) {}
  std::string name() const override { return "cpu"; }
  std::string draw(const cpu::Pass& pass, img::Image& target) override;

private:
  unsigned threads_;
};

// Wraps a device the caller owns (and keeps alive). Only when tierlift_vulkan is built.
std::unique_ptr<PassDevice> make_vulkan_pass_device(vulkan::Device& device);

} // namespace tierlift::effects
