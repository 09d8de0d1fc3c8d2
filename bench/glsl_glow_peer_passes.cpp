// The GLSL glow peer's passes: its shaders (written by hand), one pipeline and descriptor
// set per pass of the graph, and the frame (glsl_glow_peer.h).
#include <cstring>

#include "glsl_glow_peer_impl.h"

namespace tierlift::bench {
namespace {

// One vertex shader for every pass: a full-screen quad from gl_VertexIndex (uv (0,0) top
// left), NT texture coordinates uv·scale + offset.
std::string vertex_glsl(int coords) {
  return "#version 450\n#define NT " + std::to_string(coords) + R"(
layout(set = 0, binding = 0, std140) uniform U { vec4 coord[8]; vec4 weight[8]; } u;
layout(location = 0) out vec2 t[NT];
void main() {
  vec2 uv = vec2(gl_VertexIndex & 1, gl_VertexIndex >> 1);
  gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
  for (int k = 0; k < NT; ++k) t[k] = uv * u.coord[k].xy + u.coord[k].zw;
})";
}

// The pixel work of each kind of pass.
std::string fragment_glsl(const std::string& kind, int coords) {
  std::string head = "#version 450\n#define NT " + std::to_string(coords) + R"(
layout(set = 0, binding = 0, std140) uniform U { vec4 coord[8]; vec4 weight[8]; } u;
layout(set = 0, binding = 1) uniform sampler2D s0;
layout(set = 0, binding = 2) uniform sampler2D s1;
layout(location = 0) in vec2 t[NT];
layout(location = 0) out vec4 o;
)";
  if (kind == "extract")
    return head + "void main() { vec4 c = texture(s0, t[0]); o = vec4(c.rgb * c.a, c.a); }";
  if (kind == "composite")
    return head + R"(void main() {
  vec4 scene = texture(s0, t[0]);
  o = vec4(scene.rgb + texture(s1, t[1]).rgb * u.weight[0].rgb, scene.a);
})";
  return head + R"(void main() {
  vec4 r = texture(s0, t[0]) * u.weight[0].x;
  for (int k = 1; k < NT; ++k) r += texture(s0, t[k]) * u.weight[k].x;
  o = r;
})";
}

// The kind of a glow pass by its name ("extract", "downsample.0", "blur_h.1", "composite").
std::string kind_of(const std::string& name) {
  const std::string head = name.substr(0, name.find('.'));
  return head == "blur_h" || head == "blur_v" ? "blur" : head;
}

// The pass's coordinates as (scale, offset) and weights, read off its constants the way its
// listings use them: the helper listing computes tK = uv·c(4+K) + cK, the blur listings
// tK = uv + cK; the pixel listings weight read K by cK.
struct Uniforms {
  float coord[8][4] = {};
  float weight[8][4] = {};
};

int fill_uniforms(const effects::PassDesc& p, const std::string& kind, Uniforms& u) {
  int coords = 0;
  if (kind == "blur") {
    coords = int(std::min<size_t>(p.draw.vs_constants.f.size(), 8));
    for (int k = 0; k < coords; ++k) {
      u.coord[k][0] = u.coord[k][1] = 1;
      u.coord[k][2] = p.draw.vs_constants.f[k][0];
      u.coord[k][3] = p.draw.vs_constants.f[k][1];
    }
  } else {
    coords = kind == "extract" ? 1 : kind == "composite" ? 2 : 4;
    for (int k = 0; k < coords; ++k) {
      u.coord[k][0] = p.draw.vs_constants.f[4 + k][0];
      u.coord[k][1] = p.draw.vs_constants.f[4 + k][1];
      u.coord[k][2] = p.draw.vs_constants.f[k][0];
      u.coord[k][3] = p.draw.vs_constants.f[k][1];
    }
  }
  for (size_t k = 0; k < p.draw.ps_constants.f.size() && k < 8; ++k)
    for (int c = 0; c < 4; ++c) u.weight[k][c] = p.draw.ps_constants.f[k][c];
  if (kind == "extract" || kind == "composite") return coords;
  // A read weighted 0 adds exactly 0: a chain written by hand does not make it (the lift
  // leaves it out too, ir::zero_constant_products). The glow's last blur pass of an axis
  // weights the slots past the last tap by 0. At least one read stays.
  int kept = 0;
  for (int k = 0; k < coords; ++k) {
    const bool zero =
        u.weight[k][0] == 0 && u.weight[k][1] == 0 && u.weight[k][2] == 0 && u.weight[k][3] == 0;
    if (zero && (kept > 0 || k + 1 < coords)) continue;
    std::memmove(u.coord[kept], u.coord[k], sizeof(u.coord[k]));
    std::memmove(u.weight[kept], u.weight[k], sizeof(u.weight[k]));
    ++kept;
  }
  return kept;
}

} // namespace

void GlslGlowPeer::Impl::create_pass(const effects::EffectGraph& g, const effects::PassDesc& p) {
  Pass pass;
  const std::string kind = kind_of(p.name);
  pass.target = &textures.at(p.target);
  pass.replace = p.draw.blend == pass::BlendMode::Replace;
  VkSampler samplers[2] = {point, point};
  for (const effects::TextureBind& b : p.textures) {
    // Stage 0 (ps_1_x binds the same texture on stages 0..3) and, for the composite, 1.
    const int slot = kind == "composite" && b.stage == 1 ? 1 : b.stage == 0 ? 0 : -1;
    if (slot < 0) continue;
    (slot ? pass.s1 : pass.s0) = &textures.at(b.texture);
    samplers[slot] =
        p.draw.textures[b.stage].sampler.filter == pass::Filter::Linear ? linear : point;
  }
  if (!pass.s0) throw PeerError{"pass " + p.name + ": no texture on stage 0"};
  if (!pass.s1) pass.s1 = pass.s0;
  (void)g;

  Uniforms u;
  const int coords = fill_uniforms(p, kind, u);
  VkBufferCreateInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bi.size = sizeof(Uniforms);
  bi.usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  check(vkCreateBuffer(device, &bi, nullptr, &pass.ubo), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, pass.ubo, &req);
  pass.ubo_memory =
      allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check(vkBindBufferMemory(device, pass.ubo, pass.ubo_memory, 0), "vkBindBufferMemory");
  void* mapped = nullptr;
  check(vkMapMemory(device, pass.ubo_memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  std::memcpy(mapped, &u, sizeof(u));
  vkUnmapMemory(device, pass.ubo_memory);

  VkDescriptorSetAllocateInfo dsa{};

  dsa.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  dsa.descriptorPool = descriptors;
  dsa.descriptorSetCount = 1;
  dsa.pSetLayouts = &set_layout;
  check(vkAllocateDescriptorSets(device, &dsa, &pass.set), "vkAllocateDescriptorSets");
  VkDescriptorBufferInfo buffer_info{pass.ubo, 0, VK_WHOLE_SIZE};
  VkDescriptorImageInfo image_info[2] = {
      {samplers[0], pass.s0->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
      {samplers[1], pass.s1->view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
  VkWriteDescriptorSet w[3]{};
  for (int k = 0; k < 3; ++k) {
    w[k].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w[k].dstSet = pass.set;
    w[k].dstBinding = uint32_t(k);
    w[k].descriptorCount = 1;
    w[k].descriptorType =
        k == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  }
  w[0].pBufferInfo = &buffer_info;
  w[1].pImageInfo = &image_info[0];
  w[2].pImageInfo = &image_info[1];
  vkUpdateDescriptorSets(device, 3, w, 0, nullptr);

  const VkRenderPass rp = render_pass(vk_format_of(pass.target->format), !pass.replace);
  if (!pass.target->framebuffer) {
    // Framebuffers are compatible across the load and don't-care render passes.
    VkFramebufferCreateInfo fi{};
    fi.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fi.renderPass = rp;
    fi.attachmentCount = 1;
    fi.pAttachments = &pass.target->view;
    fi.width = pass.target->width;
    fi.height = pass.target->height;
    fi.layers = 1;
    check(vkCreateFramebuffer(device, &fi, nullptr, &pass.target->framebuffer),
          "vkCreateFramebuffer");
  }

  VkPipelineShaderStageCreateInfo stages[2]{};
  stages[0].sType = stages[1].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = module(EShLangVertex, vertex_glsl(coords));
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = module(EShLangFragment, fragment_glsl(kind, coords));
  stages[1].pName = "main";
  VkPipelineVertexInputStateCreateInfo vi{};
  vi.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  VkPipelineInputAssemblyStateCreateInfo ia{};
  ia.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  // The listings' constants carry D3D9's half texel (pixel i at uv i/W): shift the viewport
  // by half a pixel, as tierlift does, so that the peer reads the same texels.
  VkViewport viewport{0.5f, 0.5f, float(pass.target->width), float(pass.target->height), 0, 1};
  VkRect2D scissor{{0, 0}, {pass.target->width, pass.target->height}};
  VkPipelineViewportStateCreateInfo vp{};
  vp.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  vp.viewportCount = vp.scissorCount = 1;
  vp.pViewports = &viewport;
  vp.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo rs{};
  rs.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = VK_CULL_MODE_NONE;
  rs.lineWidth = 1;
  VkPipelineMultisampleStateCreateInfo ms{};
  ms.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineColorBlendAttachmentState cba{};
  cba.colorWriteMask = 0xF;
  if (!pass.replace) {
    cba.blendEnable = VK_TRUE;
    cba.srcColorBlendFactor = cba.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    cba.dstColorBlendFactor = cba.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    cba.colorBlendOp = cba.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  VkPipelineColorBlendStateCreateInfo cb{};
  cb.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  cb.attachmentCount = 1;
  cb.pAttachments = &cba;
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
  ci.layout = layout;
  ci.renderPass = rp;
  check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &ci, nullptr, &pass.pipeline),
        "vkCreateGraphicsPipelines");
  passes.push_back(pass);
}

GlslGlowPeer::GlslGlowPeer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlslGlowPeer::~GlslGlowPeer() = default;

std::unique_ptr<GlslGlowPeer> GlslGlowPeer::create(const effects::EffectGraph& graph,
                                                   const img::Image& scene, std::string* error) {
  auto impl = std::make_unique<Impl>();
  try {
    impl->create_device();
    impl->create_shared();
    for (const effects::TextureDesc& t : graph.textures) impl->create_texture(t);
    for (const effects::TextureDesc& t : graph.textures)
      if (t.input) impl->upload(impl->textures.at(t.name), scene);
    for (const effects::PassDesc& p : graph.passes) impl->create_pass(graph, p);
  } catch (const PeerError& e) {
    if (error) *error = e.what;
    return nullptr;
  }
  return std::unique_ptr<GlslGlowPeer>(new GlslGlowPeer(std::move(impl)));
}

std::string GlslGlowPeer::frame() {
  Impl& m = *impl_;
  try {
    VkCommandBuffer cb = m.begin();
    for (Pass& p : m.passes) {
      m.transition(cb, *p.s0, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
      m.transition(cb, *p.s1, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
      m.transition(cb, *p.target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
      VkRenderPassBeginInfo rbi{};
      rbi.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
      rbi.renderPass = m.render_pass(vk_format_of(p.target->format), !p.replace);
      rbi.framebuffer = p.target->framebuffer;
      rbi.renderArea = {{0, 0}, {p.target->width, p.target->height}};
      vkCmdBeginRenderPass(cb, &rbi, VK_SUBPASS_CONTENTS_INLINE);
      vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
      vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, m.layout, 0, 1, &p.set, 0,
                              nullptr);
      vkCmdDraw(cb, 4, 1, 0, 0);
      vkCmdEndRenderPass(cb);
    }
    m.submit(cb);
  } catch (const PeerError& e) {
    return e.what;
  }
  return {};
}

std::string GlslGlowPeer::read(const std::string& texture, img::Image& out) {
  Impl& m = *impl_;
  auto it = m.textures.find(texture);
  if (it == m.textures.end()) return "no texture " + texture;
  Texture& t = it->second;
  if (t.format != img::Format::RGBA32F) return "the peer reads RGBA32F textures only";
  try {
    VkBufferCreateInfo bi{};
    bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bi.size = VkDeviceSize{t.width} * t.height * 16;
    bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(m.device, &bi, nullptr, &buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(m.device, buffer, &req);
    VkDeviceMemory memory =
        m.allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkBindBufferMemory(m.device, buffer, memory, 0), "vkBindBufferMemory");
    VkCommandBuffer cb = m.begin();
    m.transition(cb, t, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {t.width, t.height, 1};
    vkCmdCopyImageToBuffer(cb, t.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &copy);
    VkBufferMemoryBarrier bb{};
    bb.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    bb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    bb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    bb.buffer = buffer;
    bb.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                         nullptr, 1, &bb, 0, nullptr);
    m.submit(cb);
    void* mapped = nullptr;
    check(vkMapMemory(m.device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
    out = img::Image(t.width, t.height, img::Format::RGBA32F);
    std::memcpy(out.rgba.data(), mapped, bi.size);
    vkDestroyBuffer(m.device, buffer, nullptr);
    vkFreeMemory(m.device, memory, nullptr);
  } catch (const PeerError& e) {
    return e.what;
  }
  return {};
}

std::string GlslGlowPeer::device_name() const {
  return impl_->name;
}

} // namespace tierlift::bench
