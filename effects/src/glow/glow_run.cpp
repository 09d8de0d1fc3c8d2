#include "tierlift/effects/glow/glow_run.h"

#include <fmt/format.h>

namespace tierlift::effects {
EffectRun run_effect(const EffectPlan& plan, const img::Image& scene, PassDevice& device,
                     bool keep_pass_images, const PassProgress& progress) {
  ImageMap images;
  images.emplace(std::string(kSceneTexture), scene);
  ir::Result<GraphRun> run = run_graph(plan.graph, device, images, keep_pass_images, progress);
  return EffectRun{std::move(run), std::move(images)};
}

EffectFrames run_effect_frames(const EffectPlan& plan, const img::Image& scene, PassDevice& device,
                               unsigned frames, const std::vector<std::string>& read_back,
                               const EffectFrameSink& sink, const SceneAt& scene_at,
                               const FrameProgress& progress) {
  ImageMap images;
  images.emplace(std::string(kSceneTexture), scene);
  FrameSink frame_sink;
  if (sink)
    frame_sink = [&](unsigned f, PassDevice& d) -> ir::Status {
      ImageMap read;
      for (const std::string& name : read_back) {
        ir::Result<img::Image> image = d.read_texture(name);
        if (!image)
          return ir::fail(d.name(), "device",
                          fmt::format("reading '{}' back: {}", name, image.message()));
        read[name] = std::move(*image);
      }
      return sink(f, read);
    };
  FrameInputs inputs_at;
  if (scene_at)
    inputs_at = [&](unsigned f, ImageMap& changed) -> ir::Status {
      img::ImageResult im = scene_at(f);
      if (!im) return std::move(im).failure();
      changed.emplace(std::string(kSceneTexture), std::move(*im));
      return ir::ok_status();
    };
  ir::Result<FrameTimes> run =
      run_frames(plan.graph, device, images, frames, frame_sink, inputs_at, progress);
  return EffectFrames{std::move(run), std::move(images)};
}

} // namespace tierlift::effects
