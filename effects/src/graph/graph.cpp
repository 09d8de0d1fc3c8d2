#include "tierlift/effects/graph.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>

namespace tierlift::effects {

const TextureDesc* EffectGraph::find_texture(std::string_view name) const {
  for (const TextureDesc& t : textures)
    if (t.name == name) return &t;
  return nullptr;
}

PassDesc PassDesc::at_frame(unsigned frame) const {
  PassDesc d = *this;
  d.vs_constants_per_frame.clear();
  d.ps_constants_per_frame.clear();
  if (!vs_constants_per_frame.empty())
    d.vs_constants =
        vs_constants_per_frame[std::min<size_t>(frame, vs_constants_per_frame.size() - 1)];
  if (!ps_constants_per_frame.empty())
    d.ps_constants =
        ps_constants_per_frame[std::min<size_t>(frame, ps_constants_per_frame.size() - 1)];
  return d;
}

namespace {

std::string check_textures(const EffectGraph& g) {
  std::set<std::string_view> names;
  for (const TextureDesc& t : g.textures) {
    if (t.name.empty()) return "a texture has no name";
    if (!names.insert(t.name).second) return fmt::format("texture '{}' is declared twice", t.name);
    if (t.width == 0 || t.height == 0 || t.width > img::kMaxDimension ||
        t.height > img::kMaxDimension)
      return fmt::format("texture '{}': size {}x{} outside 1..{}", t.name, t.width, t.height,
                         img::kMaxDimension);
  }
  return {};
}

std::string check_pass(const EffectGraph& g, const PassDesc& p) {
  if (!p.vs || !p.ps) return fmt::format("pass '{}': needs a vertex and a pixel listing", p.name);
  const TextureDesc* target = g.find_texture(p.target);
  if (!target) return fmt::format("pass '{}': unknown target '{}'", p.name, p.target);
  if (target->input)
    return fmt::format("pass '{}': renders into the input texture '{}'", p.name, p.target);
  for (const auto* table : {&p.vs_constants_per_frame, &p.ps_constants_per_frame})
    for (const std::vector<pass::Vec4>& frame : *table)
      if (frame.empty())
        return fmt::format("pass '{}': a frame of its per-frame constants is empty", p.name);
  std::set<uint32_t> stages;
  for (const TextureBind& b : p.textures) {
    if (b.stage >= pass::kMaxSamplers)
      return fmt::format("pass '{}': sampler stage {} out of range", p.name, b.stage);
    if (!stages.insert(b.stage).second)
      return fmt::format("pass '{}': sampler stage {} bound twice", p.name, b.stage);
    if (!g.find_texture(b.texture))
      return fmt::format("pass '{}': unknown texture '{}'", p.name, b.texture);
    // D3D9 leaves reading the bound render target undefined; we refuse it.
    if (b.texture == p.target)
      return fmt::format("pass '{}': reads its own target '{}'", p.name, p.target);
  }
  return {};
}

} // namespace

std::string check_graph(const EffectGraph& graph) {
  if (std::string e = check_textures(graph); !e.empty()) return e;
  std::set<std::string_view> names;
  for (const PassDesc& p : graph.passes) {
    if (!names.insert(p.name).second) return fmt::format("pass '{}' appears twice", p.name);
    if (std::string e = check_pass(graph, p); !e.empty()) return e;
  }
  return {};
}

} // namespace tierlift::effects
