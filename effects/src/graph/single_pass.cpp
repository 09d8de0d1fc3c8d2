// pass::Pass → a graph of one pass, for what `tierlift run` draws: the draw moves into the
// pass as it is; only its bound images leave it, to become the graph's input textures, which
// the device then owns for the run and binds back by name (graph_draw binds none).
#include "tierlift/effects/graph/single_pass.h"

#include <map>
#include <utility>

#include <fmt/format.h>

#include "tierlift/pass/depth.h"

#include "tierlift/pass/srgb.h"

namespace tierlift::effects {
namespace {

// What `tierlift run` never asks and a graph pass would take as something else; refused
// rather than dropped, so a device never draws a different pass than the one asked for.
// (check_graph refuses the rest a graph device does not draw.)
std::string unsupported(const pass::Pass& pass) {
  if (pass.color_targets < 1 || pass.color_targets > 4)
    return fmt::format("{} colour targets", pass.color_targets);
  if (pass.depth_stencil.stencil_test) return "a stencil state";
  if (pass.pixel_spirv) return "a SPIR-V pixel stage";
  return {};
}

} // namespace

std::string single_pass_target(uint32_t index) {
  return index == 0 ? std::string(kSinglePassTarget)
                    : fmt::format("{}{}", kSinglePassTarget, index);
}

ir::Result<EffectGraph> single_pass_graph(pass::Pass pass, uint32_t width, uint32_t height,
                                          img::Format format, const SinglePassDepth& depth) {
  if (std::string what = unsupported(pass); !what.empty())
    return ir::fail("graph", "graph",
                    fmt::format("a graph pass cannot describe {} (tierlift run draws none)", what));
  EffectGraph graph;
  graph.conventions = pass.conventions;
  PassDesc desc;
  desc.name = std::string(kSinglePass);
  desc.target = std::string(kSinglePassTarget);
  // One input texture per image, however many stages bind it (Listing 4 binds one four
  // times): one upload on Vulkan, one copy on the CPU. The stage keeps its state in the draw;
  // its image leaves it for the graph, and the device binds it back by name.
  // An sRGB stage (SRGBTEXTURE) gets its image decoded once here, before filtering, as every
  // device would decode it (pass/srgb.h): one more input texture, read as a plain one.
  // The vertex stage's samplers (vs_3_0 texldl) the same way, bound as stages 257 + N
  // (TextureBind::stage); their textures are named vs_sN.
  std::map<std::pair<const img::Image*, bool>, std::string> names;
  for (uint32_t s = 0; s < pass::kSamplerSlots; ++s) {
    const bool vertex = s >= pass::kMaxSamplers;
    const uint32_t stage = vertex ? pass::kVertexSampler0 + (s - pass::kMaxSamplers) : s;
    pass::TextureBinding& b = *pass::sampler_binding(pass, stage);
    if (!b.image) continue;
    auto [it, added] = names.emplace(std::pair{b.image.get(), b.sampler.srgb},
                                     vertex ? fmt::format("vs_s{}", s - pass::kMaxSamplers)
                                            : fmt::format("s{}", s));
    if (b.sampler.srgb) b = pass::srgb_resolved(b);
    std::shared_ptr<const img::Image> image = std::move(b.image);
    if (added) {
      TextureDesc t;
      t.name = it->second;
      t.width = image->width;
      t.height = image->height;
      t.format = image->format; // stored as it is: run_graph quantizes nothing
      t.input = true;
      t.contents = std::move(image);
      graph.textures.push_back(std::move(t));
    }
    desc.textures.push_back({stage, it->second});
  }
  // oC0 into kSinglePassTarget, oC1..oC3 (MRT) into targets of the same size and format; the
  // graph names them (more_targets), and graph_draw counts them back into the draw.
  for (uint32_t i = 0; i < pass.color_targets; ++i) {
    TextureDesc target;
    target.name = single_pass_target(i);
    target.width = width;
    target.height = height;
    target.format = format;
    graph.textures.push_back(std::move(target));
    if (i > 0) desc.more_targets.push_back(single_pass_target(i));
  }
  if (pass::uses_depth(pass.depth_stencil)) {
    if (depth.initial && (depth.initial->width != width || depth.initial->height != height))
      return ir::fail("graph", "graph",
                      fmt::format("the depth image is {}x{}, the target {}x{}",
                                  depth.initial->width, depth.initial->height, width, height));
    TextureDesc z;
    z.name = std::string(kSinglePassDepth);
    z.width = width;
    z.height = height;
    z.depth = true;
    z.depth_clear = depth.clear;
    z.contents = depth.initial;
    graph.textures.push_back(std::move(z));
    desc.depth = std::string(kSinglePassDepth);
  }
  desc.draw = std::move(pass);
  desc.draw.color_targets = 1;
  graph.passes.push_back(std::move(desc));
  if (ir::Status checked = check_graph(graph); !checked) return std::move(checked).failure();
  return graph;
}

} // namespace tierlift::effects
