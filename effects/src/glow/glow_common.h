// What the glow tiers share (internal): parameter checks, the texture list, where every
// helper pass reads (texel centres, exact midpoints for the downsample, the scale for sizes
// that are not multiples of N), the blur constants by the article's rule, and the graph's
// assembly. A tier (glow_dx9.cpp, glow_dx8.cpp) says only what differs: its listings, its
// taps per blur pass, how a pixel listing reaches its texture (one sampler for every read,
// or one texture stage per read), its composite constant and its intensity limit.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/glow/stage_states.h"

namespace tierlift::effects::detail {

// Built-in listing paths ("glow/…", "gpugems21/…") of one tier.
struct TierListingPaths {
  std::string_view helper_vs; // every helper pass: oTk = uv · c(k+4) + ck, k = 0..3
  std::string_view extract_ps, downsample_ps, composite_ps;
  std::string_view blur_vs, blur_ps; // the article's listings
  // The after-image's mix: out = t0 + c0·t1 (a composite listing; used only with one).
  std::string_view mix_ps;
  // The fogged extract (glow_context.h; used only with fog).
  std::string_view fogged_ps;
};

struct TierRecipe {
  std::string_view tier; // "dx9", "dx8": for messages
  TierListingPaths listings;
  unsigned taps_per_blur_pass = 0;
  // ps_2_0 samples every read through one sampler s0 (texld tk, s0); ps_1_1..1_3 read
  // t# from texture stage #, so a texture read k times is bound to stages 0..k−1.
  bool one_stage_per_read = false;
  // The composite's c0.rgb = intensity / composite_divisor multiplies the glow (the dx8
  // listing for intensities above 1 scales it back with _x4); c0.a is unused.
  double composite_divisor = 1;
  // The same for the after-image's mix: c0.rgb = g / mix_divisor.
  double mix_divisor = 1;
  // ps.1.x: constants clamp to [-1, 1], so a tap weight above 1 is used as 1 (a warning).
  bool constants_clamp_to_one = false;
  // Intensity above this is an error; why_limit explains it in the message.
  double max_intensity = 0;
  std::string_view why_limit;
  // Tier dx7: the blur is drawn as quads of these lowered texture-stage states (two taps a
  // quad: offsets in vs c0/c1, the weights as the D3DCOLOR in vs c8: rgb the first, alpha
  // the second) instead of listings.blur_vs/blur_ps, which are then not loaded.
  std::shared_ptr<const tss::Lowered> stage_blur;
  // Tier dx9c: listings.blur_ps is ONE loop over a pass's taps (i0 = (taps, 1, 2, 0), tap k's
  // offset in ps c(2k+1), its weight in c(2k+2)), and the analytic model takes the kernel
  // the pass states (AnalyticForm::Kernel) instead of reading the listing.
  bool loop_blur = false;
  WeightRounding rounding = WeightRounding::ErrorCarry;
};

// The recipe the ps.1.x tiers (dx8, dx7) share: vs.1.1 helper listings, ps.1.x extract,
// downsample, composite and mix, one stage per read, constants clamped to [−1, 1], and an
// intensity (and after-image gain) above 1 reached as c0 = value / 4 times the listing's
// _x4 (exact: a power of two), up to 4. The tier fills in its name, the blur listings, its
// taps per blur pass and the reason for the limit.
TierRecipe ps1x_recipe(const EffectParams& params);

// Checks the parameters every tier shares (downsample, size, intensity ≥ 0 and finite,
// intensity ≤ recipe.max_intensity), loads the listings, samples the profile and builds
// the graph. Errors name the parameter (or the listing) at fault.
PlanResult build_glow_graph(const EffectParams& params, const TierRecipe& recipe);

// A ramped parameter's value for frames 1..ramp.span() (glow_frames.cpp); empty when the
// parameter does not ramp.
std::vector<double> ramp_values(const Keyframes& ramp);

} // namespace tierlift::effects::detail
