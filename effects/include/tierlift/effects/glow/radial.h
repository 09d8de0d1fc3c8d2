// Radial-blur beams (Meshuggah "Beams") as an effect graph:
//   star        the animated star: four reads of the scene image (wrapping, bilinear) at the
//               quad uv plus four offsets that are functions of time, averaged (0.25 each);
//               time = frame / rate
//   zoom.i      the beams: the weighted sum over copies i = 1..N of the star image zoomed
//               toward the centre c: copy i reads u' = c + (u − c)·(1 − 2·i·step) (the
//               article's quad texture range [i·step, 1 − i·step] for c = ½, step 0.0075),
//               weight (1/8)(N − i)/N (the article's source alpha with destination factor
//               ONE), bilinear reads clamped at the edge; eight copies a pass (ps.2.0) or four
//               (ps.1.x), the passes summed by ONE/ONE blending (the first replaces)
//   composite   final = star + strength × beams, the star's alpha kept
// Texture names: "scene" (input), "star", "glow" (the beams), "final": the glow's names for
// input, effect image and result, so the glow command's reporting serves both.
#pragma once

#include <array>
#include <vector>

#include "tierlift/effects/glow/glow.h"

namespace tierlift::effects {

inline constexpr std::string_view kStarTexture = "star";

struct RadialParams {
  std::array<double, 2> centre{0.5, 0.5}; // in texture coordinates, 0..1
  unsigned steps = 32;                    // N: copies 1..N
  double step = 0.0075;                   // the zoom per copy (the article's 0.0075)
  double strength = 1;                    // the composite's factor for the beams
  // The star: amplitude of the four time offsets in texels (0: the scene image unmoved),
  // frames per time unit, and the frame rendered (time = frame / rate).
  double amplitude = 4;
  double rate = 30;
  unsigned frame = 0;
  // Frames the star moves through (`tierlift glow --frames N` sets N): frame f of a run
  // (from 0) is time (frame + f) / rate, given to the star pass as per-frame vertex
  // constants (PassDesc::vs_constants_per_frame), so every device animates alike.
  unsigned frames = 1;
  // The star moves from frame to frame (a still star: amplitude 0).
  bool moves() const { return amplitude > 0; }
};

// One zoomed copy: u' = scale·uv + offset per axis (uv as the quad listing sees it: texel
// x at x / W), and its weight.
struct RadialCopy {
  double scale = 1;
  std::array<double, 2> offset{0, 0};
  double weight = 0;
};
// The copies i = 1..N for a target of width × height (texel centres: the half texel included).
std::vector<RadialCopy> radial_copies(const RadialParams& r, uint32_t width, uint32_t height);
// The star's four offsets (in texture coordinates, half texel included) at `frame`.
std::array<std::array<double, 2>, 4> star_offsets(const RadialParams& r, unsigned frame,
                                                  uint32_t width, uint32_t height);

// The graph for glow's tier, size and format (`glow`: the other glow fields are unused) and
// the radial parameters. Errors name the parameter at fault.
PlanResult build_radial(const EffectParams& glow, const RadialParams& radial);

} // namespace tierlift::effects
