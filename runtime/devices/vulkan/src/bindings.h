// Internal: descriptor set 0 of one pass (see docs/spirv-mapping.md "Resources"): uniform
// blocks, textures and samplers, the set layout and the pipeline layout.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"
#include "vk_internal.h"

namespace tierlift::vulkan {

// The image each sampler reads (R32G32B32A32_SFLOAT, in SHADER_READ_ONLY_OPTIMAL when the
// draw runs), by pass::sampler_slot (the vertex stage's sN at kMaxSamplers + N); only the
// samplers the programs read need one.
using SampledImages = std::array<const Image2D*, pass::kSamplerSlots>;

struct Bindings {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  Buffer trace; // pair.ps.trace: the storage buffer it records into, zeroed
  // What the set layout was made from (a pipeline made with another layout from the same
  // bindings is compatible with this one: program_reuse.h).
  std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
};

// A descriptor set layout of `bindings` and the pipeline layout over it (set 0), both
// registered with `cleanup`; `set_layout` (if given) receives the former. Empty on success.
ir::Status create_pipeline_layout(Device::Impl& d, Cleanup& cleanup,
                                  const std::vector<VkDescriptorSetLayoutBinding>& bindings,
                                  VkPipelineLayout& out,
                                  VkDescriptorSetLayout* set_layout = nullptr);

// Every object is registered with `cleanup`; a failure is one error of rule kDrawRule.
// Samplers come from pass.textures[stage].sampler, images from `images`.
ir::Status create_bindings(Device::Impl& d, Cleanup& cleanup, const codegen::CompiledPair& pair,
                           const pass::Pass& pass, const SampledImages& images, Bindings& out);

} // namespace tierlift::vulkan
