// Texture sampling with Direct3D 9 rules (docs/d3d9-rules.md §10): texel centres at (k + 0.5)/N,
// point = floor(u·N), bilinear i0 = floor(u·N − 0.5) with α = frac(u·N − 0.5), address
// modes applied to the integer texel index, unbound stages read (0, 0, 0, 1).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "tierlift/cpu/shader_vm.h"
#include "tierlift/image/image.h"
#include "tierlift/pass/pass.h"

namespace tierlift::cpu {

// Sampler state and stage bindings are the device-neutral pass state's (tierlift/pass).
using pass::address_texel; // the D3DTADDRESS rule (tierlift/pass/addressing.h)
using pass::AddressMode;
using pass::Filter;
using pass::kMaxSamplers;
using pass::SamplerState;
using pass::TextureBinding;

// Bilinear fraction quantised to `subtexel_bits` (0 = exact): round(α·2^N)/2^N, the
// rounding Vulkan describes for subTexelPrecisionBits.
double quantize_fraction(double alpha, int subtexel_bits);

// Samples `image` at normalised (u, v). Point: floor(fl32(u·N)). Bilinear: u·N − 0.5 exact
// in double, weights and sum in double, returned as float. NaN coordinates
// read texel index 0; huge ones are clamped before conversion (no UB).
Vec4 sample_texture(const img::Image& image, const SamplerState& sampler, float u, float v,
                    int subtexel_bits);

// The same with Mesa llvmpipe's float-texture arithmetic (ir::Rounding::Llvmpipe): bilinear
// x = fl32(u·N) − 0.5 in float (Clamp: min(u·N, N) first and max(x, 0) after, as llvmpipe
// clamps coordinates rather than indices), α = x − floor(x) unquantised unless subtexel_bits
// > 0, rows lerped as fma(α, t1 − t0, t0), then the two rows the same way. lavapipe reports
// subTexelPrecisionBits = 8 but weights float textures with full float fractions, so 0
// matches it. Point sampling is the same as sample_texture's.
Vec4 sample_texture_llvmpipe(const img::Image& image, const SamplerState& sampler, float u, float v,
                             int subtexel_bits);

// A cube read (coord = direction x, y, z; rounding::cube_coord_* picks the face and (s, t),
// the face is read with edge clamping) and a volume read (u, v, w: point, or trilinear as the
// lerp of two slices' bilinear reads, ADDRESSW on w). llvmpipe: the rules of
// sample_texture_llvmpipe, else sample_texture's (texture_sampling_layered.cpp).
Vec4 sample_cube(const TextureBinding& b, const Vec4& coord, bool llvmpipe, int subtexel_bits);
Vec4 sample_volume(const TextureBinding& b, const Vec4& coord, bool llvmpipe, int subtexel_bits);

// The TextureUnit the pixel stage of a draw sees: sample(stage, …) reads bindings[stage].
class BoundTextures final : public TextureUnit {
public:
  // `bindings`: a stage's samplers, stage s at [s] (Pass::textures, or Pass::vertex_textures
  // for the vertex stage's texldl); a stage past its end reads (0, 0, 0, 1).
  BoundTextures(std::span<const TextureBinding> bindings, int subtexel_bits, bool llvmpipe = false)
      : bindings_(bindings), subtexel_bits_(subtexel_bits), llvmpipe_(llvmpipe) {}
  // A stage with a mip chain (TextureBinding::levels) reads the levels pass::select_levels
  // picks (the exact rules, or lavapipe's when `llvmpipe`) and blends them (NUMERICS.md M3);
  // sample() reads it as from a quad of zero gradients (texture_sampling_mip.cpp).
  Vec4 sample(uint32_t stage, const Vec4& coord, float lod_bias) const override;
  Vec4 sample_lod(uint32_t stage, const Vec4& coord, const pass::LodInput& lod) const override;
  StageState stage_state(uint32_t stage) const override;
  // The same samples without a virtual call per lane (texture_sampling_block.cpp).
  void sample_block(uint32_t stage, const float* const coord[4], const float* bias, int n,
                    Lanes out[4]) const override;

private:
  std::span<const TextureBinding> bindings_;
  int subtexel_bits_;
  bool llvmpipe_; // sample_texture_llvmpipe instead of sample_texture
};

} // namespace tierlift::cpu
