// Running a scene, whatever its effect, the way `tierlift glow` does: build the effect's
// graph, check that its memory fits, read the scene image, leave out what the image does not
// need (prune.h), run the graph on every way asked for (cpu, vulkan, analytic), compare every
// pair of ways pass by pass, and with `frames` run the steady state (a still scene) or every
// frame of a moving scene, compared frame by frame. A front end (the CLI, a test, a corpus
// runner) only chooses the options and shows the result.
//
//   SceneRunOptions o;
//   o.backends = *parse_backends("cpu,analytic", {"cpu", "vulkan", "analytic"});
//   ir::Result<SceneRun> run = run_scene(*load_scene("scene.json", ""), o);
//   for (const PairAgreement& p : run->pairs) … p.agreement.all_pass …
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/prune.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/backends.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/io/output_folder.h"
#include "tierlift/ir/result.h"

namespace tierlift::effects {

// One way of computing the scene ("cpu", "vulkan", "analytic") and its run.
struct WayRun {
  std::string name;
  EffectRun glow;
};

// The agreement of two ways, `a` and `b` naming them.
struct PairAgreement {
  std::string a, b;
  RunAgreement agreement;
};

// Every pair of `ways` in order (cpu·vulkan, cpu·analytic, vulkan·analytic), on the final
// image; fails (rule "agreement") when two runs cannot be compared.
ir::Result<std::vector<PairAgreement>> compare_ways(const std::vector<WayRun>& ways);

// With `frames`: one device's setup and steady-state frames (run_frames).
struct FrameReport {
  std::string device;
  FrameTimes times;
};

// A moving scene's frames, one pair of devices over every frame: the worst frame's figures.
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

struct SceneRunOptions {
  BackendChoice backends;                    // the ways asked for (parse_backends)
  vulkan::DeviceOptions vulkan;              // for the process's Vulkan device (gpu_filter)
  unsigned threads = 0;                      // the CPU device's (0: as many as the machine has)
  unsigned frames = 0;                       // N frames per device after the compared run (0: none)
  bool prune = true;                         // leave out what the scene does not need (prune.h)
  io::OutputFolder* frames_folder = nullptr; // a moving scene's frames: the first device's
                                             // frame-NNNN.png and frames-strip.png
  // Progress, per way: before each pass of the compared run, after each of N frames.
  std::function<PassProgress(const std::string& way)> pass_progress;
  std::function<FrameProgress(const std::string& way)> frame_progress;
};

struct SceneRun {
  Scene scene;           // as run: its warnings all of the run's, a radial star's frame count set
  EffectPlan plan;       // the graph as run (pruned unless the options or a moving scene forbid it)
  PrunedGraph pruned;    // what pruning left out (also when it was not applied)
  bool moves = false;    // the scene changes from frame to frame (scene_animated)
  bool animated = false; // moves, and frames > 0: `animation` holds the frames
  SelectedWays selected; // the ways that ran (Vulkan left out under "all" without a device)
  std::string vulkan_device; // its name when vulkan ran
  std::vector<WayRun> ways;
  std::vector<PairAgreement> pairs;
  std::vector<FrameReport> frames; // frames > 0 on a still scene
  Animation animation;             // frames > 0 on a moving scene
  uint64_t planned_bytes = 0;      // the run's peak, planned before it (memory_plan.h)
  // Every pair within docs/design.md's targets, and every frame pair of an animation.
  bool all_within() const;
};

// The rules of run_scene's failures; each error names its subject where it has one (the
// scene's file, its image). Warnings come before the error, in the order they arose, and on
// success with the result: the effect's parameters' ("scene", subject the scene's file or
// "tierlift glow"), then "backend" (Vulkan left out under "all").
//   "scene": the effect cannot be built, or the image is wrong; "io": the image cannot be
//   read; "memory": the peak exceeds the memory available; "device": a Vulkan device asked
//   for cannot be had; "run": a way failed; "agreement": two ways cannot be compared;
//   "frames": a frame run failed or a still scene's last frame differs from the compared run.
ir::Result<SceneRun> run_scene(const Scene& scene, const SceneRunOptions& options);

} // namespace tierlift::effects
