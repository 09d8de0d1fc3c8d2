// The one interface a device draws a pass through. The CPU interpreter (cpu::PassDevice,
// tierlift/cpu/device.h) and the Vulkan device (vulkan::PassDevice, tierlift/vulkan/
// run_job.h) implement it; `tierlift run` prepares one pass (setup.h) and hands it to each
// device it was asked for, the same code path for both. The effect graph's devices
// (effects/device.h) keep their textures resident between passes on top of this.
#pragma once

#include <cstdint>
#include <string>

#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"

namespace tierlift::pass {

// What a draw took, for the report; counters a device does not keep stay 0.
struct DrawReport {
  double setup_ms = 0; // programs, pipelines, uploads
  double draw_ms = 0;  // the draw itself (and, on a GPU, the readback)
  uint64_t pixels_shaded = 0, pixels_killed = 0;
};

class Device {
public:
  virtual ~Device() = default;
  // "cpu", "vulkan": the word the device's own diagnostics and reports use.
  virtual std::string name() const = 0;
  // What the device draws beyond one colour target with programmable stages; a pass asking
  // for more is refused by draw (check_supported).
  virtual Capabilities capabilities() const = 0;
  // Draws `pass` into `target`: its format is the store rule, its current pixels are the
  // destination blending reads. On failure the target is unchanged. A success may carry
  // warnings (e.g. nothing reached the screen).
  virtual ir::Result<DrawReport> draw(const Pass& pass, img::Image& target) = 0;
};

} // namespace tierlift::pass
