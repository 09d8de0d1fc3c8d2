// Cube and volume reads (NUMERICS.md, cube maps and volume textures): a cube read picks a face
// and its (s, t) by rounding::cube_coord_* and reads that face as a 2D texture with edge
// clamping; a volume read is point or trilinear over the slices, with ADDRESSW on the third axis.
#include <cmath>

#include "sampling_rules.h"
#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {
namespace {

// The face's sampler: Direct3D 9 ignores ADDRESSU/V on a cube and filters each face on its own,
// clamped at its edges (NUMERICS.md T4; the Vulkan device asks the same of its cube samplers).
SamplerState face_sampler(const SamplerState& s) {
  SamplerState f = s;
  f.address_u = f.address_v = AddressMode::Clamp;
  return f;
}

Vec4 sample_slice(const img::Image& slice, const SamplerState& s, float u, float v, bool llvmpipe,
                  int bits) {
  return llvmpipe ? sample_texture_llvmpipe(slice, s, u, v, bits)
                  : sample_texture(slice, s, u, v, bits);
}

// Slice k after ADDRESSW (nullptr: the border colour).
const img::Image* slice_at(const std::vector<std::shared_ptr<const img::Image>>& layers,
                           AddressMode mode, int64_t k) {
  const std::optional<int64_t> a = address_texel(mode, k, static_cast<int64_t>(layers.size()));
  return a ? layers[static_cast<size_t>(*a)].get() : nullptr;
}

} // namespace

Vec4 sample_cube(const TextureBinding& b, const Vec4& coord, bool llvmpipe, int subtexel_bits) {
  const rounding::CubeCoord c = llvmpipe
                                    ? rounding::cube_coord_llvmpipe(coord[0], coord[1], coord[2])
                                    : rounding::cube_coord_exact(coord[0], coord[1], coord[2]);
  return sample_slice(*b.layers[c.face], face_sampler(b.sampler), c.s, c.t, llvmpipe,
                      subtexel_bits);
}

Vec4 sample_volume(const TextureBinding& b, const Vec4& coord, bool llvmpipe, int subtexel_bits) {
  const SamplerState& s = b.sampler;
  const uint32_t depth = static_cast<uint32_t>(b.layers.size());
  if (s.filter == Filter::Point) {
    const img::Image* slice = slice_at(b.layers, s.address_w, detail::point_texel(coord[2], depth));
    return slice ? sample_slice(*slice, s, coord[0], coord[1], llvmpipe, subtexel_bits)
                 : s.border_color;
  }
  // Trilinear within the level: the two slices' bilinear reads, then a lerp between them
  // (lavapipe: rounding::linear_axis on w and rounding::lerp; exact: the weight in double).
  int64_t k0;
  double gamma;
  if (llvmpipe) {
    const detail::LinearAxis z =
        detail::llvmpipe_linear_axis(coord[2], depth, s.address_w, subtexel_bits);
    k0 = z.i0;
    gamma = z.alpha;
  } else {
    const double w = detail::texel_space(coord[2], depth) - 0.5;
    const double f = std::floor(w);
    k0 = static_cast<int64_t>(f);
    gamma = quantize_fraction(w - f, subtexel_bits);
  }
  const img::Image* s0 = slice_at(b.layers, s.address_w, k0);
  const img::Image* s1 = slice_at(b.layers, s.address_w, k0 + 1);
  const Vec4 v0 =
      s0 ? sample_slice(*s0, s, coord[0], coord[1], llvmpipe, subtexel_bits) : s.border_color;
  const Vec4 v1 =
      s1 ? sample_slice(*s1, s, coord[0], coord[1], llvmpipe, subtexel_bits) : s.border_color;
  Vec4 out;
  for (int c = 0; c < 4; ++c)
    out[c] = llvmpipe ? detail::llvmpipe_lerp(static_cast<float>(gamma), v0[c], v1[c])
                      : static_cast<float>((1 - gamma) * v0[c] + gamma * v1[c]);
  return out;
}

} // namespace tierlift::cpu
