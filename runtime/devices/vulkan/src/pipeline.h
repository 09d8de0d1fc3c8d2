// Internal: the fixed-function objects of one pass — render pass, framebuffer, sampler,
// graphics pipeline — created from the pass description and the compiled modules.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/pass/pass.h"
#include "vk_internal.h"

namespace tierlift::vulkan {

// Render pass with one colour attachment per render target (oC# at attachment #) kept in
// COLOR_ATTACHMENT_OPTIMAL, loaded (blending reads the stored destination) and stored; and,
// with a stencil format (not VK_FORMAT_UNDEFINED), a depth/stencil attachment after them in
// DEPTH_STENCIL_ATTACHMENT_OPTIMAL, its stencil loaded and stored.
ir::Status create_render_pass(Device::Impl& d, Cleanup& cleanup,
                              const std::vector<VkFormat>& colors, VkFormat stencil,
                              VkRenderPass& out);
// `attachments`: the colour targets in order, then the stencil buffer if the pass has one.
ir::Status create_framebuffer(Device::Impl& d, Cleanup& cleanup, VkRenderPass rp,
                              const std::vector<const Image2D*>& attachments, VkFramebuffer& out);
// D3D9 sampler state → VkSampler (`levels` mip levels) for an image of `shape`. Errors for
// MirrorOnce and border colours other than transparent black, opaque black and opaque white.
// A cube's sampler clamps at the face edges whatever ADDRESSU/V say, and filters each face on
// its own where the device allows (Device::Impl::cube_faces_alone; NUMERICS.md T4).
ir::Status create_sampler(Device::Impl& d, Cleanup& cleanup, const pass::SamplerState& s,
                          uint32_t levels, pass::TextureShape shape, VkSampler& out);

struct PipelineDesc {
  const codegen::ShaderModule* vs = nullptr;
  const codegen::ShaderModule* ps = nullptr;
  std::vector<uint32_t> ps_words;                          // possibly rewritten (flat varyings)
  pass::BlendMode blend = pass::BlendMode::Replace;        // every target blends alike, as in D3D9
  pass::FrontFace front_face = pass::FrontFace::Clockwise; // which winding vFace calls front
  // Colour attachments; the pixel stage writes each (prepare_draw checks), so all blend
  // attachment states are identical and the independentBlend feature is not needed.
  uint32_t color_targets = 1;
  // With a stencil attachment: D3D9's stencil state (one-sided; no depth test).
  bool stencil_attachment = false;
  pass::DepthStencilState depth_stencil;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  uint32_t vertex_stride = 0; // bytes per vertex; input vN at offset 16·N
};
ir::Status create_pipeline(Device::Impl& d, Cleanup& cleanup, const PipelineDesc& desc,
                           VkPipeline& out);

// Runs `submit` (a queue submission holding draws, waited for) and adds its time to
// draw_submission_ms (pipeline_stats.h): where llvmpipe compiles a pipeline's shaders to
// machine code, at the first draw that uses it.
ir::Status timed_draw_submission(const std::function<ir::Status()>& submit);
// Counts one vkQueueSubmit for queue_submissions (pipeline_stats.h).
void count_queue_submission();

} // namespace tierlift::vulkan
