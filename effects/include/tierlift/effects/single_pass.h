// `tierlift run` as an effect graph: the pass::Pass that pass::prepare_pass makes from the
// command's flags becomes a graph of one pass, so the CPU and the Vulkan device draw it
// through the one device interface (effects::PassDevice, run_graph) exactly as they draw
// every effect's passes.
//
//   ir::Result<pass::Pass> prepared = pass::prepare_pass(request);
//   ir::Result<EffectGraph> graph = single_pass_graph(*prepared, 64, 64, img::Format::RGBA8);
//   CpuPassDevice cpu;
//   ImageMap images;
//   ir::Result<GraphRun> run = run_graph(*graph, cpu, images);
//   const img::Image& image = images.at(std::string(kSinglePassTarget));
#pragma once

#include <cstdint>
#include <string_view>

#include "tierlift/effects/graph.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"

namespace tierlift::effects {

inline constexpr std::string_view kSinglePass = "run";          // the pass's name
inline constexpr std::string_view kSinglePassTarget = "target"; // the texture it renders into

// `pass` drawn into a new width × height target of `format` (zeros before the draw), as a
// graph of one pass. Every image the pass binds is an input texture the graph carries
// (TextureDesc::contents, shared, not copied) at its own size and in its own format, so
// run_graph hands it to the device unchanged; it is named s# after the first sampler stage
// that binds it (an image bound to several stages is one texture). The pass keeps its
// listings (either may be absent), its constant banks (c#, i#, b#), its geometry (vertices
// and triangles, or constant pixel inputs without a vertex listing), scissor, blend and
// conventions. What a PassDesc does not describe is refused (rule "graph"): pre-transformed
// vertices, fixed-function stages, a viewport other than the whole target, texture-stage
// state, more than one colour target, a depth/stencil state, a SPIR-V pixel stage, the
// scalar executor (a CPU device's own choice: CpuPassDevice).
ir::Result<EffectGraph> single_pass_graph(const pass::Pass& pass, uint32_t width, uint32_t height,
                                          img::Format format);

} // namespace tierlift::effects
