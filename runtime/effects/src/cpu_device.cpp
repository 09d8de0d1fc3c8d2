#include "tierlift/cpu/draw.h"
#include "tierlift/effects/device.h"

namespace tierlift::effects {

std::string CpuPassDevice::draw(const cpu::Pass& pass, img::Image& target) {
  cpu::DrawStats s = cpu::draw(pass, target, threads_);
  return s.ok ? std::string() : s.error;
}

} // namespace tierlift::effects
