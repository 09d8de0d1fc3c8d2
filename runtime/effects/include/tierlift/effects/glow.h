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
#include <map>
#include <optional>
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

inline constexpr unsigned kTapsPerBlurPassDx9 = 8; // Listing 1's eight oT#
inline constexpr unsigned kTapsPerBlurPassDx8 = 4; // Listing 3's four oT#

// dx9: vs.2.0 + ps.2.0, Listings 1 + 2, 8 taps a pass. dx8: vs.1.1 + ps.1.3, Listings 3 + 4,
// 4 taps a pass, every helper pass in ps.1.x as well (values clamp to [-1, 1], constants too).
enum class Tier { Dx9, Dx8 };
std::string_view tier_name(Tier tier);                 // "dx9", "dx8"
std::optional<Tier> parse_tier(std::string_view name); // nullopt for anything else

struct GlowParams {
  Tier tier = Tier::Dx9;
  uint32_t width = 1280, height = 720; // the scene
  unsigned downsample = 2;             // 1..4
  img::Format format = img::Format::RGBA32F;
  bool half_texel = true;
  BlurProfile profile = default_blur_profile();
  double intensity = 1; // the composite adds intensity × glow (dx8: at most 1, a ps.1.x constant)
  // Built-in listing path ("gpugems21/listing2_blur8_weighted_sum.psh", "glow/…") → a file
  // to read instead (a scene that names its own listing). Empty: every listing built in.
  std::map<std::string, std::string, std::less<>> listing_files;
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

// The graph for one scene size and parameter set, for params.tier. Texture "scene" is its
// input. Every error names the parameter at fault.
GlowPlan build_glow(const GlowParams& params);
GlowPlan build_glow_dx9(const GlowParams& params);
GlowPlan build_glow_dx8(const GlowParams& params);

// The per-axis bilinear read positions that average N texels (position in texels from the
// start of the block, where texel k spans [k, k + 1]) and their weights.
struct AxisRead {
  double position = 0;
  double weight = 0;
};
std::vector<AxisRead> downsample_reads(unsigned n);

} // namespace tierlift::effects
