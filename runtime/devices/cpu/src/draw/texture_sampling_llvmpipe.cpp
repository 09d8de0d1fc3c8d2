// Bilinear sampling with the arithmetic of Mesa llvmpipe's float-texture path (lavapipe's
// sampler for the RGBA32F textures the Vulkan device binds), for ir::Rounding::Llvmpipe.
// The float steps are rounding::linear_axis and rounding::lerp; reproducing them (measured
// bit-exact against lavapipe, Mesa 22.3 on x86-64, at 1920×1080 with taps on texel centres,
// corners and arbitrary offsets) is what makes the two devices agree.
#include <cmath>
#include <limits>
#include <utility>

#include "sampling_rules.h"
#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {
Vec4 sample_texture_llvmpipe(const img::Image& image, const SamplerState& sampler, float u, float v,
                             int subtexel_bits) {
  if (image.width == 0 || image.height == 0)
    return sample_texture(image, sampler, u, v, subtexel_bits);
  using Kind = detail::UnaddressableAxis::Kind;
  const detail::UnaddressableAxis ux =
      detail::llvmpipe_unaddressable(u, image.width, sampler.address_u, sampler.filter);
  const detail::UnaddressableAxis uy =
      detail::llvmpipe_unaddressable(v, image.height, sampler.address_v, sampler.filter);
  if (ux.kind == Kind::NanWeight || uy.kind == Kind::NanWeight) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return {nan, nan, nan, nan};
  }
  if (sampler.filter == Filter::Point) {
    if (ux.kind == Kind::Ordinary && uy.kind == Kind::Ordinary)
      return sample_texture(image, sampler, u, v, subtexel_bits);
    if (ux.kind == Kind::Border || uy.kind == Kind::Border) return sampler.border_color;
    const int64_t i = ux.kind == Kind::Texel ? ux.texel : detail::point_texel(u, image.width);
    const int64_t j = uy.kind == Kind::Texel ? uy.texel : detail::point_texel(v, image.height);
    return detail::fetch(image, sampler, address_texel(sampler.address_u, i, image.width),
                         address_texel(sampler.address_v, j, image.height));
  }
  auto axis = [&](float c, uint32_t n, AddressMode mode, const detail::UnaddressableAxis& un) {
    // Texel: both taps on texel un.texel (i0 = k, i1 = k), weight un.alpha, as llvmpipe's
    // clamped indices; lerp(α, t, t) is computed all the same (an infinite texel gives NaN).
    if (un.kind == Kind::Texel) return std::pair{detail::LinearAxis{un.texel, un.alpha}, true};
    return std::pair{detail::llvmpipe_linear_axis(c, n, mode, subtexel_bits), false};
  };
  const auto [x, x_same] = axis(u, image.width, sampler.address_u, ux);
  const auto [y, y_same] = axis(v, image.height, sampler.address_v, uy);
  const auto u0 = address_texel(sampler.address_u, x.i0, image.width);
  const auto u1 = address_texel(sampler.address_u, x.i0 + (x_same ? 0 : 1), image.width);
  const auto v0 = address_texel(sampler.address_v, y.i0, image.height);
  const auto v1 = address_texel(sampler.address_v, y.i0 + (y_same ? 0 : 1), image.height);
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
