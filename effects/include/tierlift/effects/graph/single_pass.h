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
//
// or, on every way `--backend` names, compared: run_single_pass (below).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/effects/graph/backends.h"
#include "tierlift/effects/graph/graph.h"
#include "tierlift/image/compare.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"

namespace tierlift::effects {

inline constexpr std::string_view kSinglePass = "run";          // the pass's name
inline constexpr std::string_view kSinglePassTarget = "target"; // the texture it renders into
inline constexpr std::string_view kSinglePassDepth = "depth";   // its depth buffer, if any

// The depth buffer of a pass with a depth state (pass::uses_depth(pass.depth_stencil)): every pixel
// starts at `clear`, or at `initial`'s red channel (a target-sized image) when given.
struct SinglePassDepth {
  float clear = 1.0f;
  std::shared_ptr<const img::Image> initial;
};

// `pass` drawn into a new width × height target of `format` (zeros before the draw), as a
// graph of one pass. The pass becomes the graph pass's draw as it is (PassDesc::draw: its
// listings, either may be absent, constant banks, geometry, stage states, scissor, blend);
// only its bound images leave it: each is an input texture the graph carries
// (TextureDesc::contents, shared, not copied) at its own size and in its own format, so
// run_graph hands it to the device unchanged; it is named s# after the first sampler stage
// that binds it (an image bound to several stages is one texture) and bound by that name.
// The graph's conventions are the pass's. A pass with pass.color_targets = n > 1 (D3D9 MRT)
// draws oC1..oC(n−1) into n − 1 more targets of the same size and format, named
// single_pass_target(1..n−1). A pass with a depth state (ZENABLE / ZWRITEENABLE / ZFUNC)
// draws with a depth texture named kSinglePassDepth of the target's size, starting as `depth`
// says (default: cleared to 1.0). Refused (rule "graph"): a stencil state, a SPIR-V pixel
// stage (`tierlift run` asks for neither), more than four colour targets, and whatever
// check_graph refuses (pre-transformed vertices, a viewport other than the whole target, the
// scalar executor: a CPU device's own choice, CpuPassDevice).
std::string single_pass_target(uint32_t index); // 0: kSinglePassTarget; i: "target<i>"
ir::Result<EffectGraph> single_pass_graph(pass::Pass pass, uint32_t width, uint32_t height,
                                          img::Format format, const SinglePassDepth& depth = {});

// One device's draw of a graph of one pass: the target, and what the draw took (setup_ms:
// textures, uploads, pipelines; draw_ms: the pass to the end of its work on the device).
struct SinglePassDraw {
  std::string device; // "cpu", "vulkan"
  img::Image image;
  pass::DrawReport report;
  std::vector<img::Image> more_images; // oC1..oC(n−1) of a pass with n colour targets
  std::optional<img::Image> depth;     // the depth buffer after the draw (depth in red)
};

struct SinglePassRun {
  std::vector<SinglePassDraw> draws; // one per way that ran, cpu before vulkan
  std::string vulkan_device;         // its name when vulkan ran
  SelectedWays selected;
  // With two ways: how far apart their images are, judged at docs/design.md's targets for
  // the target's format.
  std::optional<img::Comparison> agreement;
  std::optional<img::Verdict> verdict;
  // The same for oC1..oC(n−1) of a pass with n colour targets, one entry per target.
  std::vector<img::Comparison> more_agreement;
  std::vector<img::Verdict> more_verdicts;
  // The depth buffers compared, for a pass with one: they must agree bit for bit (NUMERICS.md
  // D1-D4), so the verdict passes only when every pixel is identical.
  std::optional<img::Comparison> depth_agreement;
  std::optional<img::Verdict> depth_verdict;
};

// `graph` (single_pass_graph's) on each way `backends` asks for, then compared. The memory the
// run needs is planned first (plan_memory) and a run that cannot fit is refused before
// anything is allocated. Failures, each after the warnings so far:
//   "memory": the plan exceeds the memory available, or the host cannot hold the target;
//   "device": a Vulkan device asked for cannot be had;
//   "agreement": the two images cannot be compared;
//   a device's own failure as run_graph gives it (rule kRunRule, its cause as notes), the
//   error's subject naming the device ("cpu", "vulkan").
// Warnings, in the order they arose: "backend" (Vulkan left out under "all"), then each
// device's own (a draw that reached no pixel).
ir::Result<SinglePassRun> run_single_pass(const EffectGraph& graph, const BackendChoice& backends,
                                          const vulkan::DeviceOptions& vulkan, unsigned threads);

} // namespace tierlift::effects
