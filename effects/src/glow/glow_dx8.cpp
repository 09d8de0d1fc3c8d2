// The dx8 glow tier (glow.h): vs.1.1 + ps.1.3, Listings 3 + 4, 4 taps a blur pass; every
// helper pass is a vs.1.1 / ps.1.x listing too. The graph itself is built by
// glow_common.cpp; this file says only what is dx8's own.
#include "glow_common.h"

namespace tierlift::effects {

PlanResult build_glow_dx8(const EffectParams& params) {
  // A ps.1.x constant clamps to [-1, 1], so intensity ≤ 1 goes into c0 as it is; above 1
  // the composite takes c0 = intensity / 4 and scales the product back with _x4 (exact: a
  // power of two), which reaches 4 (ps1x_recipe).
  detail::TierRecipe r = detail::ps1x_recipe(params);
  r.tier = "dx8";
  r.listings.blur_vs = "gpugems21/listing3_blur4_coords.vsh";
  r.listings.blur_ps = "gpugems21/listing4_blur4_weighted_sum.psh";
  r.taps_per_blur_pass = kTapsPerBlurPassDx8;
  r.why_limit = "a ps.1.x constant clamps to [-1, 1]; the composite's _x4 scales it by 4";
  return detail::build_glow_graph(params, r);
}

} // namespace tierlift::effects
