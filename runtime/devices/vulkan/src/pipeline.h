// Internal: the fixed-function objects of one pass — render pass, framebuffer, sampler,
// graphics pipeline — created from the pass description and the compiled modules.
#pragma once

#include <string>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/pass/pass.h"
#include "vk_internal.h"

namespace tierlift::vulkan {

// Render pass with one colour attachment kept in COLOR_ATTACHMENT_OPTIMAL, loaded (blending
// reads the stored destination) and stored.
std::string create_render_pass(Device::Impl& d, Cleanup& cleanup, VkFormat format,
                               VkRenderPass& out);
std::string create_framebuffer(Device::Impl& d, Cleanup& cleanup, VkRenderPass rp,
                               const Image2D& target, VkFramebuffer& out);
// D3D9 sampler state → VkSampler (one level). Errors for MirrorOnce and border colours other
// than transparent black, opaque black and opaque white.
std::string create_sampler(Device::Impl& d, Cleanup& cleanup, const pass::SamplerState& s,
                           VkSampler& out);

struct PipelineDesc {
  const codegen::ShaderModule* vs = nullptr;
  const codegen::ShaderModule* ps = nullptr;
  std::vector<uint32_t> ps_words; // possibly rewritten (flat varyings)
  pass::BlendMode blend = pass::BlendMode::Replace;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  uint32_t vertex_stride = 0; // bytes per vertex; input vN at offset 16·N
};
std::string create_pipeline(Device::Impl& d, Cleanup& cleanup, const PipelineDesc& desc,
                            VkPipeline& out);

} // namespace tierlift::vulkan
