// The CPU interpreter behind the one device interface (tierlift/pass/device.h): cpu::draw.
#pragma once

#include "tierlift/cpu/draw.h"
#include "tierlift/pass/device.h"

namespace tierlift::cpu {

class PassDevice final : public pass::Device {
public:
  explicit PassDevice(unsigned threads = 0) : threads_(threads) {}
  std::string name() const override { return "cpu"; }
  pass::Capabilities capabilities() const override { return kCapabilities; }
  // Errors: rule "draw" (a pass the device refuses); warning "nothing-drawn" when no
  // triangle reached the screen.
  ir::Result<pass::DrawReport> draw(const pass::Pass& pass, img::Image& target) override;

private:
  unsigned threads_;
};

} // namespace tierlift::cpu
