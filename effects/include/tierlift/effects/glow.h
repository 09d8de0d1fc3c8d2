// The Real-Time Glow (GPU Gems ch. 21) as an effect graph. Both tiers build the same passes:
//   extract     glow sources = scene rgb × alpha, alpha kept (point reads at texel centres)
//   downsample.i  the box average of each N×N block, N = 2..4 (skipped for N = 1): point
//               reads at texel centres, four a pass, weights 1/N², the passes summed by
//               ONE/ONE (N = 2: one pass, 3: three, 4: four); the quad uv is scaled by
//               N·ceil(W/N)/W for sizes not a multiple of N. Point reads because a bilinear
//               read between texels turns fp32 coordinate error (≈ N·2^-24 texel) into a
//               weight error that the three ways would see differently (glow_common.cpp).
//   blur_h.i    the article's blur listings as printed, k taps a pass; the passes of a wider
//               kernel are summed by ONE/ONE blending (the first of an axis replaces)
//   blur_v.i    the same along y
//   composite   final = scene + intensity × glow (glow read bilinearly), scene alpha kept
// Tier dx9 (vs.2.0 + ps.2.0):
//   helper vertex listing  glow/quad4_coords.vsh (oTk = uv · c(k+4) + ck)
//   extract / downsample / composite  glow/extract_sources.psh, glow/downsample4.psh,
//               glow/composite_add.psh (c0 = intensity)
//   blur        Listings 1 + 2, 8 taps a pass: vs c0..c7 = offsets, ps c0..c7 = weights;
//               every read through sampler s0
// Tier dx8 (vs.1.1 + ps.1.x), every pass a Direct3D 8 era listing:
//   helper vertex listing  glow/quad4_coords_vs11.vsh (same constants; mul + add, since a
//               vs.1.1 instruction reads one constant register)
//   extract     glow/extract_sources_ps11.psh (ps.1.1)
//   downsample  glow/downsample4_ps13.psh (Listing 4's shape: four weighted reads)
//   composite   glow/composite_add_ps13.psh (c0 = intensity) for intensity ≤ 1, else
//               glow/composite_add_x4_ps13.psh (c0 = intensity / 4, product _x4): a ps.1.x
//               constant clamps to [-1, 1], so dx8 reaches intensity 4 at most
//   blur        Listings 3 + 4, 4 taps a pass: vs c0..c3 = offsets, ps c0..c3 = weights;
//               t# reads texture stage #, so the source is bound to stages 0..3
//   ps.1.x ranges apply: texture reads lie in [0, 1] (a float scene above 1 reads as 1),
//   registers and constants clamp to [-1, 1], so the final frame is at most 1 as well.
// Tier dx7 (no shaders: two fixed-function texture stages, glow_dx7.cpp):
//   blur        quads of two taps each, drawn with the texture-stage states of
//               dx7/blur_pair.tss lowered into a vs.1.1 + ps.1.1 pair (stage_states.h); the
//               two weights travel as one 8-bit D3DCOLOR vertex colour (rgb: the first tap,
//               alpha: the second), rounded plainly or with Tron 2.0's error carry
//               (weight_quantize.h); the quads are summed by ONE/ONE blending
//   extract / downsample / composite  the dx8 tier's ps.1.x helper listings
//   ps.1.x registers clamp to [-1, 1] (MaxPixelShaderValue 1 whatever the scene says), which
//   is Direct3D 7's per-stage saturation for the non-negative values of the blur.
// Blur constants follow the article's rule: tap k of a texture W wide has the offset
// (k + ½)/W, the half texel added on the CPU (`half_texel`; without it the taps land on texel
// corners and bilinear filtering averages the neighbours, as on D3D9 hardware); padding taps
// of a pass's last group read the centre with weight 0. Helper passes always sample where
// they mean to; only the blur offsets follow `half_texel`. Blur filtering: with the half
// texel every tap sits on a texel centre, where a bilinear read is that texel, and the
// passes say so with point filtering — which also keeps fp32 texture-coordinate error
// (≈ W·2^-24 texel: a bilinear weight off by that much at a sharp edge, 2e-5 at 640 texels)
// out of the result; without it the taps sit on corners and bilinear filtering averages the
// four texels around each, the article's failure case.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/effects/blur_profile.h"
#include "tierlift/effects/builtin_listing.h"
#include "tierlift/effects/graph.h"
#include "tierlift/effects/weight_quantize.h"
#include "tierlift/ir/ps1x_range.h"

namespace tierlift::effects {

inline constexpr std::string_view kSceneTexture = "scene"; // the input
inline constexpr std::string_view kSourcesTexture = "glow_sources";
inline constexpr std::string_view kSmallTexture = "glow_small"; // downsampled sources
inline constexpr std::string_view kBlurHTexture = "blur_h";
inline constexpr std::string_view kGlowTexture = "glow";
inline constexpr std::string_view kFinalTexture = "final";

inline constexpr unsigned kTapsPerBlurPassDx9 = 8; // Listing 1's eight oT#
inline constexpr unsigned kTapsPerBlurPassDx8 = 4; // Listing 3's four oT#
inline constexpr unsigned kTapsPerBlurPassDx7 = 2; // two texture stages
// The built-in stage states of a dx7 blur quad (a scene's "listings" may replace it).
inline constexpr std::string_view kDx7BlurStates = "dx7/blur_pair.tss";

// dx9: vs.2.0 + ps.2.0, Listings 1 + 2, 8 taps a pass. dx8: vs.1.1 + ps.1.3, Listings 3 + 4,
// 4 taps a pass, every helper pass in vs.1.1 / ps.1.x as well (see the top of this file).
// dx7: two fixed-function texture stages, 2 taps a quad, 8-bit weights (see above).
enum class Tier { Dx9, Dx8, Dx7 };
std::string_view tier_name(Tier tier);                 // "dx9", "dx8", "dx7"
std::optional<Tier> parse_tier(std::string_view name); // nullopt for anything else
// Every tier, in declaration order: the enum's values from 0 on for as long as tier_name and
// parse_tier round-trip them, so a tier added to the enum, tier_name and parse_tier joins
// every list (the report's sweep, messages) by itself.
std::vector<Tier> all_tiers();

struct GlowParams {
  Tier tier = Tier::Dx9;
  uint32_t width = 1280, height = 720; // the scene
  unsigned downsample = 2;             // 1..4
  img::Format format = img::Format::RGBA32F;
  bool half_texel = true;
  BlurProfile profile = default_blur_profile();
  // The composite adds intensity × glow. Finite and ≥ 0; dx8 at most 4 (see above).
  double intensity = 1;
  // Built-in listing path ("gpugems21/listing2_blur8_weighted_sum.psh", "glow/…") → a file
  // to read instead (a scene that names its own listing). Empty: every listing built in.
  std::map<std::string, std::string, std::less<>> listing_files;
  // -D, -I, --profile, --skip-validation for every listing, built-in or from a file.
  ListingOptions listing_options;
  int subtexel_bits = 0; // conventions of every pass: match the device (lavapipe: 8)
  // ps_1_x register range of every pass (tier dx8): the preset d3d9 unless a scene or
  // --ps1x-max names another (ir/ps1x_range.h).
  float ps1x_max = ir::default_ps1x_max();
  // Tier dx7: how the blur weights become 8-bit vertex colours (weight_quantize.h).
  WeightRounding weight_rounding = WeightRounding::ErrorCarry;
};

struct GlowPlan {
  EffectGraph graph;
  std::vector<BlurTap> taps; // one axis, the same for x and y
  // Tier dx7: the bytes the weights became (taps' order), and what that costs in brightness
  // (quantization_summary); empty for the shader tiers.
  std::vector<uint8_t> weight_bytes;
  std::string quantization;
  uint32_t glow_width = 0, glow_height = 0; // ceil(size / downsample)
  unsigned blur_passes_per_axis = 0;
  std::string error;                 // non-empty: no graph
  std::vector<std::string> warnings; // the graph runs, but not as asked (e.g. clamped weights)
  explicit operator bool() const { return error.empty(); }
};

// The graph for one scene size and parameter set, for params.tier. Texture "scene" is its
// input. Every error names the parameter at fault ("downsample 9: expected 1..4",
// "intensity 4.5: tier dx8 reaches at most 4 (…)", "scene size 0x27: …"), or the listing.
GlowPlan build_glow(const GlowParams& params);
GlowPlan build_glow_dx9(const GlowParams& params);
GlowPlan build_glow_dx8(const GlowParams& params);
GlowPlan build_glow_dx7(const GlowParams& params);

// The per-axis read positions that average N texels (position in texels from the start of
// the block, where texel k spans [k, k + 1]: the centres k + ½) and their weights (1/N).
// The downsample passes point-read every pair of them: N² reads, four a pass.
struct AxisRead {
  double position = 0;
  double weight = 0;
};
std::vector<AxisRead> downsample_reads(unsigned n);

} // namespace tierlift::effects
