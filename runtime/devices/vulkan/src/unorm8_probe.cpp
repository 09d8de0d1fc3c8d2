// Reading every RGBA8 level once (unorm8_probe.h).
#include "unorm8_probe.h"

#include "synthetic_programs.h"
#include "tierlift/rounding/rounding.h"
#include "tierlift/vulkan/texture_set.h"

namespace tierlift::vulkan {

ir::Result<std::vector<float>> read_unorm8_levels(Device& device) {
  constexpr uint32_t kSide = 16; // 256 texels
  img::Image levels(kSide, kSide, img::Format::RGBA8);
  for (uint32_t p = 0; p < kSide * kSide; ++p)
    for (uint32_t c = 0; c < 4; ++c)
      levels.rgba[p * 4 + c] = rounding::unorm8_levels()[(p + 64 * c) % 256];

  // Pixel (i, j) reads texel (i, j) at its centre, in place (undecoded while probing).
  const pass::Pass p = texel_copy_pass(kSide, kSide);

  TextureSet set(device);
  ir::Result<TextureId> src = set.create(kSide, kSide, img::Format::RGBA8);
  if (!src) return src.failure();
  ir::Result<TextureId> dst = set.create(kSide, kSide, img::Format::RGBA32F);
  if (!dst) return dst.failure();
  if (ir::Status up = set.upload(*src, levels); !up) return up.failure();
  StageTextures stages{};
  stages[0] = *src;
  if (ir::Result<pass::DrawReport> r = set.draw(p, stages, *dst); !r) return r.failure();
  ir::Result<img::Image> out = set.read(*dst);
  if (!out) return out.failure();

  std::vector<float> values(4 * 256);
  for (uint32_t px = 0; px < kSide * kSide; ++px)
    for (uint32_t c = 0; c < 4; ++c) values[c * 256 + (px + 64 * c) % 256] = out->rgba[px * 4 + c];
  return values;
}

} // namespace tierlift::vulkan
