// Reads of a mip chain (texture.h, BoundTextures::sample_lod; NUMERICS.md M1-M5): the levels
// pass::select_levels picks, each read as a 2D texture of its own size, blended by the
// fraction toward the coarser one.
#include "tierlift/cpu/texture.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::cpu {

Vec4 BoundTextures::sample_lod(uint32_t stage, const Vec4& coord, const pass::LodInput& lod) const {
  if (stage >= bindings_.size() || !bindings_[stage].image) return {0, 0, 0, 1};
  const TextureBinding& b = bindings_[stage];
  if (b.levels.size() <= 1 || b.shape != pass::TextureShape::Tex2D)
    return sample(stage, coord, lod.bias);
  const img::Image& base = *b.levels[0];
  const pass::LevelChoice c =
      pass::select_levels(lod, b.sampler.mip, static_cast<uint32_t>(b.levels.size()), base.width,
                          base.height, llvmpipe_);
  auto read = [&](uint32_t k) {
    const img::Image& level = *b.levels[k];
    return llvmpipe_ ? sample_texture_llvmpipe(level, b.sampler, coord[0], coord[1], subtexel_bits_)
                     : sample_texture(level, b.sampler, coord[0], coord[1], subtexel_bits_);
  };
  const Vec4 fine = read(c.fine);
  // A fraction of 0 reads one level: lavapipe skips the second read and the lerp there.
  if (c.coarse == c.fine || c.fraction == 0.0f) return fine;
  const Vec4 coarse = read(c.coarse);
  Vec4 out;
  for (int k = 0; k < 4; ++k)
    out[k] = llvmpipe_ ? rounding::lerp(c.fraction, fine[k], coarse[k])
                       : pass::mip_blend_exact(c.fraction, fine[k], coarse[k]);
  return out;
}

} // namespace tierlift::cpu
