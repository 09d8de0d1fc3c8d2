// Device::draw: one pass::Pass with host images in and out. The target becomes a texture for
// this draw only; the work itself is draw_pass (pass_draw.h), shared with TextureSet::draw.
#include <chrono>

#include "pass_draw.h"

namespace tierlift::vulkan {

DrawResult Device::draw(const pass::Pass& pass, img::Image& target) {
  DrawResult res;
  if (target.width == 0 || target.height == 0 || target.width > img::kMaxDimension ||
      target.height > img::kMaxDimension) {
    res.error = "render target size must be 1..16384 on each side";
    return res;
  }
  if (target.rgba.size() != size_t{target.width} * target.height * 4) {
    res.error = "render target pixel buffer does not match its size";
    return res;
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::unique_ptr<Resident> rt;
  if (std::string err = create_resident(*impl_, target.width, target.height, target.format, rt);
      !err.empty()) {
    res.error = err;
    return res;
  }
  const double create_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  DrawTextures textures;
  textures.target = rt.get();
  textures.host_target = &target;
  res = draw_pass(*impl_, pass, textures);
  res.setup_ms += create_ms;
  return res;
}

} // namespace tierlift::vulkan
