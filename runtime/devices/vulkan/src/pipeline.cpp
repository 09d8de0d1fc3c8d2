// Render pass, framebuffer, sampler and graphics pipeline of one pass.
#include "pipeline.h"
#include "tierlift/vulkan/pipeline_stats.h"

#include "pipeline_cache.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>

#include <fmt/format.h>

namespace tierlift::vulkan {
namespace {
// What pipeline_creation_ms (device.h) reports: every device's pipeline creations.
std::atomic<int64_t> g_pipeline_creation_ns{0};
std::atomic<long> g_pipeline_creations{0};
std::atomic<int64_t> g_pipeline_creation_cpu_ns{0};
// What draw_submission_ms reports: the submits that carry draws.
std::atomic<int64_t> g_draw_submission_ns{0};
std::atomic<long> g_draw_submissions{0};
std::atomic<int64_t> g_draw_submission_cpu_ns{0};
std::atomic<long> g_queue_submissions{0}; // every submit, draws or not

int64_t thread_cpu_ns() {
  timespec t{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return int64_t{t.tv_sec} * 1000000000 + t.tv_nsec;
}
int64_t process_cpu_ns() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return int64_t{t.tv_sec} * 1000000000 + t.tv_nsec;
}

VkSamplerAddressMode address_mode(pass::AddressMode m) {
  switch (m) {
  case pass::AddressMode::Wrap: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
  case pass::AddressMode::Mirror: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  case pass::AddressMode::Clamp: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  case pass::AddressMode::Border: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  case pass::AddressMode::MirrorOnce: return VK_SAMPLER_ADDRESS_MODE_MAX_ENUM;
  }
  return VK_SAMPLER_ADDRESS_MODE_MAX_ENUM;
}

// D3DCMPFUNC → VkCompareOp. Both compare the reference (left) with the stored value (right).
VkCompareOp compare_op(pass::CompareFunc f) {
  switch (f) {
  case pass::CompareFunc::Never: return VK_COMPARE_OP_NEVER;
  case pass::CompareFunc::Less: return VK_COMPARE_OP_LESS;
  case pass::CompareFunc::Equal: return VK_COMPARE_OP_EQUAL;
  case pass::CompareFunc::LessEqual: return VK_COMPARE_OP_LESS_OR_EQUAL;
  case pass::CompareFunc::Greater: return VK_COMPARE_OP_GREATER;
  case pass::CompareFunc::NotEqual: return VK_COMPARE_OP_NOT_EQUAL;
  case pass::CompareFunc::GreaterEqual: return VK_COMPARE_OP_GREATER_OR_EQUAL;
  case pass::CompareFunc::Always: return VK_COMPARE_OP_ALWAYS;
  }
  return VK_COMPARE_OP_NEVER;
}

// D3DSTENCILOP → VkStencilOp: the _SAT operations clamp, INCR/DECR wrap (pass/stencil.h).
VkStencilOp stencil_op(pass::StencilOp op) {
  switch (op) {
  case pass::StencilOp::Keep: return VK_STENCIL_OP_KEEP;
  case pass::StencilOp::Zero: return VK_STENCIL_OP_ZERO;
  case pass::StencilOp::Replace: return VK_STENCIL_OP_REPLACE;
  case pass::StencilOp::IncrSat: return VK_STENCIL_OP_INCREMENT_AND_CLAMP;
  case pass::StencilOp::DecrSat: return VK_STENCIL_OP_DECREMENT_AND_CLAMP;
  case pass::StencilOp::Invert: return VK_STENCIL_OP_INVERT;
  case pass::StencilOp::Incr: return VK_STENCIL_OP_INCREMENT_AND_WRAP;
  case pass::StencilOp::Decr: return VK_STENCIL_OP_DECREMENT_AND_WRAP;
  }
  return VK_STENCIL_OP_KEEP;
}

// The pipeline's depth/stencil state: D3D9's ZENABLE / ZWRITEENABLE / ZFUNC (Vulkan's
// compare takes the incoming depth on the left, as D3DRS_ZFUNC does, and writes only while
// the test is on, as D3D9 does: pass/depth.h); D3D9's one-sided stencil for both faces
// (culling is off, and D3D9 without D3DRS_TWOSIDEDSTENCILMODE treats both faces alike).
// Reference and masks modulo 256: only the buffer's 8 bits take part.
VkPipelineDepthStencilStateCreateInfo depth_stencil_state(const pass::DepthStencilState& ds) {
  VkPipelineDepthStencilStateCreateInfo out{};
  out.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  out.depthTestEnable = ds.depth_test ? VK_TRUE : VK_FALSE;
  out.depthWriteEnable = ds.depth_test && ds.depth_write ? VK_TRUE : VK_FALSE;
  out.depthCompareOp = ds.depth_test ? compare_op(ds.depth_func) : VK_COMPARE_OP_ALWAYS;
  out.stencilTestEnable = ds.stencil_test ? VK_TRUE : VK_FALSE;
  VkStencilOpState face{};
  face.failOp = stencil_op(ds.stencil_fail);
  face.passOp = stencil_op(ds.stencil_pass);
  face.depthFailOp = stencil_op(ds.stencil_depth_fail);
  face.compareOp = compare_op(ds.stencil_func);
  face.compareMask = ds.stencil_read_mask & 0xffu;
  face.writeMask = ds.stencil_write_mask & 0xffu;
  face.reference = ds.stencil_ref & 0xffu;
  out.front = out.back = face;
  out.minDepthBounds = 0.0f;
  out.maxDepthBounds = 1.0f;
  return out;
}

ir::Status shader_module(Device::Impl& d, Cleanup& cleanup, const std::vector<uint32_t>& words,
                         VkShaderModule& out) {
  VkShaderModuleCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  ci.codeSize = words.size() * sizeof(uint32_t);
  ci.pCode = words.data();
  VkResult r = vkCreateShaderModule(d.device, &ci, nullptr, &out);
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateShaderModule", r));
  cleanup.destroy_later(d.device, out, vkDestroyShaderModule);
  return ir::ok_status();
}

} // namespace

ir::Status create_render_pass(Device::Impl& d, Cleanup& cleanup,
                              const std::vector<VkFormat>& colors, VkFormat stencil,
                              VkRenderPass& out) {
  std::vector<VkAttachmentDescription> atts;
  std::vector<VkAttachmentReference> refs;
  for (VkFormat format : colors) {
    VkAttachmentDescription att{};
    att.format = format;
    att.samples = VK_SAMPLE_COUNT_1_BIT;
    att.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    att.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    att.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    att.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    att.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    refs.push_back({static_cast<uint32_t>(atts.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    atts.push_back(att);
  }
  VkAttachmentReference stencil_ref{static_cast<uint32_t>(atts.size()),
                                    VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  if (stencil != VK_FORMAT_UNDEFINED) {
    VkAttachmentDescription att{};
    att.format = stencil;
    att.samples = VK_SAMPLE_COUNT_1_BIT;
    // The depth aspect of a combined format is never tested; loading and storing it keeps
    // the image whole.
    att.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    att.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    att.stencilStoreOp = VK_ATTACHMENT_STORE_OP_STORE;
    att.initialLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    att.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    atts.push_back(att);
  }
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.colorAttachmentCount = static_cast<uint32_t>(refs.size());
  sub.pColorAttachments = refs.data();
  if (stencil != VK_FORMAT_UNDEFINED) sub.pDepthStencilAttachment = &stencil_ref;
  VkRenderPassCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  ci.attachmentCount = static_cast<uint32_t>(atts.size());
  ci.pAttachments = atts.data();
  ci.subpassCount = 1;
  ci.pSubpasses = &sub;
  VkResult r = vkCreateRenderPass(d.device, &ci, nullptr, &out);
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateRenderPass", r));
  cleanup.destroy_later(d.device, out, vkDestroyRenderPass);
  return ir::ok_status();
}

ir::Status create_framebuffer(Device::Impl& d, Cleanup& cleanup, VkRenderPass rp,
                              const std::vector<const Image2D*>& attachments, VkFramebuffer& out) {
  std::vector<VkImageView> views;
  for (const Image2D* a : attachments) views.push_back(a->view);
  VkFramebufferCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  ci.renderPass = rp;
  ci.attachmentCount = static_cast<uint32_t>(views.size());
  ci.pAttachments = views.data();
  ci.width = attachments.front()->width;
  ci.height = attachments.front()->height;
  ci.layers = 1;
  VkResult r = vkCreateFramebuffer(d.device, &ci, nullptr, &out);
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateFramebuffer", r));
  cleanup.destroy_later(d.device, out, vkDestroyFramebuffer);
  return ir::ok_status();
}

namespace {

// D3D9's mip state as Vulkan's (NUMERICS.md M2): MAXMIPLEVEL m (clamped to the last level)
// is minLod, the lod never goes below it; MIPFILTER NONE reads level m alone (minLod = maxLod
// = m, so no lod is computed); POINT and LINEAR are the NEAREST and LINEAR mipmap modes up to
// the last level; MIPMAPLODBIAS is mipLodBias. One level: minLod = maxLod = 0 whatever the
// state (level 0, as before mip chains).
void set_mip_state(const pass::MipState& mip, uint32_t levels, VkSamplerCreateInfo& ci) {
  const uint32_t last = levels == 0 ? 0 : levels - 1;
  const float m = static_cast<float>(std::min(mip.max_mip_level, last));
  ci.mipmapMode = mip.filter == pass::MipFilter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR
                                                        : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  ci.minLod = m;
  ci.maxLod = mip.filter == pass::MipFilter::None ? m : static_cast<float>(last);
  ci.mipLodBias = last == 0 ? 0.0f : mip.lod_bias;
}

// ADDRESSU/V/W and the border colour of a 2D or volume sampler.
ir::Status set_address_modes(const pass::SamplerState& s, VkSamplerCreateInfo& ci) {
  ci.addressModeU = address_mode(s.address_u);
  ci.addressModeV = address_mode(s.address_v);
  ci.addressModeW = address_mode(s.address_w); // volumes only; 2D views ignore it
  if (ci.addressModeU == VK_SAMPLER_ADDRESS_MODE_MAX_ENUM ||
      ci.addressModeV == VK_SAMPLER_ADDRESS_MODE_MAX_ENUM ||
      ci.addressModeW == VK_SAMPLER_ADDRESS_MODE_MAX_ENUM)
    return draw_failure("the Vulkan device does not support the MirrorOnce address mode");
  const pass::Vec4& b = s.border_color;
  if (b == pass::Vec4{0, 0, 0, 0})
    ci.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  else if (b == pass::Vec4{0, 0, 0, 1})
    ci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
  else if (b == pass::Vec4{1, 1, 1, 1})
    ci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  else
    return draw_failure(
        fmt::format("the Vulkan device supports border colours (0,0,0,0), (0,0,0,1) and "
                    "(1,1,1,1) only, not ({},{},{},{})",
                    b[0], b[1], b[2], b[3]));
  return ir::ok_status();
}

} // namespace

ir::Status create_sampler(Device::Impl& d, Cleanup& cleanup, const pass::SamplerState& s,
                          uint32_t levels, pass::TextureShape shape, VkSampler& out) {
  VkSamplerCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  VkFilter f = s.filter == pass::Filter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  ci.magFilter = ci.minFilter = f;
  ci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  set_mip_state(s.mip, levels, ci);
  if (shape == pass::TextureShape::Cube) {
    // Direct3D 9 ignores ADDRESSU/V (and so the border colour) on a cube and filters each face
    // on its own (NUMERICS.md T4). A non-seamless cube sampler wraps by its address modes, so
    // they are edge clamping, as the CPU device reads a face.
    ci.addressModeU = ci.addressModeV = ci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    ci.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    if (d.cube_faces_alone) ci.flags |= VK_SAMPLER_CREATE_NON_SEAMLESS_CUBE_MAP_BIT_EXT;
  } else if (ir::Status err = set_address_modes(s, ci); !err) {
    return err;
  }
  VkResult r = vkCreateSampler(d.device, &ci, nullptr, &out);
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateSampler", r));
  cleanup.destroy_later(d.device, out, vkDestroySampler);
  return ir::ok_status();
}

ir::Status create_pipeline(Device::Impl& d, Cleanup& cleanup, const PipelineDesc& desc,
                           VkPipeline& out) {
  VkShaderModule vsm = VK_NULL_HANDLE, psm = VK_NULL_HANDLE;
  ir::Status err = shader_module(d, cleanup, desc.vs->words, vsm);
  if (err) err = shader_module(d, cleanup, desc.ps_words, psm);
  if (!err) return err;
  VkPipelineShaderStageCreateInfo stages[2]{};
  stages[0].sType = stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vsm;
  stages[0].pName = desc.vs->entry_point.c_str();
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = psm;
  stages[1].pName = desc.ps->entry_point.c_str();

  // One interleaved binding: all sixteen input registers of a vertex, v# at 16·#.
  VkVertexInputBindingDescription binding{0, desc.vertex_stride, VK_VERTEX_INPUT_RATE_VERTEX};
  std::vector<VkVertexInputAttributeDescription> attrs;
  for (const auto& iv : desc.vs->interface)
    if (iv.kind == codegen::InterfaceKind::Input)
      attrs.push_back({iv.location, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 16 * iv.index});
  VkPipelineVertexInputStateCreateInfo vi{};
  vi.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  vi.vertexBindingDescriptionCount = 1;
  vi.pVertexBindingDescriptions = &binding;
  vi.vertexAttributeDescriptionCount = static_cast<uint32_t>(attrs.size());
  vi.pVertexAttributeDescriptions = attrs.data();
  VkPipelineInputAssemblyStateCreateInfo ia{};
  ia.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo vp{};
  vp.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  vp.viewportCount = vp.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo rs{};
  rs.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = VK_CULL_MODE_NONE; // D3DCULL_NONE, as the CPU device
  rs.frontFace = desc.front_face == pass::FrontFace::Clockwise ? VK_FRONT_FACE_CLOCKWISE
                                                               : VK_FRONT_FACE_COUNTER_CLOCKWISE;
  rs.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo ms{};
  ms.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineColorBlendAttachmentState cba{};
  cba.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                       VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  cba.colorBlendOp = cba.alphaBlendOp = VK_BLEND_OP_ADD;
  // Blending applies to all four channels, as in the CPU device.
  auto factors = [&](VkBlendFactor src, VkBlendFactor dst) {
    cba.blendEnable = VK_TRUE;
    cba.srcColorBlendFactor = cba.srcAlphaBlendFactor = src;
    cba.dstColorBlendFactor = cba.dstAlphaBlendFactor = dst;
  };
  switch (desc.blend) {
  case pass::BlendMode::Replace: break;
  case pass::BlendMode::OneOne: factors(VK_BLEND_FACTOR_ONE, VK_BLEND_FACTOR_ONE); break;
  case pass::BlendMode::SrcAlphaOne: factors(VK_BLEND_FACTOR_SRC_ALPHA, VK_BLEND_FACTOR_ONE); break;
  case pass::BlendMode::SrcAlphaInvSrcAlpha:
    factors(VK_BLEND_FACTOR_SRC_ALPHA, VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA);
    break;
  }
  const std::vector<VkPipelineColorBlendAttachmentState> blends(desc.color_targets, cba);
  VkPipelineColorBlendStateCreateInfo cb{};
  cb.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  cb.attachmentCount = desc.color_targets;
  cb.pAttachments = blends.data();
  const VkPipelineDepthStencilStateCreateInfo dss = depth_stencil_state(desc.depth_stencil);
  VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo ds{};
  ds.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  ds.dynamicStateCount = 2;
  ds.pDynamicStates = dyn;

  VkGraphicsPipelineCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  ci.stageCount = 2;
  ci.pStages = stages;
  ci.pVertexInputState = &vi;
  ci.pInputAssemblyState = &ia;
  ci.pViewportState = &vp;
  ci.pRasterizationState = &rs;
  ci.pMultisampleState = &ms;
  ci.pColorBlendState = &cb;
  if (desc.stencil_attachment) ci.pDepthStencilState = &dss;
  ci.pDynamicState = &ds;
  ci.layout = desc.layout;
  ci.renderPass = desc.render_pass;
  const auto t0 = std::chrono::steady_clock::now();
  const int64_t cpu0 = thread_cpu_ns();
  VkResult r = vkCreateGraphicsPipelines(d.device, pipeline_cache(d), 1, &ci, nullptr, &out);
  g_pipeline_creation_ns +=
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0)
          .count();
  ++g_pipeline_creations;
  g_pipeline_creation_cpu_ns += thread_cpu_ns() - cpu0;
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkCreateGraphicsPipelines", r));
  d.pipeline_cache_dirty = true;
  cleanup.destroy_later(d.device, out, vkDestroyPipeline);
  return ir::ok_status();
}

ir::Status timed_draw_submission(const std::function<ir::Status()>& submit) {
  const auto t0 = std::chrono::steady_clock::now();
  const int64_t cpu0 = process_cpu_ns();
  ir::Status s = submit();
  g_draw_submission_ns +=
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0)
          .count();
  g_draw_submission_cpu_ns += process_cpu_ns() - cpu0;
  ++g_draw_submissions;
  return s;
}

double draw_submission_ms() {
  return static_cast<double>(g_draw_submission_ns.load()) / 1e6;
}
double draw_submission_cpu_ms() {
  return static_cast<double>(g_draw_submission_cpu_ns.load()) / 1e6;
}
long draw_submissions() {
  return g_draw_submissions.load();
}

void count_queue_submission() {
  ++g_queue_submissions;
}
long queue_submissions() {
  return g_queue_submissions.load();
}

double pipeline_creation_cpu_ms() {
  return static_cast<double>(g_pipeline_creation_cpu_ns.load()) / 1e6;
}

long pipeline_creations() {
  return g_pipeline_creations.load();
}

double pipeline_creation_ms() {
  return static_cast<double>(g_pipeline_creation_ns.load()) / 1e6;
}

} // namespace tierlift::vulkan
