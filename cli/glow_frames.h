// `tierlift glow --frames N` on an animated scene (after-image, ramped parameters): every
// device runs the N frames, each frame's final image is read back, the devices are compared
// frame by frame against docs/design.md's targets, and with -o the first device's frames
// are written (frame-0001.png …) with a contact strip (frames-strip.png).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glow_report.h"
#include "tierlift/effects/glow_run.h"
#include "tierlift/io/output_folder.h"

namespace tierlift::cli {

// One pair of devices over every frame: the worst frame's figures.
struct FramePairAgreement {
  std::string a, b;
  unsigned frames = 0, frames_within = 0;
  double worst_max_abs = 0;   // over every frame
  double worst_identical = 1; // the smallest identical share of any frame
  unsigned worst_frame = 0;   // from 1: where worst_max_abs occurs
  std::string first_failure;  // the first frame beyond the targets, described
};

struct Animation {
  std::vector<FrameReport> times;
  std::vector<FramePairAgreement> pairs;
  bool all_within() const;
};

using DeviceFactory = std::function<std::unique_ptr<effects::PassDevice>(const std::string&)>;

// Runs `frames` frames of the plan on each device `devices` names (in order), compares
// each later device with each earlier one frame by frame (the final image), and writes the
// first device's frames into `folder` when there is one (committed by the caller, with
// the glow's images). Empty string on success, else why.
std::string run_animation(const effects::GlowPlan& plan, const img::Image& scene,
                          const std::vector<std::string>& devices, const DeviceFactory& make,
                          unsigned frames, io::OutputFolder* folder,
                          const effects::SceneAt& scene_at, Animation& out);

void print_animation(const Animation& a);
nlohmann::json animation_json(const Animation& a);

} // namespace tierlift::cli
