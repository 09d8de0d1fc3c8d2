// Bilinear sampling with the arithmetic of Mesa llvmpipe's float-texture path (lavapipe's
// sampler for the RGBA32F textures the Vulkan device binds), for ir::Rounding::Llvmpipe.
// The float steps are rounding::linear_axis and rounding::lerp; reproducing them (measured
// bit-exact against lavapipe, Mesa 22.3 on x86-64, at 1920×1080 with taps on texel centres,
// corners and arbitrary offsets) is what makes the two devices agree.
#include <cmath>

#include "sampling_rules.h"
#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {
Vec4 sample_texture_llvmpipe(const img::Image& image, const SamplerState& sampler, float u, float v,
                             int subtexel_bits) {
  if (image.width == 0 || image.height == 0 || sampler.filter == Filter::Point)
    return sample_texture(image, sampler, u, v, subtexel_bits);
  const detail::LinearAxis x =
      detail::llvmpipe_linear_axis(u, image.width, sampler.address_u, subtexel_bits);
  const detail::LinearAxis y =
      detail::llvmpipe_linear_axis(v, image.height, sampler.address_v, subtexel_bits);
  const auto u0 = address_texel(sampler.address_u, x.i0, image.width);
  const auto u1 = address_texel(sampler.address_u, x.i0 + 1, image.width);
  const auto v0 = address_texel(sampler.address_v, y.i0, image.height);
  const auto v1 = address_texel(sampler.address_v, y.i0 + 1, image.height);
  const Vec4 t00 = detail::fetch(image, sampler, u0, v0),
             t10 = detail::fetch(image, sampler, u1, v0);
  const Vec4 t01 = detail::fetch(image, sampler, u0, v1),
             t11 = detail::fetch(image, sampler, u1, v1);
  Vec4 out;
  for (int c = 0; c < 4; ++c)
    out[c] = detail::llvmpipe_lerp(y.alpha, detail::llvmpipe_lerp(x.alpha, t00[c], t10[c]),
                                   detail::llvmpipe_lerp(x.alpha, t01[c], t11[c]));
  return out;
}

} // namespace tierlift::cpu
