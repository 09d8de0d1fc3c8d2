#include "tierlift/effects/glow_run.h"

namespace tierlift::effects {

GlowRun run_glow(const GlowPlan& plan, const img::Image& scene, PassDevice& device,
                 bool keep_pass_images, const PassProgress& progress) {
  GlowRun out;
  if (!plan) {
    out.run.error = plan.error;
    return out;
  }
  out.images.emplace(std::string(kSceneTexture), scene);
  out.run = run_graph(plan.graph, device, out.images, keep_pass_images, progress);
  return out;
}

GlowFrames run_glow_frames(const GlowPlan& plan, const img::Image& scene, PassDevice& device,
                           unsigned frames) {
  GlowFrames out;
  if (!plan) {
    out.run.error = plan.error;
    return out;
  }
  out.images.emplace(std::string(kSceneTexture), scene);
  out.run = run_frames(plan.graph, device, out.images, frames);
  return out;
}

} // namespace tierlift::effects
