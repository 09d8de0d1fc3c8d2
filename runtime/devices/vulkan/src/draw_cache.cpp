// The prepared-draw cache of TextureSet (draw_cache.h).
#include "draw_cache.h"

#include "key_bytes.h"

namespace tierlift::vulkan {

std::optional<std::string> draw_key(const pass::Pass& pass, const DrawTextures& textures) {
  if (!pass.vertex_program || !textures.target) return std::nullopt;
  KeyBytes k;
  k.put(pass.vertex_program.get());
  k.put(pass.pixel_program.get());
  k.put(pass.pixel_spirv.get());
  const ir::Conventions& c = pass.conventions;
  k.put(c.pixel_center);
  k.put(c.subtexel_bits);
  k.put(c.ps1x_max_value);
  k.put(c.ps1x_fixed_bits);
  k.put(c.rounding);
  k.put(textures.target);
  for (const Resident* m : textures.more_targets) k.put(m);
  k.put(textures.stencil);
  k.put(textures.depth);
  k.put(pass.color_targets);
  k.put(pass.depth_stencil);
  for (uint32_t s = 0; s < pass::kSamplerSlots; ++s) { // both stages' samplers
    const pass::TextureBinding& b =
        s < pass::kMaxSamplers ? pass.textures[s] : pass.vertex_textures[s - pass::kMaxSamplers];
    if (!textures.stages[s] && b.image) return std::nullopt;       // host pixels: not cached
    if (b.shape != pass::TextureShape::Tex2D) return std::nullopt; // host layers: not either
    if (b.levels.size() > 1) return std::nullopt;                  // nor host mip levels
    k.put(textures.stages[s]);
    k.put(b.sampler.filter);
    k.put(b.sampler.address_u);
    k.put(b.sampler.address_v);
    k.put(b.sampler.border_color);
    k.put(b.sampler.mip.filter);
    k.put(b.sampler.mip.lod_bias);
    k.put(b.sampler.mip.max_mip_level);
    k.put(b.levels.size());
    k.put(b.sampler.srgb);
    for (float m : b.stage.bumpenv_mat) k.put(m);
    k.put(b.stage.bumpenv_lscale);
    k.put(b.stage.bumpenv_loffset);
    k.put(b.stage.projected);
  }
  k.put(pass.vs_constants);
  k.put(pass.ps_constants);
  // With a vertex program the geometry is the pass's vertices and triangles only.
  k.put(pass.vertices.size());
  for (const pass::VertexInput& v : pass.vertices)
    for (const pass::Vec4& r : v.v) k.put(r);
  k.put(pass.triangles.size());
  for (const auto& t : pass.triangles)
    for (uint32_t i : t) k.put(i);
  k.put(pass.viewport.x);
  k.put(pass.viewport.y);
  k.put(pass.viewport.width);
  k.put(pass.viewport.height);
  k.put(pass.viewport.min_z);
  k.put(pass.viewport.max_z);
  k.put(pass.blend);
  k.put(pass.front_face);
  k.put(pass.srgb_write);
  k.put(pass.scissor.has_value());
  if (pass.scissor) {
    k.put(pass.scissor->x0);
    k.put(pass.scissor->y0);
    k.put(pass.scissor->x1);
    k.put(pass.scissor->y1);
  }
  return k.take();
}

PreparedDraw* DrawCache::find(const std::string& key) {
  auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : &it->second->draw;
}

PreparedDraw& DrawCache::insert(const std::string& key, const pass::Pass& pass,
                                std::unique_ptr<CachedDraw> entry) {
  entry->vs = pass.vertex_program;
  entry->ps = pass.pixel_program;
  entry->ps_spirv = pass.pixel_spirv;
  auto& slot = entries_[key];
  slot = std::move(entry);
  return slot->draw;
}

void DrawCache::forget(const Resident* r) {
  for (auto it = entries_.begin(); it != entries_.end();) {
    const PreparedDraw& d = it->second->draw;
    bool uses = d.target == r || d.stencil == r;
    for (const Resident* m : d.more_targets) uses = uses || m == r;
    for (const Resident* s : d.sampled) uses = uses || s == r;
    it = uses ? entries_.erase(it) : std::next(it);
  }
}

} // namespace tierlift::vulkan
