// The dx8 glow tier (glow.h): vs.1.1 + ps.1.3, Listings 3 + 4, 4 taps a blur pass; every
// helper pass is a vs.1.1 / ps.1.x listing too. The graph itself is built by
// glow_common.cpp; this file says only what is dx8's own.
#include "glow_common.h"

namespace tierlift::effects {

PlanResult build_glow_dx8(const GlowParams& params) {
  detail::TierRecipe r;
  r.tier = "dx8";
  // A ps.1.x constant clamps to [-1, 1], so intensity ≤ 1 goes into c0 as it is; above 1
  // the composite takes c0 = intensity / 4 and scales the product back with _x4 (exact: a
  // power of two), which reaches 4.
  const bool above_one = params.intensity_ramp.max(params.intensity) > 1;
  // The after-image's mix the same way for g.
  const bool gain_above_one = params.afterimage_gain_ramp.max(params.afterimage_gain) > 1;
  r.listings = {"glow/quad4_coords_vs11.vsh",
                "glow/extract_sources_ps11.psh",
                "glow/downsample4_ps13.psh",
                above_one ? "glow/composite_add_x4_ps13.psh" : "glow/composite_add_ps13.psh",
                "gpugems21/listing3_blur4_coords.vsh",
                "gpugems21/listing4_blur4_weighted_sum.psh",
                gain_above_one ? "glow/composite_add_x4_ps13.psh" : "glow/composite_add_ps13.psh",
                "glow/extract_fogged_ps11.psh"};
  r.taps_per_blur_pass = kTapsPerBlurPassDx8;
  r.one_stage_per_read = true; // tex t# reads texture stage #
  r.constants_clamp_to_one = true;
  r.composite_divisor = above_one ? 4 : 1;
  r.mix_divisor = gain_above_one ? 4 : 1;
  r.max_intensity = 4;
  r.why_limit = "a ps.1.x constant clamps to [-1, 1]; the composite's _x4 scales it by 4";
  return detail::build_glow_graph(params, r);
}

} // namespace tierlift::effects
