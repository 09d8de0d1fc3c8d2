// Internal to run_scene: the frames of a moving scene (after-image, ramped parameters, moving
// lights, a radial star that moves) on every device, compared frame by frame.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tierlift/effects/scenes/scene_run.h"

namespace tierlift::effects {

// A fresh device of the kind `name` names ("cpu", "vulkan", "analytic").
using DeviceMaker = std::function<std::unique_ptr<PassDevice>(const std::string& name)>;

// Runs `frames` frames of the plan on each device `devices` names (in order), compares
// each later device with each earlier one frame by frame (the final image), and writes the
// first device's frames into `folder` when there is one (frame-0001.png …, and a contact
// strip frames-strip.png; committed by the caller, with the other images). Empty string on
// success, else why.
std::string run_animation(const EffectPlan& plan, const img::Image& scene,
                          const std::vector<std::string>& devices, const DeviceMaker& make,
                          unsigned frames, io::OutputFolder* folder, const SceneAt& scene_at,
                          const std::function<FrameProgress(const std::string&)>& progress,
                          Animation& out);

} // namespace tierlift::effects
