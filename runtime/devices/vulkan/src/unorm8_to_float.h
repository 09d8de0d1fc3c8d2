// Internal: the exact RGBA8 UNORM → R32G32B32A32_SFLOAT conversion behind a sampled RGBA8
// texture's float copy on a device whose in-place reads no decode makes exact
// (DeviceOptions::unorm8_in_place; elsewhere a draw fills the copy, resident.h).
//
// Why not vkCmdBlitImage (which serves RGBA16F exactly): lavapipe's blit converts UNORM8 as
// k · fl(1/255), which differs from the correctly rounded k/255 in 126 of the 256 levels by
// one ulp (measured on Mesa 22.3: level 3 reads 0.011764707, k/255 is 0.0117647061), and
// one ulp in a sampled texel flips stored RGBA8 results of later passes by a whole step.
// Device::draw samples the host's k/255.0f, and so does the CPU device. So the stored bytes are
// copied into a buffer, a small compute shader computes k/255.0f from each byte k in float
// operations that round exactly once where it matters (unorm8_to_float_spirv says why it is
// exact), and that is copied into the float image. It replaced a 256-entry table of k/255.0f
// in a storage buffer, whose four gathers per texel lavapipe runs slowly (1080p RGBA8 glow:
// about a millisecond a frame). (Storing into a storage image instead measured slower on
// lavapipe: ~29 vs ~17 ms at 1280×720.)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vk_internal.h"

namespace tierlift::vulkan {

// Per device, created on first use: shader, pipeline and layouts.
struct Unorm8Converter {
  Cleanup objects;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};

// Per texture: the buffer the stored bytes are copied into, the float buffer the shader
// writes, and the descriptor set binding them.
struct Unorm8Scratch {
  Buffer bytes, floats;
  VkDescriptorSet set = VK_NULL_HANDLE;
};

// The compute shader (SPIR-V 1.3): set 0 = {0: uint texels[], 1: vec4 out[]} (storage
// buffers); push constants (width, height); local size 8 × 8.
std::vector<uint32_t> unorm8_to_float_spirv();

// Creates d.unorm8 if it does not exist yet.
ir::Status ensure_unorm8_converter(Device::Impl& d);
// Scratch for a `width` × `height` texture; objects go to `cleanup` (the texture's).
ir::Status create_unorm8_scratch(Device::Impl& d, Cleanup& cleanup, uint32_t width, uint32_t height,
                                 Unorm8Scratch& out);
// Records: stored (already TRANSFER_SRC_OPTIMAL) → bytes → dispatch → floats → shadow
// (already TRANSFER_DST_OPTIMAL). The caller makes the shadow readable afterwards.
void record_unorm8_to_float(VkCommandBuffer cb, const Device::Impl& d, const Unorm8Scratch& s,
                            VkImage stored, VkImage shadow, uint32_t width, uint32_t height);

} // namespace tierlift::vulkan
