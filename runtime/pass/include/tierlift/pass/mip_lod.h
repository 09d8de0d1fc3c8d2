// Level-of-detail selection and the mip blend of Direct3D 9 sampler state, written once as
// numeric rules (NUMERICS.md "Mip levels and LOD", M1-M5) for the devices to call when
// textures carry mip chains (pass::TextureBinding::levels). These are the exact model;
// lavapipe's arithmetic beside it, measured, is in tierlift/rounding/rounding.h, and
// select_levels picks one or the other. The CPU device's only caller is
// BoundTextures::sample_lod; the Vulkan device hands the same state to its sampler.
#pragma once

#include <cstdint>

namespace tierlift::pass {

// D3DSAMP_MIPFILTER: D3DTEXF_NONE, D3DTEXF_POINT, D3DTEXF_LINEAR.
enum class MipFilter : uint8_t { None, Point, Linear };

// The mip part of one sampler stage's state, with Direct3D 9's defaults: MIPFILTER NONE,
// MIPMAPLODBIAS 0, MAXMIPLEVEL 0 (the index of the most detailed level a read may take).
struct MipState {
  MipFilter filter = MipFilter::None;
  float lod_bias = 0.0f;      // D3DSAMP_MIPMAPLODBIAS, added to every lod
  uint32_t max_mip_level = 0; // D3DSAMP_MAXMIPLEVEL
};

// The levels one read takes: `fraction` of level `fine` blended toward `coarse` (equal
// levels, or fraction 0, read one level). `magnified`: the lod with its biases was ≤ 0, so
// the magnification filter applies (D3DSAMP_MAGFILTER), else the minification one.
struct LevelChoice {
  uint32_t fine = 0, coarse = 0;
  float fraction = 0.0f;
  bool magnified = true;
};

// M1, implicit lod from gradients (texld and texldb once quads give d(u,v)/dx and /dy): the
// gradients scaled to texels, λ = log2(max(|(du/dx·W, dv/dx·H)|, |(du/dy·W, dv/dy·H)|)), in
// double, rounded to float (the isotropic rule with MAXANISOTROPY 1). A zero footprint gives
// −inf (the most detailed level after the clamp), a non-finite gradient NaN.
float lod_from_gradients(float dudx, float dvdx, float dudy, float dvdy, uint32_t width,
                         uint32_t height);

// M2, the levels a read at `lod` takes on a texture of `levels` levels (≥ 1): λ = lod +
// state.lod_bias + texldb_bias, clamped to [m, levels − 1] with m = min(MAXMIPLEVEL, levels −
// 1); a NaN λ reads level m.
//   NONE:   level m (no mipmapping: the most detailed level allowed), whatever λ is
//   POINT:  level floor(λ + ½), the nearest, halves going to the coarser level
//   LINEAR: levels floor(λ) and floor(λ) + 1 (the last level twice), fraction λ − floor(λ)
LevelChoice choose_levels(float lod, float texldb_bias, const MipState& state, uint32_t levels);

// M3, the mip blend, exact: (1 − f)·fine + f·coarse in double, rounded once to float.
float mip_blend_exact(float fraction, float fine, float coarse);

// What one read hands the level rule (M4): the gradients of (u, v) across its 2x2 quad
// (texld, texldp, texldb: the quad's coarse differences, M5; texldd: given), or an explicit
// lod (texldl), and texldb's bias.
struct LodInput {
  bool explicit_lod = false;
  float lod = 0.0f;                                         // explicit_lod
  float dudx = 0.0f, dvdx = 0.0f, dudy = 0.0f, dvdy = 0.0f; // !explicit_lod
  bool has_bias = false;                                    // texldb
  float bias = 0.0f;
};

// The levels a read of a `levels`-level texture whose level 0 is w×h takes: the exact rules
// (lod_from_gradients, choose_levels) or, `llvmpipe`, lavapipe's (rounding.h: ρ, λ, the
// nearest level, the clamps as its sampler applies them; NUMERICS.md M1-M2).
LevelChoice select_levels(const LodInput& in, const MipState& state, uint32_t levels,
                          uint32_t width, uint32_t height, bool llvmpipe);

} // namespace tierlift::pass
