// The Real-Time Glow (GPU Gems ch. 21) as an effect graph. Both tiers build the same passes:
//   extract     glow sources = scene rgb × alpha, alpha kept (point reads at texel centres);
//               with a glow image or fog (glow_context.h) the glow image's, fogged by depth
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
// Tier dx9c (shader model 3 blur, glow_dx9c.cpp):
//   extract / downsample / composite  the dx9 tier's vs.2.0 + ps.2.0 helper listings
//   blur        glow/blur_loop_vs30.vsh + glow/blur_loop_ps30.psh: up to 64 taps a pass in
//               ONE `loop aL, i0` (i0 = (taps, 1, 2, 0)), each tap read by texldl at LOD 0
//               from uv + c[aL] and weighted by c[aL + 1] (ps c(2k+1) = offset of tap k,
//               c(2k+2) = its weight); every read through sampler s0. The analytic model
//               takes the pass's kernel as stated (AnalyticForm::Kernel: the same offsets
//               and weights, as floats), since it reads straight-line listings only. A ramped
//               weight scale is refused (the stated kernel has one set of weights).
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
#include <utility>
#include <vector>

#include "tierlift/effects/glow/blur_profile.h"
#include "tierlift/effects/glow/builtin_listing.h"
#include "tierlift/effects/glow/glow_context.h"
#include "tierlift/effects/glow/weight_quantize.h"
#include "tierlift/effects/graph/graph.h"
#include "tierlift/ir/ps1x_range.h"

namespace tierlift::effects {

inline constexpr std::string_view kSceneTexture = "scene"; // the input
inline constexpr std::string_view kSourcesTexture = "glow_sources";
inline constexpr std::string_view kSmallTexture = "glow_small"; // downsampled sources
inline constexpr std::string_view kBlurHTexture = "blur_h";
inline constexpr std::string_view kGlowTexture = "glow";
inline constexpr std::string_view kFinalTexture = "final";
// After-image: what the blur reads (x + g·previous) and, for Afterimage::Sources, last
// frame's copy of it.
inline constexpr std::string_view kFedTexture = "afterimage_fed";
inline constexpr std::string_view kSavedTexture = "afterimage_saved";

inline constexpr unsigned kTapsPerBlurPassDx9 = 8; // Listing 1's eight oT#
inline constexpr unsigned kTapsPerBlurPassDx8 = 4; // Listing 3's four oT#
inline constexpr unsigned kTapsPerBlurPassDx7 = 2; // two texture stages
// dx9c: one loop over the taps; 64 taps use c1..c128 (two constants a tap) of ps_3_0's 224.
inline constexpr unsigned kTapsPerBlurPassDx9c = 64;
// The built-in stage states of a dx7 blur quad (a scene's "listings" may replace it).
inline constexpr std::string_view kDx7BlurStates = "dx7/blur_pair.tss";

// dx9: vs.2.0 + ps.2.0, Listings 1 + 2, 8 taps a pass. dx8: vs.1.1 + ps.1.3, Listings 3 + 4,
// 4 taps a pass, every helper pass in vs.1.1 / ps.1.x as well (see the top of this file).
// dx7: two fixed-function texture stages, 2 taps a quad, 8-bit weights (see above).
// dx9c: dx9's helper passes with a vs_3_0 + ps_3_0 blur, one loop of texldl (see above).
enum class Tier { Dx9, Dx8, Dx7, Dx9c };
std::string_view tier_name(Tier tier);                 // "dx9", "dx8", "dx7", "dx9c"
std::optional<Tier> parse_tier(std::string_view name); // nullopt for anything else
// Every tier, in declaration order: the enum's values from 0 on for as long as tier_name and
// parse_tier round-trip them, so a tier added to the enum, tier_name and parse_tier joins
// every list (the report's sweep, messages) by itself.
std::vector<Tier> all_tiers();

// A numeric parameter as a function of the frame number (frames counted from 1, as the
// files frame-0001.png … are): keyframes (frame, value) with strictly increasing frames,
// linear between them, the first value before the first keyframe and the last after the
// last. Empty: the parameter's constant value every frame.
struct Keyframes {
  std::vector<std::pair<unsigned, double>> points;
  bool empty() const { return points.empty(); }
  // The value at `frame` (from 1); `constant` when there are no keyframes.
  double at(unsigned frame, double constant) const;
  // The largest value over every frame (`constant` when empty).
  double max(double constant) const;
  // Frames up to the last keyframe (0 when empty): after it the value holds.
  unsigned span() const { return points.empty() ? 0 : points.back().first; }
};

// After-image feedback (Tron 2.0, seed 002), at the glow's resolution, on the texture the
// blur reads (x: the downsampled glow sources):
//   Sources  the previous frame's fed sources s, dimmed by g, added to this frame's:
//            s_n = x + g·s_(n−1): a geometric series, steady state x / (1 − g) for g < 1
//   Glow     the previous frame's blurred glow y, dimmed by g, added to the sources:
//            y_n = B(x + g·y_(n−1)): steady state (I − gB)⁻¹Bx while g·‖B‖ < 1, where ‖B‖
//            is the square of the profile's tap sum (x then y); past that it runs away
enum class Afterimage { Off, Sources, Glow };
std::string_view afterimage_name(Afterimage mode); // "off", "sources", "glow"

// The built-in scene's round lights moving on circles over the frames (a moving scene for
// the after-image): radius in scene heights, one turn every `period` frames. Off: still.
struct Motion {
  double radius = 0;
  unsigned period = 0;
  bool on() const { return period > 0 && radius > 0; }
};

// What every effect reads from a scene (size, tier, format, blur profile, intensity,
// listings; radial beams, the stencil outline and the GLSL blur take these too) and what only
// the glow reads (downsample, after-image, context, fog). Named for every effect, not the glow.
struct EffectParams {
  Tier tier = Tier::Dx9;
  uint32_t width = 1280, height = 720; // the scene
  unsigned downsample = 4;             // 1..4
  img::Format format = img::Format::RGBA32F;
  bool half_texel = true;
  BlurProfile profile = default_blur_profile();
  // The composite adds intensity × glow. Finite and ≥ 0; dx8 at most 4 (see above).
  double intensity = 3;
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
  // Every blur tap weight times this (both axes: the glow scales by its square); ≥ 0.
  double weight_scale = 1;
  Afterimage afterimage = Afterimage::Off;
  double afterimage_gain = 0.5; // g, ≥ 0 (tier dx8: at most 4, as intensity)
  // Ramped parameters (Keyframes; empty: the constant above). A ramp's values follow the
  // constant's own range.
  Keyframes intensity_ramp, weight_scale_ramp, afterimage_gain_ramp;
  Motion motion; // the built-in scene only
  // A separate glow render and the glow fog (glow_context.h); off: the scene's rgb × alpha.
  GlowContext context;
  // True when any frame differs from the first (a ramp or an after-image): --frames then
  // reads every frame back.
  bool animated() const {
    return afterimage != Afterimage::Off || motion.on() || !intensity_ramp.empty() ||
           !weight_scale_ramp.empty() || !afterimage_gain_ramp.empty();
  }
};

// An effect's graph and what the run reports about how it was built (every effect builder
// returns one; the glow fills all of it).
struct EffectPlan {
  EffectGraph graph;
  std::vector<BlurTap> taps; // one axis, the same for x and y
  // Tier dx7: the bytes the weights became (taps' order), and what that costs in brightness
  // (quantization_summary); empty for the shader tiers.
  std::vector<uint8_t> weight_bytes;
  std::string quantization;
  uint32_t glow_width = 0, glow_height = 0; // ceil(size / downsample)
  unsigned downsample = 1;
  unsigned blur_passes_per_axis = 0;
  std::vector<std::string> warnings; // the graph runs, but not as asked (e.g. clamped weights)
};

// A plan, or why there is none: one error (rule kPlanRule) naming the parameter at fault or
// the listing.
using PlanResult = ir::Result<EffectPlan>;
inline constexpr std::string_view kPlanRule = "glow";
inline ir::Failure plan_failure(std::string message) {
  return ir::fail("glow", std::string(kPlanRule), std::move(message));
}

// The graph for one scene size and parameter set, for params.tier. Texture "scene" is its
// input. Every error names the parameter at fault ("downsample 9: expected 1..4",
// "intensity 4.5: tier dx8 reaches at most 4 (…)", "scene size 0x27: …"), or the listing.
PlanResult build_glow(const EffectParams& params);
PlanResult build_glow_dx9(const EffectParams& params);
PlanResult build_glow_dx8(const EffectParams& params);
PlanResult build_glow_dx7(const EffectParams& params);
PlanResult build_glow_dx9c(const EffectParams& params);

// The after-image's loop gain: g (Sources), or g·S² (Glow: S = the tap sum of one axis
// times the weight scale), with g and the scale at their largest over the frames. 0: off.
double afterimage_loop_gain(const EffectParams& params, const std::vector<BlurTap>& taps);
// The RGBA8 stall of a loop that multiplies a level L (in steps of 1/255) by k each frame:
// the largest L with round(k·L) = L, i.e. L·(1 − k) < ½, so a fading trail stops there;
// 0 when none (k ≤ ½) or k outside (0, 1).
int rgba8_stall_level(double k);
// Runaway (loop gain ≥ 1) and, in rgba8, the stall, each naming the fix; empty otherwise.
std::vector<std::string> afterimage_warnings(const EffectParams& params,
                                             const std::vector<BlurTap>& taps);

// The per-axis read positions that average N texels (position in texels from the start of
// the block, where texel k spans [k, k + 1]: the centres k + ½) and their weights (1/N).
// The downsample passes point-read every pair of them: N² reads, four a pass.
struct AxisRead {
  double position = 0;
  double weight = 0;
};
std::vector<AxisRead> downsample_reads(unsigned n);

} // namespace tierlift::effects
