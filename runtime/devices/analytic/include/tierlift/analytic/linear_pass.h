// A general pass as math, in double: the taps (read off the pass's listings by
// extract_taps) over the textures bound to their sampler stages, the target's size, the
// blend with what the target already holds, the ps_1_x range rule and the store rule.
// Shares no code with the CPU device: only the sampling model of blur_model.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tierlift/analytic/blur_model.h"
#include "tierlift/analytic/taps.h"
#include "tierlift/image/image.h"
#include "tierlift/image/io.h"

namespace tierlift::analytic {

// One sampler stage (s# of ps_2_0, texture stage of ps_1_x) and what it holds. A stage
// without an entry reads (0, 0, 0, 1), as D3D9 does for an unbound stage.
struct StageTexture {
  uint32_t stage = 0;
  const img::Image* image = nullptr; // not owned; must outlive the call
  SamplerModel sampler;
};

// How the pass's colour meets the target: Replace, or ONE/ONE (dst = src + dst; the passes
// of a wide blur are summed this way). On an RGBA8 target the source colour is clamped to
// [0, 1] before blending, as UNORM attachments do (Vulkan, D3D9).
enum class Blend { Replace, OneOne };

struct LinearPassInput {
  std::vector<StageTexture> textures;
  PassModel model; // conventions, target size (both > 0) and format, quad uv; not .sampler
  Blend blend = Blend::Replace;
  const img::Image* destination = nullptr; // OneOne: the target's stored contents
  // The pixel listing is ps_1_x: every sample (a t# write) and the output clamp to
  // [-m, m], m = model.conventions.ps1x_max_value (NUMERICS.md rule 25). The model clamps
  // the final sum only: with non-negative weights and non-negative samples every partial
  // sum of the listing's mul/mad chain lies between 0 and the final sum, so clamping the end
  // equals clamping each step. Where a weight or a sample is negative that no longer holds
  // and a note says so.
  bool ps1x_clamp = false;
  // RGBA8 and RGBA16F stores. With every tap's coordinate the devices' own (Tap::corners,
  // Rounding::Llvmpipe) the model stores exactly what the float devices store: the double
  // value settles the stored step or half wherever the devices' fp32 value, which lies within
  // a bound worked out from the pass's fp32 operations (linear_pass.cpp), cannot cross a
  // rounding boundary; elsewhere — exact midpoints, where averaging 8-bit texels with
  // power-of-two weights lands, and values within that bound of one — the pass's own fp32
  // arithmetic decides (the listing's mul/mad chain in the order it samples, bilinear lerps
  // as fused multiply-adds, the store's fl32(x·255) with ties to even for lavapipe).
  // RGBA8 only: when set (target width × height entries), each entry receives 1 where a
  // channel's fp32 x·255 lies exactly half-way between two steps (a proven tie, which D3D9
  // and Vulkan leave to the device: one step of slack for compare_runs); other entries are
  // left as they are (start from 0s, or from the target's mask under ONE/ONE). Without the
  // devices' coordinates (hand-made taps, Rounding::Exact) the store is decided in double and
  // the entry is set where a value lies within kUnorm8MidpointBand of a midpoint.
  std::vector<uint8_t>* slack = nullptr;
};

// In 8-bit steps, for the double-only store: 1/1024 of a step covers a float device's own
// noise on values up to 255 steps (fp32 sums: ~255 · 2^-23 step).
inline constexpr double kUnorm8MidpointBand = 1.0 / 1024;

// out(i, j) = Σ_k w_k · sample(tex[stage_k], scale_k·uv + offset_k), uv = pixel_uv(i, j) of
// the target, then the ps_1_x rule, the blend, and the target format's store rule
// (store_value: img::quantize, with model.unorm8_ties deciding exact RGBA8 midpoints).
// Target and texture sizes are independent (downsampling, upsampling).
// `notes`, when given, receives the assumptions the model made for this pass.
img::ImageResult linear_pass(const std::vector<Tap>& taps, const LinearPassInput& in,
                             std::vector<std::string>* notes = nullptr);

// The glow's source extraction: out = (r·a, g·a, b·a, a) of the one read (its stage and
// coordinate from `read`; its weight is not used), with the same ps_1_x rule, blend and store.
img::ImageResult mask_by_alpha_pass(const Tap& read, const LinearPassInput& in,
                                    std::vector<std::string>* notes = nullptr);

// The glow sources fogged by depth (Direct3D's linear fog applied while the glow sources are
// drawn; Tron 2.0's "black glow fog"), per channel c:
//   f_c = saturate(scale·(slope_c·d_c + bias_c)), d the depth read
//   out_c = f_c·(s_c·s_a) + (1 − f_c)·color_c (c = r, g, b), out_a = s_a, s the source read
// `slope`, `bias` and `color` are the pixel listing's c0, c1 and c2 as it sees them (a `def`
// wins; ps_1_x constants clamp to [-1, 1]); `scale` the result scale of its fog factor:
// 4 for ps_1_x (the _x4 its clamped constants need), 1 otherwise.
struct FogForm {
  std::array<double, 4> slope{}, bias{}, color{};
  double scale = 1;
};
FogForm fog_form(const ir::Program& ps, const std::vector<Vec4>& ps_consts);
// Stored as linear_pass stores (with the devices' own coordinates, their fp32 arithmetic
// settles what the double value cannot), with the same ps_1_x rule and blend.
img::ImageResult fogged_mask_pass(const Tap& source, const Tap& depth, const FogForm& fog,
                                  const LinearPassInput& in,
                                  std::vector<std::string>* notes = nullptr);

} // namespace tierlift::analytic
