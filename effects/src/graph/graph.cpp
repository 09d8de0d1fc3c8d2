#include "tierlift/effects/graph/graph.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "tierlift/pass/depth.h"

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
    d.draw.vs_constants.f =
        vs_constants_per_frame[std::min<size_t>(frame, vs_constants_per_frame.size() - 1)];
  if (!ps_constants_per_frame.empty())
    d.draw.ps_constants.f =
        ps_constants_per_frame[std::min<size_t>(frame, ps_constants_per_frame.size() - 1)];
  return d;
}

namespace {

std::string check_textures(const EffectGraph& g) {
  std::set<std::string_view> names;
  for (const TextureDesc& t : g.textures) {
    if (t.name.empty()) return "a texture has no name";
    if (!names.insert(t.name).second) return fmt::format("texture '{}' is declared twice", t.name);
    if (!img::valid_size(t.width, t.height))
      return fmt::format("texture '{}': size {}x{} outside 1..{}", t.name, t.width, t.height,
                         img::kMaxDimension);
  }
  return {};
}

// The depth buffer and its state: a depth state needs a depth texture of the target's size and
// the reverse; not with a stencil buffer in the same pass (no device draws both yet).
std::string check_depth(const EffectGraph& g, const PassDesc& p, const TextureDesc& target) {
  const pass::DepthStencilState& ds = p.draw.depth_stencil;
  if (p.depth.empty())
    return pass::uses_depth(ds)
               ? fmt::format("pass '{}': a depth state without a depth texture", p.name)
               : std::string();
  const TextureDesc* d = g.find_texture(p.depth);
  if (!d || !d->depth)
    return fmt::format("pass '{}': '{}' is not a depth texture", p.name, p.depth);
  if (!pass::uses_depth(ds))
    return fmt::format("pass '{}': a depth texture without a depth state", p.name);
  if (!p.stencil.empty() || ds.stencil_test)
    return fmt::format("pass '{}': a depth and a stencil buffer in one pass (not drawn yet)",
                       p.name);
  if (d->width != target.width || d->height != target.height)
    return fmt::format("pass '{}': depth '{}' is {}x{}, the target {}x{}", p.name, p.depth,
                       d->width, d->height, target.width, target.height);
  return {};
}

// The targets beyond oC0, the stencil buffer and its state, the geometry.
std::string check_outputs(const EffectGraph& g, const PassDesc& p, const TextureDesc& target) {
  if (p.more_targets.size() > 3)
    return fmt::format("pass '{}': {} render targets (D3D9 has at most 4)", p.name,
                       p.more_targets.size() + 1);
  std::set<std::string_view> used{p.target};
  for (const std::string& name : p.more_targets) {
    const TextureDesc* t = g.find_texture(name);
    if (!t) return fmt::format("pass '{}': unknown target '{}'", p.name, name);
    if (t->input || t->attachment())
      return fmt::format("pass '{}': cannot render colour into '{}'", p.name, name);
    if (!used.insert(name).second)
      return fmt::format("pass '{}': renders into '{}' twice", p.name, name);
    if (t->width != target.width || t->height != target.height)
      return fmt::format("pass '{}': target '{}' is {}x{}, '{}' is {}x{} (one size per pass)",
                         p.name, name, t->width, t->height, p.target, target.width, target.height);
  }
  const pass::DepthStencilState& ds = p.draw.depth_stencil;
  if (std::string e = check_depth(g, p, target); !e.empty()) return e;
  if (p.stencil.empty()) {
    if (ds.stencil_test)
      return fmt::format("pass '{}': a stencil state without a stencil texture", p.name);
  } else {
    const TextureDesc* s = g.find_texture(p.stencil);
    if (!s || !s->stencil)
      return fmt::format("pass '{}': '{}' is not a stencil texture", p.name, p.stencil);
    if (s->width != target.width || s->height != target.height)
      return fmt::format("pass '{}': stencil '{}' is {}x{}, the target {}x{}", p.name, p.stencil,
                         s->width, s->height, target.width, target.height);
    // The masks default to D3D9's 0xffffffff and act through their low 8 bits; a reference
    // beyond 8 bits would be wrapped silently, so it is refused.
    if (ds.stencil_ref > 255)
      return fmt::format("pass '{}': stencil reference {} is outside the 8-bit buffer's 0..255",
                         p.name, ds.stencil_ref);
  }
  for (const auto& t : p.draw.triangles)
    for (uint32_t i : t)
      if (i >= p.draw.vertices.size())
        return fmt::format("pass '{}': triangle index {} past the {} vertices", p.name, i,
                           p.draw.vertices.size());
  if (!p.draw.triangles.empty() && p.draw.vertices.empty())
    return fmt::format("pass '{}': triangles without vertices", p.name);
  return {};
}

// Which listings a pass has: both (every effect's pass), or the forms `tierlift run` draws
// (single_pass.h) — constant pixel inputs in place of the vertex listing, D3D9's oD0
// pass-through in place of the pixel listing — each only where both devices draw it.
std::string check_listings(const PassDesc& p) {
  const pass::Pass& d = p.draw;
  if (!d.vertex_program && !d.vertices.empty())
    return fmt::format("pass '{}': vertices without a vertex listing", p.name);
  if (d.pixel_spirv && (!d.vertex_program || !d.pixel_program))
    return fmt::format("pass '{}': a GLSL pass needs a vertex listing and its ps_2_0 twin", p.name);
  if (!d.pixel_program && (!p.more_targets.empty() || !p.stencil.empty()))
    return fmt::format("pass '{}': several targets or a stencil need a pixel listing", p.name);
  return {};
}

// The draw state the graph decides itself (graph_draw: the colour targets come from the
// named targets, the executor is the CPU device's) or no graph device draws.
std::string check_draw_state(const PassDesc& p) {
  const pass::Pass& d = p.draw;
  const pass::Viewport& v = d.viewport;
  if (!d.transformed.empty())
    return fmt::format("pass '{}': pre-transformed vertices (a graph pass has none)", p.name);
  if (v.x != 0 || v.y != 0 || v.width != 0 || v.height != 0 || v.min_z != 0.0f || v.max_z != 1.0f)
    return fmt::format("pass '{}': a viewport other than the whole target", p.name);
  if (d.color_targets != 1)
    return fmt::format("pass '{}': {} colour targets counted (a graph pass names them: "
                       "more_targets)",
                       p.name, d.color_targets);
  if (d.executor != pass::Executor::Auto)
    return fmt::format("pass '{}': the scalar executor (the CPU device's own choice)", p.name);
  return {};
}

std::string check_pass(const EffectGraph& g, const PassDesc& p) {
  if (std::string e = check_listings(p); !e.empty()) return e;
  if (std::string e = check_draw_state(p); !e.empty()) return e;
  if (p.draw.pixel_spirv && p.draw.pixel_program->profile != ir::Profile::ps_2_0)
    return fmt::format("pass '{}': a GLSL pass's twin must be a ps_2_0 listing", p.name);
  if ((p.analytic == AnalyticForm::Kernel) != !p.kernel.empty())
    return fmt::format("pass '{}': the analytic form Kernel and a kernel go together", p.name);
  const TextureDesc* target = g.find_texture(p.target);
  if (!target) return fmt::format("pass '{}': unknown target '{}'", p.name, p.target);
  if (target->input)
    return fmt::format("pass '{}': renders into the input texture '{}'", p.name, p.target);
  if (target->attachment())
    return fmt::format("pass '{}': renders colour into the {} texture '{}'", p.name,
                       target->stencil ? "stencil" : "depth", p.target);
  if (std::string e = check_outputs(g, p, *target); !e.empty()) return e;
  for (const auto* table : {&p.vs_constants_per_frame, &p.ps_constants_per_frame})
    for (const std::vector<pass::Vec4>& frame : *table)
      if (frame.empty())
        return fmt::format("pass '{}': a frame of its per-frame constants is empty", p.name);
  std::set<uint32_t> stages;
  for (const TextureBind& b : p.textures) {
    if (!pass::sampler_binding(p.draw, b.stage)) // 0..15, or 257..260: the vertex stage's
      return fmt::format("pass '{}': sampler stage {} out of range", p.name, b.stage);
    if (!stages.insert(b.stage).second)
      return fmt::format("pass '{}': sampler stage {} bound twice", p.name, b.stage);
    if (!g.find_texture(b.texture))
      return fmt::format("pass '{}': unknown texture '{}'", p.name, b.texture);
    // D3D9 leaves reading the bound render target undefined; we refuse it.
    if (b.texture == p.target)
      return fmt::format("pass '{}': reads its own target '{}'", p.name, p.target);
    for (const std::string& t : p.more_targets)
      if (b.texture == t) return fmt::format("pass '{}': reads its own target '{}'", p.name, t);
    if (const TextureDesc* t = g.find_texture(b.texture); t->attachment())
      return fmt::format("pass '{}': samples the {} texture '{}'", p.name,
                         t->stencil ? "stencil" : "depth", b.texture);
  }
  return {};
}

} // namespace

PassDesc listing_pass(std::string name, std::shared_ptr<const ir::Program> vs,
                      std::shared_ptr<const ir::Program> ps, std::string_view target) {
  PassDesc d;
  d.name = std::move(name);
  d.draw.vertex_program = std::move(vs);
  d.draw.pixel_program = std::move(ps);
  d.target = std::string(target);
  return d;
}

void bind_reads(PassDesc& d, uint32_t stage, std::string_view texture, const pass::SamplerState& s,
                unsigned reads, bool one_stage_per_read) {
  const unsigned stages = one_stage_per_read ? reads : 1;
  for (unsigned k = 0; k < stages; ++k) {
    d.textures.push_back({stage + k, std::string(texture)});
    if (stage + k < pass::kMaxSamplers) d.draw.textures[stage + k].sampler = s;
  }
}

ir::Status check_graph(const EffectGraph& graph) {
  auto fail = [](std::string message) { return ir::fail("graph", "graph", std::move(message)); };
  if (std::string e = check_textures(graph); !e.empty()) return fail(std::move(e));
  std::set<std::string_view> names;
  for (const PassDesc& p : graph.passes) {
    if (!names.insert(p.name).second) return fail(fmt::format("pass '{}' appears twice", p.name));
    if (std::string e = check_pass(graph, p); !e.empty()) return fail(std::move(e));
  }
  return ir::ok_status();
}

} // namespace tierlift::effects
