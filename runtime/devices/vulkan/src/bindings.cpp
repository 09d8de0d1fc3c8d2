// Descriptor set 0 of a pass: the uniform blocks filled with pack_uniforms (uniforms.h), the
// sampled images with their samplers, and the pipeline layout over them.
#include "bindings.h"

#include <cstring>

#include <fmt/format.h>

#include "pipeline.h"
#include "tierlift/vulkan/uniforms.h"

namespace tierlift::vulkan {

std::string create_bindings(Device::Impl& d, Cleanup& cleanup, const codegen::CompiledPair& pair,
                            const pass::Pass& pass, const SampledImages& images, Bindings& out) {
  std::string err;
  // Descriptor bindings: uniform blocks, then combined image samplers.
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  struct Ubo {
    Buffer buf;
    uint32_t binding;
  };
  std::vector<Ubo> ubos;
  auto add_ubo = [&](const codegen::ShaderModule& m, const pass::ConstantBank& bank,
                     VkShaderStageFlags stage) {
    if (m.uniforms.size_bytes == 0 || !err.empty()) return;
    std::vector<uint32_t> words = pack_uniforms(m, bank, pass);
    Ubo u{{}, m.uniforms.binding};
    err = create_buffer(d, cleanup, words.size() * 4, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, u.buf);
    if (!err.empty()) return;
    std::memcpy(u.buf.mapped, words.data(), words.size() * 4);
    bindings.push_back({u.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stage, nullptr});
    ubos.push_back(u);
  };
  add_ubo(pair.vs, pass.vs_constants, VK_SHADER_STAGE_VERTEX_BIT);
  add_ubo(pair.ps, pass.ps_constants, VK_SHADER_STAGE_FRAGMENT_BIT);
  if (!err.empty()) return err;

  VkFormatProperties tex_props;
  vkGetPhysicalDeviceFormatProperties(d.physical, VK_FORMAT_R32G32B32A32_SFLOAT, &tex_props);
  struct Texture {
    VkImageView view = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    uint32_t binding = 0;
  };
  std::vector<Texture> textures;
  for (const auto& si : pair.ps.samplers) {
    if (si.type != ir::SamplerType::Tex2D)
      return fmt::format("s{}: only 2D textures are supported on the Vulkan device", si.stage);
    const uint32_t stage = si.stage % pass::kMaxSamplers;
    const pass::TextureBinding& tb = pass.textures[stage];
    if (!images[stage]) return fmt::format("s{}: no texture to sample", si.stage);
    if (tb.sampler.filter == pass::Filter::Linear &&
        !(tex_props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
      return "the Vulkan device cannot filter RGBA32F textures linearly";
    Texture t;
    t.binding = si.binding;
    t.view = images[stage]->view;
    if (err = create_sampler(d, cleanup, tb.sampler, t.sampler); !err.empty()) return err;
    bindings.push_back({t.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
    textures.push_back(t);
  }

  // A traced pixel module's record (codegen::TracePixel): a storage buffer starting at zero.
  if (const std::optional<codegen::TraceInfo>& trace = pair.ps.trace) {
    const VkDeviceSize bytes = VkDeviceSize{trace->entries} * codegen::kTraceEntryBytes;
    err = create_buffer(d, cleanup, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, out.trace);
    if (!err.empty()) return err;
    std::memset(out.trace.mapped, 0, out.trace.size);
    bindings.push_back({trace->binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  }

  // Descriptor set layout, pool, set; pipeline layout.
  VkDescriptorSetLayoutCreateInfo dli{};
  dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  dli.bindingCount = static_cast<uint32_t>(bindings.size());
  dli.pBindings = bindings.data();
  VkDescriptorSetLayout dsl = VK_NULL_HANDLE;
  VkResult r = vkCreateDescriptorSetLayout(d.device, &dli, nullptr, &dsl);
  if (r != VK_SUCCESS) return vk_error("vkCreateDescriptorSetLayout", r);
  VkDevice dev = d.device;
  cleanup.destroy_later(dev, dsl, vkDestroyDescriptorSetLayout);
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &dsl;
  VkPipelineLayout& layout = out.layout;
  if ((r = vkCreatePipelineLayout(dev, &pli, nullptr, &layout)) != VK_SUCCESS)
    return vk_error("vkCreatePipelineLayout", r);
  cleanup.destroy_later(dev, layout, vkDestroyPipelineLayout);
  VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2},
                                   {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
  VkDescriptorPoolCreateInfo dpi{};
  dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dpi.maxSets = 1;
  dpi.poolSizeCount = out.trace.buffer ? 3 : 2; // untraced: the pool it always was
  dpi.pPoolSizes = sizes;
  VkDescriptorPool dpool = VK_NULL_HANDLE;
  if ((r = vkCreateDescriptorPool(dev, &dpi, nullptr, &dpool)) != VK_SUCCESS)
    return vk_error("vkCreateDescriptorPool", r);
  cleanup.destroy_later(dev, dpool, vkDestroyDescriptorPool);
  VkDescriptorSetAllocateInfo dsa{};
  dsa.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  dsa.descriptorPool = dpool;
  dsa.descriptorSetCount = 1;
  dsa.pSetLayouts = &dsl;
  VkDescriptorSet& set = out.set;
  if ((r = vkAllocateDescriptorSets(dev, &dsa, &set)) != VK_SUCCESS)
    return vk_error("vkAllocateDescriptorSets", r);
  std::vector<VkDescriptorBufferInfo> buffer_infos(ubos.size() + 1);
  std::vector<VkDescriptorImageInfo> image_infos(textures.size());
  std::vector<VkWriteDescriptorSet> writes;
  auto write = [&](uint32_t binding, VkDescriptorType type) -> VkWriteDescriptorSet& {
    VkWriteDescriptorSet& w = writes.emplace_back();
    w.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    return w;
  };
  for (size_t k = 0; k < ubos.size(); ++k) {
    buffer_infos[k] = {ubos[k].buf.buffer, 0, VK_WHOLE_SIZE};
    write(ubos[k].binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER).pBufferInfo = &buffer_infos[k];
  }
  if (out.trace.buffer) {
    buffer_infos.back() = {out.trace.buffer, 0, VK_WHOLE_SIZE};
    write(pair.ps.trace->binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER).pBufferInfo =
        &buffer_infos.back();
  }
  for (size_t k = 0; k < textures.size(); ++k) {
    image_infos[k] = {textures[k].sampler, textures[k].view,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    write(textures[k].binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER).pImageInfo =
        &image_infos[k];
  }
  vkUpdateDescriptorSets(dev, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  return {};
}

} // namespace tierlift::vulkan
