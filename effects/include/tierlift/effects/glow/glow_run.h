// Running an effect's plan (any effect: glow, radial beams, stencil outline, GLSL blur) over a
// scene on one device.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/image/io.h"

namespace tierlift::effects {

struct EffectRun {
  ir::Result<GraphRun> run;
  ImageMap images; // every texture of the graph afterwards ("scene", …, "glow", "final")
};

// The scene must have the plan's scene size; it is stored in the plan's format first.
EffectRun run_effect(const EffectPlan& plan, const img::Image& scene, PassDevice& device,
                     bool keep_pass_images = false, const PassProgress& progress = {});

struct EffectFrames {
  ir::Result<FrameTimes> run;
  ImageMap images; // every texture after the last frame
};

// `frames` frames of the plan over the scene on one device (run_frames): setup apart from
// the steady state.
// `read_back` names textures read back after every frame and handed to `sink` (frame from
// 0): the frames of an animated glow (EffectParams::animated), without keeping them all.
// `scene_at`, when set, gives the scene of frame f (from 0; asked for f ≥ 1): a moving scene.
using SceneAt = std::function<img::ImageResult(unsigned frame)>;
using EffectFrameSink = std::function<ir::Status(unsigned frame, const ImageMap& images)>;
EffectFrames run_effect_frames(const EffectPlan& plan, const img::Image& scene, PassDevice& device,
                               unsigned frames, const std::vector<std::string>& read_back = {},
                               const EffectFrameSink& sink = {}, const SceneAt& scene_at = {},
                               const FrameProgress& progress = {});

} // namespace tierlift::effects
