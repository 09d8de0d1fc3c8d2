// Internal: the one draw both public paths share. Device::draw (host images in, host image
// out) and TextureSet::draw (textures that stay on the device) differ only in where the
// sampled textures and the target come from; programs, geometry, descriptors, pipeline,
// barriers and the render pass are this function's.
#pragma once

#include <array>

#include "resident.h"
#include "tierlift/cpu/draw.h"

namespace tierlift::vulkan {

struct DrawTextures {
  // The texture each sampler stage reads. nullptr: the pass's own host image for that stage
  // (pass.textures[s].image, uploaded as R32G32B32A32_SFLOAT for this draw only), or the
  // unbound texture (0, 0, 0, 1) when it has none.
  std::array<Resident*, cpu::kMaxSamplers> stages{};
  Resident* target = nullptr;
  // Device::draw: the target's starting contents, uploaded before the draw (setup), and
  // where the result is read back to after it (in the same submit as the draw). Must have
  // the target's size and format. nullptr: the target stays on the device.
  img::Image* host_target = nullptr;
};

// Draws `pass` into textures.target. On failure nothing was submitted that changes any
// texture, and host_target is unchanged.
DrawResult draw_pass(Device::Impl& d, const cpu::Pass& pass, const DrawTextures& textures,
                     const DrawOptions& options);

} // namespace tierlift::vulkan
