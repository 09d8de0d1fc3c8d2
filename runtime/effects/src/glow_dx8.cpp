// Builds the dx8 glow graph (see glow.h). PLACEHOLDER until the dx8 generator lands.
#include "tierlift/effects/glow.h"

namespace tierlift::effects {

GlowPlan build_glow_dx8(const GlowParams&) {
  GlowPlan plan;
  plan.error = "tier dx8: not built yet";
  return plan;
}

} // namespace tierlift::effects
