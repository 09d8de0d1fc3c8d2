// BoundTextures' block read: the block executor's texture instructions sample all their lanes
// through one call. Each lane is the sample() of that lane (same functions, same arguments).
#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {

void BoundTextures::sample_block(uint32_t stage, const float* const coord[4], const float* bias,
                                 int n, Lanes out[4]) const {
  (void)bias; // one mip level: the bias has nothing to select
  if (stage >= kMaxSamplers || !bindings_[stage].image) {
    for (int l = 0; l < n; ++l) {
      out[0][l] = out[1][l] = out[2][l] = 0.0f;
      out[3][l] = 1.0f;
    }
    return;
  }
  const TextureBinding& b = bindings_[stage];
  for (int l = 0; l < n; ++l) {
    const Vec4 r =
        llvmpipe_
            ? sample_texture_llvmpipe(*b.image, b.sampler, coord[0][l], coord[1][l], subtexel_bits_)
            : sample_texture(*b.image, b.sampler, coord[0][l], coord[1][l], subtexel_bits_);
    for (int c = 0; c < 4; ++c) out[c][l] = r[c];
  }
}

} // namespace tierlift::cpu
