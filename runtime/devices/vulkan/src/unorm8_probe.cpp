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

  // Pixel (i, j) reads texel (i, j) at its centre: the quad's uv (i/16 at pixel i, D3D9
  // centres) plus half a texel, through a POINT, CLAMP/CLAMP sampler (the in-place read).
  pass::Pass p;
  p.vertex_program = passthrough_vertex_program();
  p.pixel_program = texel_copy_pixel_program();
  pass::set_full_screen_quad(p, kPassPosition);
  for (size_t c = 0; c < p.vertices.size(); ++c) {
    pass::Vec4 uv = pass::kQuadUV[c];
    uv[0] += 0.5f / kSide;
    uv[1] += 0.5f / kSide;
    p.vertices[c].v[kPassTex] = uv;
  }
  pass::SamplerState& s = p.textures[0].sampler;
  s.filter = pass::Filter::Point;
  s.address_u = s.address_v = pass::AddressMode::Clamp;

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
