// Running an effect graph on one device: passes in order, images in a map between passes.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/graph.h"
#include "tierlift/ir/result.h"

namespace tierlift::effects {

struct PassRecord {
  std::string pass, target;
  img::Image result;              // the target after this pass (only when keep_pass_images)
  double ms = 0;                  // draw only (a readback for keep_pass_images is not counted)
  std::vector<uint8_t> midpoints; // the device's rounding-midpoint mask of `result`, if any
  // With keep_pass_images, what else the pass wrote: its targets beyond oC0 and its stencil
  // buffer (read as the device's read_texture gives it), compared like `result`.
  struct Extra {
    std::string target;
    img::Image result;
    std::vector<uint8_t> midpoints;
  };
  std::vector<Extra> more;
  pass::DrawReport report;              // what the device's draw said (its counters)
  std::vector<ir::Diagnostic> warnings; // and the warnings it gave with it
};

struct GraphRun {
  std::vector<PassRecord> passes;
  double total_ms = 0;
  double setup_ms = 0; // of total_ms: check, inputs, begin_run (before the first pass)
  // Every texture's rounding-midpoint mask after the run, where the device keeps one.
  std::map<std::string, std::vector<uint8_t>, std::less<>> midpoints;
};

// The draw a device makes of a pass: desc.draw as it is, with what the graph decides put in
// — the graph's conventions, one colour target per named target, and for a vertex listing
// without vertices the full-screen quad (pass::set_full_screen_quad_uv: the position input
// gets the corners, every dcl_texcoord input the quad uv (0,0) top-left … (1,1)
// bottom-right). No image is bound: the device that owns the graph's textures binds its own
// into the stages `desc.textures` names, by reference (CpuPassDevice) or as its resident
// copy (the Vulkan device), so nothing is copied.
pass::Pass graph_draw(const PassDesc& desc, const ir::Conventions& conventions);

// The rule of run_graph's and run_frames' failures (a graph the device could not run): one
// error whose message names the pass (and frame) that failed and the device, followed, when
// the device refused, by the device's own diagnostics as notes (severity Note: its words
// without the run's, for a caller that words the failure itself, e.g. `tierlift run`).
inline constexpr std::string_view kRunRule = "run";

// Checks the graph, requires every input texture in `images` (or carried by the graph:
// TextureDesc::contents) at its declared size (it is
// converted to the declared format with img::quantize), hands the inputs to the device,
// runs each pass there (reading its target back after it only when keep_pass_images), then
// reads every texture back: `images` holds every texture afterwards.
// `progress`, when set, is called before each pass runs (index from 0, pass count).
using PassProgress = std::function<void(size_t index, size_t count, const PassDesc& pass)>;
ir::Result<GraphRun> run_graph(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                               bool keep_pass_images = false, const PassProgress& progress = {});
// The same, reading back only the textures named in `read_back` (`images` gains those): for a
// caller that compares one target, as `tierlift test`'s differential run does, every other
// read-back (the inputs it uploaded) is a device round trip it does not need.
ir::Result<GraphRun> run_graph_reading(const EffectGraph& graph, PassDevice& device,
                                       ImageMap& images, const std::vector<std::string>& read_back);

// Setup apart from the steady state: what a graph costs to start on a device, and then
// what each frame costs.
struct FrameTimes {
  double setup_ms = 0;          // check, inputs, begin_run (textures, uploads, pipelines)
  std::vector<double> frame_ms; // each frame: every pass, then finish()
  double median_ms() const;     // 0 without frames
  double min_ms() const;
  double max_ms() const;
};

// Starts the graph once (as run_graph does), then runs all its passes `frames` times, the
// textures carried from one frame into the next (a pass that blends onto its target sees
// what the frame before left there: what feedback effects such as an after-image need; a
// graph whose every texture is first written by a Replace pass gives the same image every
// frame). Frame f (from 0) runs every pass as PassDesc::at_frame(f) (per-frame constants).
// Nothing is read back between frames unless `sink` is given: it is called after each
// frame's finish() (outside the frame's time) and may read textures from the device (the
// frames of an after-image); a failure from it ends the run. `images` holds every texture
// afterwards. run_graph is frame 0 of this.
// `inputs_at`, when set, is asked before every frame f ≥ 1 for the input textures that
// change (a moving scene): it fills the map (input name → image, at the declared size; it
// is stored in the declared format), and the device replaces them (update_input).
using FrameSink = std::function<ir::Status(unsigned frame, PassDevice& device)>;
// `progress`, when set, is told after each frame how many are done (1..frames) and of how
// many: a long --frames run on a terminal shows where it is (cli/progress_line.h).
using FrameInputs = std::function<ir::Status(unsigned frame, ImageMap& changed)>;
using FrameProgress = std::function<void(unsigned done, unsigned frames)>;
ir::Result<FrameTimes> run_frames(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                                  unsigned frames, const FrameSink& sink = {},
                                  const FrameInputs& inputs_at = {},
                                  const FrameProgress& progress = {});

} // namespace tierlift::effects
