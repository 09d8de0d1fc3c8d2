// The GLSL glow peer's Vulkan plumbing: device, textures, uploads, barriers, render passes,
// shader modules, samplers and the descriptor layout (glsl_glow_peer_impl.h).
#include <cstring>

#include "glsl_glow_peer_impl.h"
#include "glslang_peer.h"

namespace tierlift::bench {

VkFormat vk_format_of(img::Format f) {
  switch (f) {
  case img::Format::RGBA8: return VK_FORMAT_R8G8B8A8_UNORM;
  case img::Format::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
  case img::Format::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
  return VK_FORMAT_R32G32B32A32_SFLOAT;
}

GlslGlowPeer::Impl::~Impl() {
  if (device) {
    vkDeviceWaitIdle(device);
    for (Pass& p : passes) {
      vkDestroyPipeline(device, p.pipeline, nullptr);
      vkDestroyBuffer(device, p.ubo, nullptr);
      vkFreeMemory(device, p.ubo_memory, nullptr);
    }
    for (auto& [name, t] : textures) {
      vkDestroyFramebuffer(device, t.framebuffer, nullptr);
      vkDestroyImageView(device, t.view, nullptr);
      vkDestroyImage(device, t.image, nullptr);
      vkFreeMemory(device, t.memory, nullptr);
    }
    for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
    for (auto& [key, rp] : render_passes) vkDestroyRenderPass(device, rp, nullptr);
    vkDestroyDescriptorPool(device, descriptors, nullptr);
    vkDestroyPipelineLayout(device, layout, nullptr);
    vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
    vkDestroySampler(device, point, nullptr);
    vkDestroySampler(device, linear, nullptr);
    vkDestroyFence(device, fence, nullptr);
    vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyDevice(device, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
}

uint32_t GlslGlowPeer::Impl::memory_type(uint32_t bits, VkMemoryPropertyFlags flags) const {
  for (uint32_t i = 0; i < memory_props.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (memory_props.memoryTypes[i].propertyFlags & flags) == flags)
      return i;
  throw PeerError{"no suitable memory type"};
}

VkDeviceMemory GlslGlowPeer::Impl::allocate(const VkMemoryRequirements& req,
                                            VkMemoryPropertyFlags flags) {
  VkMemoryAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = memory_type(req.memoryTypeBits, flags);
  VkDeviceMemory m = VK_NULL_HANDLE;
  check(vkAllocateMemory(device, &ai, nullptr, &m), "vkAllocateMemory");
  return m;
}

void GlslGlowPeer::Impl::create_device() {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo ici{};
  ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ici.pApplicationInfo = &app;
  check(vkCreateInstance(&ici, nullptr, &instance), "vkCreateInstance");
  uint32_t n = 0;
  vkEnumeratePhysicalDevices(instance, &n, nullptr);
  std::vector<VkPhysicalDevice> all(n);
  vkEnumeratePhysicalDevices(instance, &n, all.data());
  for (VkPhysicalDevice pd : all) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(pd, &p);
    if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && !physical) {
      physical = pd;
      name = p.deviceName;
    }
  }
  if (!physical) throw PeerError{"no CPU Vulkan device (lavapipe)"};
  vkGetPhysicalDeviceMemoryProperties(physical, &memory_props);
  uint32_t qn = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &qn, nullptr);
  std::vector<VkQueueFamilyProperties> families(qn);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &qn, families.data());
  uint32_t family = 0;
  while (family < qn && !(families[family].queueFlags & VK_QUEUE_GRAPHICS_BIT)) ++family;
  const float priority = 1;
  VkDeviceQueueCreateInfo qci{};
  qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qci.queueFamilyIndex = family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{};
  dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  check(vkCreateDevice(physical, &dci, nullptr, &device), "vkCreateDevice");
  vkGetDeviceQueue(device, family, 0, &queue);
  VkCommandPoolCreateInfo pci{};
  pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = family;
  check(vkCreateCommandPool(device, &pci, nullptr, &pool), "vkCreateCommandPool");
  VkFenceCreateInfo fci{};
  fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  check(vkCreateFence(device, &fci, nullptr, &fence), "vkCreateFence");
}

void GlslGlowPeer::Impl::create_texture(const effects::TextureDesc& d) {
  Texture t;
  t.width = d.width;
  t.height = d.height;
  t.format = d.format;
  VkImageCreateInfo ii{};
  ii.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  ii.imageType = VK_IMAGE_TYPE_2D;
  ii.format = vk_format_of(d.format);
  ii.extent = {d.width, d.height, 1};
  ii.mipLevels = ii.arrayLayers = 1;
  ii.samples = VK_SAMPLE_COUNT_1_BIT;
  ii.tiling = VK_IMAGE_TILING_OPTIMAL;
  ii.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
             VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  check(vkCreateImage(device, &ii, nullptr, &t.image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, t.image, &req);
  t.memory = allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check(vkBindImageMemory(device, t.image, t.memory, 0), "vkBindImageMemory");
  VkImageViewCreateInfo vi{};
  vi.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  vi.image = t.image;
  vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
  vi.format = ii.format;
  vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  check(vkCreateImageView(device, &vi, nullptr, &t.view), "vkCreateImageView");
  textures.emplace(d.name, t);
}

VkCommandBuffer GlslGlowPeer::Impl::begin() {
  VkCommandBufferAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  ai.commandPool = pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  VkCommandBuffer cb = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device, &ai, &cb), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cb, &bi), "vkBeginCommandBuffer");
  return cb;
}

void GlslGlowPeer::Impl::submit(VkCommandBuffer cb) {
  check(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
  VkSubmitInfo si{};
  si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cb;
  check(vkResetFences(device, 1, &fence), "vkResetFences");
  check(vkQueueSubmit(queue, 1, &si, fence), "vkQueueSubmit");
  check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  vkFreeCommandBuffers(device, pool, 1, &cb);
}

void GlslGlowPeer::Impl::transition(VkCommandBuffer cb, Texture& t, VkImageLayout to) {
  if (t.layout == to && to == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) return;
  VkImageMemoryBarrier b{};
  b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  b.oldLayout = t.layout;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = t.image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkPipelineStageFlags src = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, dst = 0;
  switch (t.layout) {
  case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
    src = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    b.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    break;
  case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL: src = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT; break;
  case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
    src = VK_PIPELINE_STAGE_TRANSFER_BIT;
    b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    break;
  case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL: src = VK_PIPELINE_STAGE_TRANSFER_BIT; break;
  default: break;
  }
  switch (to) {
  case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
    dst = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    b.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    break;
  case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
    dst = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    break;
  case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
    dst = VK_PIPELINE_STAGE_TRANSFER_BIT;
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    break;
  default:
    dst = VK_PIPELINE_STAGE_TRANSFER_BIT;
    b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    break;
  }
  vkCmdPipelineBarrier(cb, src, dst, 0, 0, nullptr, 0, nullptr, 1, &b);
  t.layout = to;
}

// The scene goes up as floats into an RGBA32F image, then a same-size blit stores it in the
// scene's format (the peer's setup; the frame never uploads).
void GlslGlowPeer::Impl::upload(Texture& t, const img::Image& image) {
  effects::TextureDesc staging_desc{"#staging", t.width, t.height, img::Format::RGBA32F, false};
  create_texture(staging_desc);
  Texture& staging = textures.at("#staging");
  VkBufferCreateInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bi.size = image.rgba.size() * 4;
  bi.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vkCreateBuffer(device, &bi, nullptr, &buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, buffer, &req);
  VkDeviceMemory memory =
      allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
  void* mapped = nullptr;
  check(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  std::memcpy(mapped, image.rgba.data(), bi.size);
  VkCommandBuffer cb = begin();
  transition(cb, staging, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {t.width, t.height, 1};
  vkCmdCopyBufferToImage(cb, buffer, staging.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  transition(cb, staging, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  transition(cb, t, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  VkImageBlit blit{};
  blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = blit.dstOffsets[1] = {int32_t(t.width), int32_t(t.height), 1};
  vkCmdBlitImage(cb, staging.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, t.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
  transition(cb, t, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  submit(cb);
  vkDestroyBuffer(device, buffer, nullptr);
  vkFreeMemory(device, memory, nullptr);
  vkDestroyImageView(device, staging.view, nullptr);
  vkDestroyImage(device, staging.image, nullptr);
  vkFreeMemory(device, staging.memory, nullptr);
  textures.erase("#staging");
}

VkRenderPass GlslGlowPeer::Impl::render_pass(VkFormat format, bool load) {
  auto& rp = render_passes[{format, load}];
  if (rp) return rp;
  VkAttachmentDescription att{};
  att.format = format;
  att.samples = VK_SAMPLE_COUNT_1_BIT;
  att.loadOp = load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  att.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att.initialLayout = att.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.colorAttachmentCount = 1;
  sub.pColorAttachments = &ref;
  VkRenderPassCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  ci.attachmentCount = 1;
  ci.pAttachments = &att;
  ci.subpassCount = 1;
  ci.pSubpasses = &sub;
  check(vkCreateRenderPass(device, &ci, nullptr, &rp), "vkCreateRenderPass");
  return rp;
}

VkShaderModule GlslGlowPeer::Impl::module(EShLanguage stage, const std::string& glsl) {
  std::vector<uint32_t> words = glslang_to_spirv(stage, glsl.c_str());
  if (words.empty()) throw PeerError{"glslang rejected:\n" + glsl};
  VkShaderModuleCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  ci.codeSize = words.size() * 4;
  ci.pCode = words.data();
  VkShaderModule m = VK_NULL_HANDLE;
  check(vkCreateShaderModule(device, &ci, nullptr, &m), "vkCreateShaderModule");
  modules.push_back(m);
  return m;
}

void GlslGlowPeer::Impl::create_shared() {
  for (bool lin : {false, true}) {
    VkSamplerCreateInfo si{};
    si.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    si.magFilter = si.minFilter = lin ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    check(vkCreateSampler(device, &si, nullptr, lin ? &linear : &point), "vkCreateSampler");
  }
  VkDescriptorSetLayoutBinding b[3] = {
      {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo dli{};
  dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  dli.bindingCount = 3;
  dli.pBindings = b;
  check(vkCreateDescriptorSetLayout(device, &dli, nullptr, &set_layout), "DSL");
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &set_layout;
  check(vkCreatePipelineLayout(device, &pli, nullptr, &layout), "vkCreatePipelineLayout");
  VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 256},
                                   {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 512}};
  VkDescriptorPoolCreateInfo dpi{};
  dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  dpi.maxSets = 256;
  dpi.poolSizeCount = 2;
  dpi.pPoolSizes = sizes;
  check(vkCreateDescriptorPool(device, &dpi, nullptr, &descriptors), "vkCreateDescriptorPool");
}

} // namespace tierlift::bench
