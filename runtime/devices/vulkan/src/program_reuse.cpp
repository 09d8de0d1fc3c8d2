// The compiled programs and pipelines a TextureSet reuses across draws (program_reuse.h).
#include "program_reuse.h"

#include "bindings.h"
#include "key_bytes.h"
#include "pipeline.h"

namespace tierlift::vulkan {

std::optional<std::string> compile_key(const ir::Program* vs, const ir::Program* ps,
                                       const codegen::CodegenOptions& o) {
  // Known constants would make the modules those of one set of constants only.
  if (o.trace || o.known_vs_constants || o.known_ps_constants) return std::nullopt;
  KeyBytes k;
  k.put(vs);
  k.put(ps);
  k.put(o.conventions.pixel_center);
  k.put(o.conventions.subtexel_bits);
  k.put(o.conventions.ps1x_max_value);
  k.put(o.conventions.ps1x_fixed_bits);
  k.put(o.conventions.rounding);
  k.put(o.flip_y);
  k.put(o.pixel_offset_x);
  k.put(o.pixel_offset_y);
  k.put(o.kill);
  k.put(o.stage_texture_type);
  k.put(o.stage_projected);
  k.put(o.stage_fetch_unorm8);
  k.put(o.stage_point_clamped);
  k.put(o.vertex_point_clamped);
  k.put(o.unorm8_decode);
  k.put(o.point_sampling_floors);
  k.put(o.optimize);
  k.put(o.defs_in_block);
  k.put(o.srgb_write);
  k.put(o.entry_point.size());
  std::string key = k.take();
  return key + o.entry_point;
}

const codegen::CompiledPair* ProgramReuse::find_compiled(const std::string& key) const {
  auto it = compiled_.find(key);
  return it == compiled_.end() ? nullptr : &it->second.pair;
}

void ProgramReuse::keep_compiled(const std::string& key, std::shared_ptr<const ir::Program> vs,
                                 std::shared_ptr<const ir::Program> ps,
                                 const codegen::CompiledPair& pair) {
  compiled_[key] = Compiled{std::move(vs), std::move(ps), pair};
}

ir::Status ProgramReuse::pipeline(Device::Impl& d, const PipelineDesc& desc,
                                  const std::vector<VkFormat>& color_formats,
                                  VkFormat stencil_format,
                                  const std::vector<VkDescriptorSetLayoutBinding>& bindings,
                                  VkPipeline& out) {
  KeyBytes k;
  k.put(desc.vs->words);
  k.put(desc.ps_words);
  k.put(desc.blend);
  k.put(desc.front_face);
  k.put(desc.color_targets);
  k.put(desc.stencil_attachment);
  k.put(desc.depth_stencil);
  k.put(desc.vertex_stride);
  k.put(color_formats.size());
  for (VkFormat f : color_formats) k.put(f);
  k.put(stencil_format);
  k.put(bindings.size());
  for (const VkDescriptorSetLayoutBinding& b : bindings) {
    k.put(b.binding);
    k.put(b.descriptorType);
    k.put(b.descriptorCount);
    k.put(b.stageFlags);
  }
  const std::string key = k.take();
  if (auto it = pipelines_.find(key); it != pipelines_.end()) {
    out = it->second->pipeline;
    return ir::ok_status();
  }
  auto made = std::make_unique<Pipeline>();
  PipelineDesc own = desc;
  ir::Status err =
      create_render_pass(d, made->objects, color_formats, stencil_format, own.render_pass);
  if (err) err = create_pipeline_layout(d, made->objects, bindings, own.layout);
  if (err) err = create_pipeline(d, made->objects, own, made->pipeline);
  if (!err) return err;
  out = made->pipeline;
  pipelines_.emplace(key, std::move(made));
  return ir::ok_status();
}

} // namespace tierlift::vulkan
