// Device::draw: one pass::Pass with host images in and out. The target becomes a texture for
// this draw only; the work itself is draw_pass (pass_draw.h), shared with TextureSet::draw.
#include <chrono>

#include "pass_draw.h"

namespace tierlift::vulkan {

ir::Result<pass::DrawReport> Device::draw(const pass::Pass& pass, img::Image& target) {
  if (!img::valid_size(target.width, target.height))
    return draw_failure("render target size must be 1..16384 on each side");
  if (target.rgba.size() != size_t{target.width} * target.height * 4)
    return draw_failure("render target pixel buffer does not match its size");
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Resident> rt;
  if (ir::Status err = create_resident(*impl_, target.width, target.height, target.format, rt);
      !err)
    return std::move(err).failure();
  const double create_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  DrawTextures textures;
  textures.target = rt.get();
  textures.host_target = &target;
  ir::Result<pass::DrawReport> res = draw_pass(*impl_, pass, textures);
  if (res) res->setup_ms += create_ms;
  return res;
}

} // namespace tierlift::vulkan
