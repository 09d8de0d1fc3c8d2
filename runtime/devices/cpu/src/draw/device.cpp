// cpu::PassDevice: cpu::draw behind the device interface, timed.
#include "tierlift/cpu/device.h"

#include <chrono>

namespace tierlift::cpu {

ir::Result<pass::DrawReport> PassDevice::draw(const pass::Pass& pass, img::Image& target) {
  const auto t0 = std::chrono::steady_clock::now();
  ir::Result<DrawStats> stats = cpu::draw(pass, target, threads_);
  pass::DrawReport report;
  report.draw_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!stats) return std::move(stats).failure(); // rule kDrawRule ("draw"), no subject
  report.pixels_shaded = stats->pixels_shaded;
  report.pixels_killed = stats->pixels_killed;
  ir::Result<pass::DrawReport> out(report);
  if (stats->triangles == 0)
    out.add({ir::Severity::Warning,
             {},
             "no triangle reached the screen (the vertex listing's oPos "
             "is degenerate, behind the eye or clipped away): the image is empty",
             "nothing-drawn",
             ""});
  return out;
}

} // namespace tierlift::cpu
