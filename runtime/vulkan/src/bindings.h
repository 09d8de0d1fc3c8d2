// Internal: descriptor set 0 of one pass (see docs/spirv-mapping.md "Resources"): uniform
// blocks, textures and samplers, the set layout and the pipeline layout.
#pragma once

#include <string>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/cpu/draw.h"
#include "vk_internal.h"

namespace tierlift::vulkan {

// A sampled texture: the image, the staging buffer its pixels wait in until the upload
// submit, and its sampler at binding 2 + stage.
struct Texture {
  Image2D image;
  Buffer staging;
  VkSampler sampler = VK_NULL_HANDLE;
  uint32_t binding = 0;
};

struct Bindings {
  std::vector<Texture> textures; // still to be uploaded (staging → image)
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
};

// Empty string on success; every object is registered with `cleanup`.
std::string create_bindings(Device::Impl& d, Cleanup& cleanup, const codegen::CompiledPair& pair,
                            const cpu::Pass& pass, Bindings& out);

} // namespace tierlift::vulkan
