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

struct GlowFrames {
  FramesRun run;
  ImageMap images; // every texture after the last frame
};

// `frames` frames of the plan over the scene on one device (run_frames): setup apart from
// the steady state.
GlowFrames run_glow_frames(const GlowPlan& plan, const img::Image& scene, PassDevice& device,
                           unsigned frames);

} // namespace tierlift::effects
