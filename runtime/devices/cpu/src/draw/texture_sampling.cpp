// Point and bilinear sampling on the integer texel grid (docs/d3d9-rules.md §10.1, §10.2).
#include <cmath>

#include "sampling_rules.h"
#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {

double quantize_fraction(double alpha, int subtexel_bits) {
  if (subtexel_bits <= 0) return alpha;
  double scale = std::ldexp(1.0, subtexel_bits > 30 ? 30 : subtexel_bits);
  return std::nearbyint(alpha * scale) / scale;
}

Vec4 sample_texture(const img::Image& image, const SamplerState& sampler, float u, float v,
                    int subtexel_bits) {
  if (image.width == 0 || image.height == 0) return {0, 0, 0, 1};
  if (sampler.filter == Filter::Point) {
    const int64_t i = detail::point_texel(u, image.width);
    const int64_t j = detail::point_texel(v, image.height);
    return detail::fetch(image, sampler, address_texel(sampler.address_u, i, image.width),
                         address_texel(sampler.address_v, j, image.height));
  }

  double x = detail::texel_space(u, image.width) - 0.5;
  double y = detail::texel_space(v, image.height) - 0.5;
  double fx = std::floor(x), fy = std::floor(y);
  double a = quantize_fraction(x - fx, subtexel_bits);
  double b = quantize_fraction(y - fy, subtexel_bits);
  int64_t i0 = static_cast<int64_t>(fx), j0 = static_cast<int64_t>(fy);
  const auto u0 = address_texel(sampler.address_u, i0, image.width);
  const auto u1 = address_texel(sampler.address_u, i0 + 1, image.width);
  const auto v0 = address_texel(sampler.address_v, j0, image.height);
  const auto v1 = address_texel(sampler.address_v, j0 + 1, image.height);
  Vec4 t00 = detail::fetch(image, sampler, u0, v0), t10 = detail::fetch(image, sampler, u1, v0);
  Vec4 t01 = detail::fetch(image, sampler, u0, v1), t11 = detail::fetch(image, sampler, u1, v1);
  Vec4 out;
  for (int c = 0; c < 4; ++c) {
    double r =
        (1 - a) * (1 - b) * t00[c] + a * (1 - b) * t10[c] + (1 - a) * b * t01[c] + a * b * t11[c];
    out[c] = static_cast<float>(r);
  }
  return out;
}

Vec4 BoundTextures::sample(uint32_t stage, const Vec4& coord, float lod_bias) const {
  if (stage >= bindings_.size() || !bindings_[stage].image) return {0, 0, 0, 1};
  const TextureBinding& b = bindings_[stage];
  if (b.levels.size() > 1) { // a mip chain read without a quad: zero gradients
    pass::LodInput in;
    in.has_bias = lod_bias != 0.0f;
    in.bias = lod_bias;
    return sample_lod(stage, coord, in);
  }
  if (b.shape == pass::TextureShape::Cube) return sample_cube(b, coord, llvmpipe_, subtexel_bits_);
  if (b.shape == pass::TextureShape::Volume)
    return sample_volume(b, coord, llvmpipe_, subtexel_bits_);
  return llvmpipe_
             ? sample_texture_llvmpipe(*b.image, b.sampler, coord[0], coord[1], subtexel_bits_)
             : sample_texture(*b.image, b.sampler, coord[0], coord[1], subtexel_bits_);
}

StageState BoundTextures::stage_state(uint32_t stage) const {
  if (stage >= bindings_.size()) return {};
  return bindings_[stage].stage;
}

} // namespace tierlift::cpu
