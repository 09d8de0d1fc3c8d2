// The Real-Time Glow (GPU Gems ch. 21) as an effect graph, tier dx9 (vs.2.0/ps.2.0):
//   extract     glow sources = scene rgb × alpha            (glow/extract_sources.psh)
//   downsample  bilinear, by N = 2..4 (skipped for N = 1)    (glow/downsample4.psh)
//   blur_h.i    Listings 1 + 2 as printed, 8 taps a pass; the passes of a wider kernel are
//               summed by ONE/ONE blending (the first replaces)
//   blur_v.i    the same along y
//   composite   final = scene + glow (bilinear upsampling)   (glow/composite_add.psh)
// Every helper pass uses glow/quad4_coords.vsh. Helper passes always sample where they
// mean to (texel centres or exact midpoints); only the blur offsets follow `half_texel`,
// the article's rule: +½ texel on every offset constant. Without it the taps land on
// texel corners and bilinear filtering averages the neighbours, as on D3D9 hardware.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/effects/blur_profile.h"
#include "tierlift/effects/graph.h"

namespace tierlift::effects {

inline constexpr std::string_view kSceneTexture = "scene"; // the input
inline constexpr std::string_view kSourcesTexture = "glow_sources";
inline constexpr std::string_view kSmallTexture = "glow_small"; // downsampled sources
inline constexpr std::string_view kBlurHTexture = "blur_h";
inline constexpr std::string_view kGlowTexture = "glow";
inline constexpr std::string_view kFinalTexture = "final";

inline constexpr unsigned kTapsPerBlurPass = 8; // Listing 1's eight oT#

struct GlowParams {
  uint32_t width = 1280, height = 720; // the scene
  unsigned downsample = 2;             // 1..4
  img::Format format = img::Format::RGBA32F;
  bool half_texel = true;
  BlurProfile profile = default_blur_profile();
  int subtexel_bits = 0; // conventions of every pass: match the device (lavapipe: 8)
};

struct GlowPlan {
  EffectGraph graph;
  std::vector<BlurTap> taps;                // one axis, the same for x and y
  uint32_t glow_width = 0, glow_height = 0; // ceil(size / downsample)
  unsigned blur_passes_per_axis = 0;
  std::string error; // non-empty: no graph
  explicit operator bool() const { return error.empty(); }
};

// The graph for one scene size and parameter set. Texture "scene" is its input.
GlowPlan build_glow_dx9(const GlowParams& params);

// The per-axis bilinear read positions that average N texels (position in texels from the
// start of the block, where texel k spans [k, k + 1]) and their weights.
struct AxisRead {
  double position = 0;
  double weight = 0;
};
std::vector<AxisRead> downsample_reads(unsigned n);

} // namespace tierlift::effects
