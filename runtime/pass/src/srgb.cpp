// sRGB sampler stages decoded on the host (srgb.h).
#include "tierlift/pass/srgb.h"

#include <cmath>

#include "tierlift/rounding/rounding.h"

namespace tierlift::pass {

std::shared_ptr<const img::Image> srgb_decoded(const std::shared_ptr<const img::Image>& image) {
  if (!image || image->format != img::Format::RGBA8) return image;
  const std::array<float, 256>& levels = rounding::srgb_decode_levels();
  auto out = std::make_shared<img::Image>(*image);
  out->format = img::Format::RGBA32F;
  for (size_t i = 0; i < out->rgba.size(); ++i) {
    if (i % 4 == 3) continue; // alpha stays linear
    // An RGBA8 image holds k/255 exactly as unorm8_levels has it; the byte is its nearest.
    const float v = out->rgba[i];
    const long k = std::lround(static_cast<double>(v) * 255.0);
    out->rgba[i] = levels[static_cast<size_t>(k < 0 ? 0 : (k > 255 ? 255 : k))];
  }
  return out;
}

TextureBinding srgb_resolved(const TextureBinding& b) {
  if (!b.sampler.srgb) return b;
  TextureBinding out = b;
  out.sampler.srgb = false;
  out.image = srgb_decoded(b.image);
  for (auto& layer : out.layers) layer = srgb_decoded(layer);
  if (!out.layers.empty()) out.image = out.layers[0];
  // A mip chain: every level decoded, level 0 the image (pass.h's TextureBinding::levels).
  for (auto& level : out.levels) level = srgb_decoded(level);
  if (!out.levels.empty()) out.image = out.levels[0];
  return out;
}

bool reads_srgb(const Pass& pass) {
  for (const TextureBinding& b : pass.textures)
    if (b.sampler.srgb) return true;
  for (const TextureBinding& b : pass.vertex_textures)
    if (b.sampler.srgb) return true;
  return false;
}

} // namespace tierlift::pass
