// Rendering contexts (Tron 2.0, seed 002): what the glow blurs need not be the scene image's
// own rgb × alpha. A scene may give a separate glow render of itself (the "glow context":
// per-object glow colour in rgb, strength in alpha), and it may fog that glow render toward
// a colour with distance ("black glow fog": far, aliasing surfaces stop glowing).
//   sources = glow image rgb × glow image alpha (alpha kept), or the scene's when none
//   fogged   D3D linear fog on the sources: f = saturate((end − d)/(end − start)),
//            rgb = f·sources + (1 − f)·fog colour, alpha kept
// The composite still adds the glow to the scene image. The fog is drawn by the extract pass
// itself (glow/extract_fogged.psh, glow/extract_fogged_ps11.psh), so every device runs it
// as a listing; the analytic device evaluates AnalyticForm::MaskByAlphaFogged.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>

#include "tierlift/image/image.h"

namespace tierlift::effects {

inline constexpr std::string_view kGlowImageTexture = "glow_image"; // input: the glow render
inline constexpr std::string_view kDepthTexture = "glow_depth";     // input: the fog's depth

struct GlowFog {
  bool on = false;
  double start = 0.25, end = 0.75; // start < end, in depth units
  std::array<double, 3> color{0, 0, 0};
  // The depth image as read (its red channel is the depth); null: the built-in floor,
  // depth = 1 − (y + ½)/height at pixel row y (the bottom row near 0, the top row near 1,
  // as a floor receding toward a horizon at the top of the picture).
  std::shared_ptr<const img::Image> depth;
  std::string depth_file; // the file `depth` was read from ("" for the built-in floor)
};

struct GlowContext {
  // The glow render, the scene's size (RGBA32F as read); null: the scene image's own.
  std::shared_ptr<const img::Image> glow_image;
  std::string glow_image_file; // the file it was read from
  GlowFog fog;
  bool on() const { return glow_image || fog.on; }
};

// The fog's depth texture for a width × height scene: the depth image's red channel in r, g
// and b, alpha 1 (the listings fog each channel by its own read, so all three hold the
// depth), or the built-in floor when the fog names no image. RGBA32F.
img::Image fog_depth_texture(const GlowFog& fog, uint32_t width, uint32_t height);

// The constants of the fogged extract: c0 = −1/(end − start), c1 = end/(end − start) (each
// divided by `scale`, the listing's result modifier: 4 for ps.1.x, whose constants clamp to
// [-1, 1]), c2 = the fog colour. Returns c0, c1, c2.
std::array<std::array<float, 4>, 3> fog_constants(const GlowFog& fog, double scale);

// Empty when the ps.1.x constants of fog_constants(fog, 4) lie in [-1, 1] (tiers dx8, dx7);
// otherwise why not, naming the limit.
std::string fog_ps1x_limit(const GlowFog& fog);

// One line for the run's header: where the sources come from and how they are fogged, e.g.
// "glow sources: the glow image's rgb × alpha, fogged from depth 0.3 to 0.8 toward (0, 0, 0)
// (depth: the built-in floor)"; empty when the context is off.
std::string context_summary(const GlowContext& context);

} // namespace tierlift::effects
