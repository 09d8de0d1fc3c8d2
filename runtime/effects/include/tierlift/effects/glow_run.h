// Running a glow plan over a scene on one device.
#pragma once

#include "tierlift/effects/glow.h"
#include "tierlift/effects/run_graph.h"

namespace tierlift::effects {

struct GlowRun {
  GraphRun run;
  ImageMap images; // every texture of the graph afterwards ("scene", …, "glow", "final")
};

// The scene must have the plan's scene size; it is stored in the plan's format first.
GlowRun run_glow(const GlowPlan& plan, const img::Image& scene, PassDevice& device,
                 bool keep_pass_images = false, const PassProgress& progress = {});

} // namespace tierlift::effects
