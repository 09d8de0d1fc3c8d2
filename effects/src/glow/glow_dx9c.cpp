// The dx9c glow tier (glow.h): the dx9 tier's helper passes (vs.2.0 + ps.2.0) with a shader
// model 3 blur: vs_3_0 + ps_3_0, one loop over up to 64 taps a pass, each read by texldl at
// level 0, offsets and weights in constants the loop counter indexes. The graph is built by
// glow_common.cpp; this file says only what is dx9c's own.
#include <limits>

#include "glow_common.h"

namespace tierlift::effects {

PlanResult build_glow_dx9c(const EffectParams& params) {
  detail::TierRecipe r;
  r.tier = "dx9c";
  r.listings = {"glow/quad4_coords.vsh",  "glow/extract_sources.psh", "glow/downsample4.psh",
                "glow/composite_add.psh", "glow/blur_loop_vs30.vsh",  "glow/blur_loop_ps30.psh",
                "glow/composite_add.psh", "glow/extract_fogged.psh"};
  r.taps_per_blur_pass = kTapsPerBlurPassDx9c;
  r.loop_blur = true;
  r.one_stage_per_read = false; // texldl r2, r1, s0: one sampler serves every read
  r.max_intensity = std::numeric_limits<float>::max();
  r.why_limit = "a ps_3_0 constant is a float";
  return detail::build_glow_graph(params, r);
}

} // namespace tierlift::effects
