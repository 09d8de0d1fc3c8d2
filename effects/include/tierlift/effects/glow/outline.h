// The stencil-buffer outline glow: an object drawn once into two render targets and a
// stencil buffer, its glow mask blurred by the glow's Gaussian passes, and the blurred glow
// added only where the stencil is clear, so the glow is an outline around the object.
//   object      outline/object.vsh + outline/object_mrt.psh (ps_2_0): oC0 = colour (c0) into
//               "color", oC1 = glow mask (c1) into "mask", stencil ALWAYS / REPLACE ref 1
//               into "stencil"; the object is a regular polygon, a fan of triangles
//   extract, blur_h.i, blur_v.i (, downsample.i)  the dx9 glow's passes with "mask" as
//               their source (glow.h)
//   base        final = scene + color (glow/composite_add.psh with intensity 1)
//   outline     final += intensity × glow (outline/add_glow.psh), ONE/ONE, where the stencil
//               test EQUAL ref 0 passes (the stencil is not written: KEEP)
// Textures: "scene" (the input, the background), "color", "mask", "stencil" (8 bits), the
// glow's "glow_sources", "blur_h", "glow", and "final".
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tierlift/effects/glow/glow.h"

namespace tierlift::effects {

inline constexpr std::string_view kColorTexture = "color";
inline constexpr std::string_view kMaskTexture = "mask";
inline constexpr std::string_view kStencilTexture = "stencil";

struct OutlineParams {
  // A regular polygon in pixels of the scene: centre, circumradius, corners, rotation of the
  // first corner from +x (degrees, clockwise on screen since y runs down).
  double center_x = 160.25, center_y = 120.25, radius = 60;
  uint32_t sides = 6; // 3..64
  double rotation = 0;
  std::array<float, 4> color{1.0f, 0.55f, 0.1f, 1.0f};     // oC0: the object
  std::array<float, 4> glow_color{0.3f, 0.7f, 1.0f, 1.0f}; // oC1: what glows
  uint32_t stencil_ref = 1; // the object's stencil mark (REPLACE), 1..255
};

// The polygon's corners in pixels (x right, y down), first corner at `rotation`.
std::vector<std::array<double, 2>> outline_polygon(const OutlineParams& o);

// The graph (tier dx9 only: MRT is ps_2_0). glow.width/height are the scene's size; the
// glow's downsample, profile, format, intensity and listing options apply. Errors name the
// parameter at fault.
PlanResult build_outline(const EffectParams& glow, const OutlineParams& outline);

} // namespace tierlift::effects
