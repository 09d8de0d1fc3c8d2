// pass::Pass → a graph of one pass, for what `tierlift run` draws: the banks, geometry and
// states carried over as they are; the bound images become the graph's input textures, which
// the device then owns for the run and binds back by reference (make_pass binds none).
#include "tierlift/effects/graph/single_pass.h"

#include <map>
#include <utility>

#include <fmt/format.h>

#include "tierlift/pass/srgb.h"

namespace tierlift::effects {
namespace {

bool default_viewport(const pass::Viewport& v) {
  return v.x == 0 && v.y == 0 && v.width == 0 && v.height == 0 && v.min_z == 0.0f &&
         v.max_z == 1.0f;
}

// The first thing of `pass` a PassDesc cannot carry; empty when there is none. Refused
// rather than dropped, so a device never draws a different pass than the one asked for.
std::string unsupported(const pass::Pass& pass) {
  if (!pass.transformed.empty()) return "pre-transformed vertices";
  if (!default_viewport(pass.viewport)) return "a viewport other than the whole target";
  if (pass.color_targets < 1 || pass.color_targets > 4)
    return fmt::format("{} colour targets", pass.color_targets);
  if (pass.depth_stencil.enabled()) return "a depth/stencil state";
  if (pass.pixel_spirv) return "a SPIR-V pixel stage";
  if (pass.executor != pass::Executor::Auto) return "the scalar executor";
  if (!pass.vertex_program && !pass.vertices.empty()) return "vertices without a vertex listing";
  return {};
}

} // namespace

std::string single_pass_target(uint32_t index) {
  return index == 0 ? std::string(kSinglePassTarget)
                    : fmt::format("{}{}", kSinglePassTarget, index);
}

ir::Result<EffectGraph> single_pass_graph(const pass::Pass& pass, uint32_t width, uint32_t height,
                                          img::Format format) {
  if (std::string what = unsupported(pass); !what.empty())
    return ir::fail("graph", "graph",
                    fmt::format("a graph pass cannot describe {} (tierlift run draws none)", what));
  EffectGraph graph;
  graph.conventions = pass.conventions;
  PassDesc desc;
  desc.name = std::string(kSinglePass);
  desc.target = std::string(kSinglePassTarget);
  desc.vs = pass.vertex_program;
  desc.ps = pass.pixel_program;
  desc.vs_constants = pass.vs_constants;
  desc.ps_constants = pass.ps_constants;
  if (pass.vertex_program) {
    desc.vertices = pass.vertices;
    desc.triangles = pass.triangles;
  } else {
    desc.constant_inputs = pass.constant_inputs;
  }
  desc.scissor = pass.scissor;
  desc.blend = pass.blend;
  desc.front_face = pass.front_face;
  desc.srgb_write = pass.srgb_write;
  // One input texture per image, however many stages bind it (Listing 4 binds one four
  // times): one upload on Vulkan, one copy on the CPU.
  // An sRGB stage (SRGBTEXTURE) gets its image decoded once here, before filtering, as every
  // device would decode it (pass/srgb.h): one more input texture, read as a plain one.
  std::map<std::pair<const img::Image*, bool>, std::string> names;
  for (uint32_t s = 0; s < pass::kMaxSamplers; ++s) {
    const pass::TextureBinding& b = pass::srgb_resolved(pass.textures[s]);
    if (!b.image) continue;
    auto [it, added] =
        names.emplace(std::pair{pass.textures[s].image.get(), pass.textures[s].sampler.srgb},
                      fmt::format("s{}", s));
    if (added) {
      TextureDesc t;
      t.name = it->second;
      t.width = b.image->width;
      t.height = b.image->height;
      t.format = b.image->format; // stored as it is: run_graph quantizes nothing
      t.input = true;
      t.contents = b.image;
      graph.textures.push_back(std::move(t));
    }
    desc.textures.push_back({s, it->second, b.sampler, b.stage, b.shape, b.layers});
  }
  // oC0 into kSinglePassTarget, oC1..oC3 (MRT) into targets of the same size and format.
  for (uint32_t i = 0; i < pass.color_targets; ++i) {
    TextureDesc target;
    target.name = single_pass_target(i);
    target.width = width;
    target.height = height;
    target.format = format;
    graph.textures.push_back(std::move(target));
    if (i > 0) desc.more_targets.push_back(single_pass_target(i));
  }
  graph.passes.push_back(std::move(desc));
  return graph;
}

} // namespace tierlift::effects
