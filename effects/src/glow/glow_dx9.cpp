// The dx9 glow tier (glow.h): vs.2.0 + ps.2.0, Listings 1 + 2, 8 taps a blur pass. The
// graph itself is built by glow_common.cpp; this file says only what is dx9's own.
#include <limits>

#include "glow_common.h"

namespace tierlift::effects {

PlanResult build_glow_dx9(const EffectParams& params) {
  detail::TierRecipe r;
  r.tier = "dx9";
  r.listings = {"glow/quad4_coords.vsh",
                "glow/extract_sources.psh",
                "glow/downsample4.psh",
                "glow/composite_add.psh",
                "gpugems21/listing1_blur8_coords.vsh",
                "gpugems21/listing2_blur8_weighted_sum.psh",
                "glow/composite_add.psh",
                "glow/extract_fogged.psh"};
  r.taps_per_blur_pass = kTapsPerBlurPassDx9;
  r.one_stage_per_read = false; // texld tk, s0: one sampler serves every read
  // ps.2.0 constants are floats: c0 = intensity as it is.
  r.max_intensity = std::numeric_limits<float>::max();
  r.why_limit = "a ps.2.0 constant is a float";
  return detail::build_glow_graph(params, r);
}

} // namespace tierlift::effects
