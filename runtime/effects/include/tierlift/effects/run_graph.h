// Running an effect graph on one device: passes in order, images in a map between passes.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/effects/device.h"
#include "tierlift/effects/graph.h"

namespace tierlift::effects {

struct PassRecord {
  std::string pass, target;
  img::Image result;              // the target after this pass (only when keep_pass_images)
  double ms = 0;                  // run_pass only (a readback for keep_pass_images is not counted)
  std::vector<uint8_t> midpoints; // the device's rounding-midpoint mask of `result`, if any
};

struct GraphRun {
  bool ok = false;
  std::string error; // names the pass that failed
  std::vector<PassRecord> passes;
  double total_ms = 0;
  // Every texture's rounding-midpoint mask after the run, where the device keeps one.
  std::map<std::string, std::vector<uint8_t>, std::less<>> midpoints;
};

// The cpu::Pass a pass description becomes: full-screen quad (the vertex listing's
// dcl_position input gets the corners, every dcl_texcoord input the quad uv (0,0) top-left
// … (1,1) bottom-right), constants, bound textures from `images`, blend, conventions.
// Textures not in `images` are an error (returned in *error, nullopt).
std::optional<cpu::Pass> make_pass(const PassDesc& desc, const ImageMap& images,
                                   const ir::Conventions& conventions, std::string* error);

// Checks the graph, requires every input texture in `images` at its declared size (it is
// converted to the declared format with img::quantize), hands the inputs to the device,
// runs each pass there (reading its target back after it only when keep_pass_images), then
// reads every texture back: `images` holds every texture afterwards.
// `progress`, when set, is called before each pass runs (index from 0, pass count).
using PassProgress = std::function<void(size_t index, size_t count, const PassDesc& pass)>;
GraphRun run_graph(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                   bool keep_pass_images = false, const PassProgress& progress = {});

} // namespace tierlift::effects
