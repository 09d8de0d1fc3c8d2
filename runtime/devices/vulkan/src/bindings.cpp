// Descriptor set 0 of a pass: the uniform blocks filled with pack_uniforms (uniforms.h), the
// sampled images with their samplers, and the pipeline layout over them.
#include "bindings.h"

#include <cstring>
#include <tuple>

#include <fmt/format.h>

#include "pipeline.h"
#include "tierlift/vulkan/uniforms.h"

namespace tierlift::vulkan {

namespace {

// What descriptor set 0 holds: the uniform buffers, the sampled textures, the trace buffer.
struct Resources {
  struct Ubo {
    Buffer buf;
    uint32_t binding;
  };
  struct Texture {
    VkImageView view = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    uint32_t binding = 0;
  };
  std::vector<VkDescriptorSetLayoutBinding> layout;
  std::vector<Ubo> ubos;
  std::vector<Texture> textures;
};

// The uniform blocks, filled with pack_uniforms (uniforms.h).
ir::Status add_uniform_blocks(Device::Impl& d, Cleanup& cleanup, const codegen::CompiledPair& pair,
                              const pass::Pass& pass, Resources& res) {
  for (auto [m, bank, stage] :
       {std::tuple{&pair.vs, &pass.vs_constants, VK_SHADER_STAGE_VERTEX_BIT},
        std::tuple{&pair.ps, &pass.ps_constants, VK_SHADER_STAGE_FRAGMENT_BIT}}) {
    if (m->uniforms.size_bytes == 0) continue;
    std::vector<uint32_t> words = pack_uniforms(*m, *bank, pass);
    Resources::Ubo u{{}, m->uniforms.binding};
    ir::Status err =
        create_buffer(d, cleanup, words.size() * 4, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, u.buf);
    if (!err) return std::move(err).failure();
    std::memcpy(u.buf.mapped, words.data(), words.size() * 4);
    res.layout.push_back(
        {u.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VkShaderStageFlags(stage), nullptr});
    res.ubos.push_back(u);
  }
  return ir::ok_status();
}

// The combined image samplers: each sampled stage's image with a sampler of its state, the
// pixel program's for the fragment stage and the vertex program's (vs_3_0 texldl, bindings
// 19 + s#) for the vertex stage.
ir::Status add_textures(Device::Impl& d, Cleanup& cleanup, const codegen::CompiledPair& pair,
                        const pass::Pass& pass, const SampledImages& images, Resources& res) {
  VkFormatProperties tex_props;
  vkGetPhysicalDeviceFormatProperties(d.physical, VK_FORMAT_R32G32B32A32_SFLOAT, &tex_props);
  for (const bool vertex : {false, true}) {
    for (const auto& si : (vertex ? pair.vs : pair.ps).samplers) {
      const uint32_t number = vertex ? pass::kVertexSampler0 + si.stage : si.stage;
      const uint32_t slot = pass::sampler_slot(number);
      const pass::TextureBinding* tb = pass::sampler_binding(pass, number);
      const char* which = vertex ? "vertex " : "";
      if (!tb || !images[slot])
        return draw_failure(fmt::format("{}s{}: no texture to sample", which, si.stage));
      if (tb->sampler.filter == pass::Filter::Linear &&
          !(tex_props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
        return draw_failure("the Vulkan device cannot filter RGBA32F textures linearly");
      const pass::TextureShape shape = images[slot]->shape;
      if (shape == pass::TextureShape::Cube && tb->sampler.filter == pass::Filter::Linear &&
          !d.cube_faces_alone)
        return draw_failure(fmt::format(
            "{}s{}: a LINEAR cube read is refused: {} filters cube maps across face edges here "
            "(VK_EXT_non_seamless_cube_map not offered or not enabled), while Direct3D 9 and "
            "the CPU device filter each face on its own",
            which, si.stage, d.props.deviceName));
      Resources::Texture t;
      t.binding = si.binding;
      t.view = images[slot]->view;
      if (ir::Status err =
              create_sampler(d, cleanup, tb->sampler, images[slot]->levels, shape, t.sampler);
          !err)
        return std::move(err).failure();
      res.layout.push_back(
          {t.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
           VkShaderStageFlags(vertex ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT),
           nullptr});
      res.textures.push_back(t);
    }
  }
  return ir::ok_status();
}

// A traced pixel module's record (codegen::TracePixel): a storage buffer starting at zero.
ir::Status add_trace_buffer(Device::Impl& d, Cleanup& cleanup, const codegen::CompiledPair& pair,
                            Resources& res, Bindings& out) {
  const std::optional<codegen::TraceInfo>& trace = pair.ps.trace;
  if (!trace) return ir::ok_status();
  const VkDeviceSize bytes = VkDeviceSize{trace->entries} * codegen::kTraceEntryBytes;
  ir::Status err = create_buffer(d, cleanup, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, out.trace);
  if (!err) return std::move(err).failure();
  std::memset(out.trace.mapped, 0, out.trace.size);
  res.layout.push_back({trace->binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  return ir::ok_status();
}

// The descriptor set layout, the pipeline layout over it, a pool and the set.
ir::Status create_set(Device::Impl& d, Cleanup& cleanup, const Resources& res, Bindings& out) {
  VkDescriptorSetLayout dsl = VK_NULL_HANDLE;
  if (ir::Status err = create_pipeline_layout(d, cleanup, res.layout, out.layout, &dsl); !err)
    return err;
  VkDevice dev = d.device;
  VkResult r = VK_SUCCESS;
  VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2},
                                   {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, pass::kSamplerSlots},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
  VkDescriptorPoolCreateInfo dpi{};
  dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dpi.maxSets = 1;
  dpi.poolSizeCount = out.trace.buffer ? 3 : 2; // untraced: the pool it always was
  dpi.pPoolSizes = sizes;
  VkDescriptorPool dpool = VK_NULL_HANDLE;
  if ((r = vkCreateDescriptorPool(dev, &dpi, nullptr, &dpool)) != VK_SUCCESS)
    return draw_failure(vk_error("vkCreateDescriptorPool", r));
  cleanup.destroy_later(dev, dpool, vkDestroyDescriptorPool);
  VkDescriptorSetAllocateInfo dsa{};
  dsa.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  dsa.descriptorPool = dpool;
  dsa.descriptorSetCount = 1;
  dsa.pSetLayouts = &dsl;
  if ((r = vkAllocateDescriptorSets(dev, &dsa, &out.set)) != VK_SUCCESS)
    return draw_failure(vk_error("vkAllocateDescriptorSets", r));
  return ir::ok_status();
}

// Points the set's bindings at the buffers and images.
void write_set(Device::Impl& d, const codegen::CompiledPair& pair, const Resources& res,
               const Bindings& out) {
  std::vector<VkDescriptorBufferInfo> buffer_infos(res.ubos.size() + 1);
  std::vector<VkDescriptorImageInfo> image_infos(res.textures.size());
  std::vector<VkWriteDescriptorSet> writes;
  auto write = [&](uint32_t binding, VkDescriptorType type) -> VkWriteDescriptorSet& {
    VkWriteDescriptorSet& w = writes.emplace_back();
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.dstSet = out.set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    return w;
  };
  for (size_t k = 0; k < res.ubos.size(); ++k) {
    buffer_infos[k] = {res.ubos[k].buf.buffer, 0, VK_WHOLE_SIZE};
    write(res.ubos[k].binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).pBufferInfo = &buffer_infos[k];
  }
  if (out.trace.buffer) {
    buffer_infos.back() = {out.trace.buffer, 0, VK_WHOLE_SIZE};
    write(pair.ps.trace->binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo =
        &buffer_infos.back();
  }
  for (size_t k = 0; k < res.textures.size(); ++k) {
    image_infos[k] = {res.textures[k].sampler, res.textures[k].view,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    write(res.textures[k].binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).pImageInfo =
        &image_infos[k];
  }
  vkUpdateDescriptorSets(d.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

} // namespace

ir::Status create_pipeline_layout(Device::Impl& d, Cleanup& cleanup,
                                  const std::vector<VkDescriptorSetLayoutBinding>& bindings,
                                  VkPipelineLayout& out, VkDescriptorSetLayout* set_layout) {
  VkDescriptorSetLayoutCreateInfo dli{};
  dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  dli.bindingCount = static_cast<uint32_t>(bindings.size());
  dli.pBindings = bindings.data();
  VkDescriptorSetLayout dsl = VK_NULL_HANDLE;
  VkResult r = vkCreateDescriptorSetLayout(d.device, &dli, nullptr, &dsl);
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateDescriptorSetLayout", r));
  cleanup.destroy_later(d.device, dsl, vkDestroyDescriptorSetLayout);
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &dsl;
  if ((r = vkCreatePipelineLayout(d.device, &pli, nullptr, &out)) != VK_SUCCESS)
    return draw_failure(vk_error("vkCreatePipelineLayout", r));
  cleanup.destroy_later(d.device, out, vkDestroyPipelineLayout);
  if (set_layout) *set_layout = dsl;
  return ir::ok_status();
}

ir::Status create_bindings(Device::Impl& d, Cleanup& cleanup, const codegen::CompiledPair& pair,
                           const pass::Pass& pass, const SampledImages& images, Bindings& out) {
  Resources res; // descriptor bindings: uniform blocks, then combined image samplers
  if (ir::Status s = add_uniform_blocks(d, cleanup, pair, pass, res); !s) return s;
  if (ir::Status s = add_textures(d, cleanup, pair, pass, images, res); !s) return s;
  if (ir::Status s = add_trace_buffer(d, cleanup, pair, res, out); !s) return s;
  if (ir::Status s = create_set(d, cleanup, res, out); !s) return s;
  write_set(d, pair, res, out);
  out.layout_bindings = std::move(res.layout);
  return ir::ok_status();
}

} // namespace tierlift::vulkan
