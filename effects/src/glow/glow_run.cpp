#include "tierlift/effects/glow_run.h"

#include <fmt/format.h>

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
                           unsigned frames, const std::vector<std::string>& read_back,
                           const GlowFrameSink& sink, const SceneAt& scene_at) {
  GlowFrames out;
  if (!plan) {
    out.run.error = plan.error;
    return out;
  }
  out.images.emplace(std::string(kSceneTexture), scene);
  FrameSink frame_sink;
  if (sink)
    frame_sink = [&](unsigned f, PassDevice& d) -> std::string {
      ImageMap read;
      for (const std::string& name : read_back)
        if (std::string e = d.read_texture(name, read[name]); !e.empty())
          return fmt::format("reading '{}' back: {}", name, e);
      return sink(f, read);
    };
  FrameInputs inputs_at;
  if (scene_at)
    inputs_at = [&](unsigned f, ImageMap& changed) -> std::string {
      img::ImageResult im = scene_at(f);
      if (!im) return im.message();
      changed.emplace(std::string(kSceneTexture), std::move(*im));
      return {};
    };
  out.run = run_frames(plan.graph, device, out.images, frames, frame_sink, inputs_at);
  return out;
}

} // namespace tierlift::effects
