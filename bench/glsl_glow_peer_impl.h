// Internal to the GLSL glow peer (glsl_glow_peer.h): its Vulkan objects. Errors are thrown
// as PeerError inside and become messages at the public entry points.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <glslang/Public/ShaderLang.h>
#include <vulkan/vulkan.h>

#include "glsl_glow_peer.h"

namespace tierlift::bench {

struct PeerError {
  std::string what;
};

inline void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw PeerError{std::string(what) + " failed: " + std::to_string(int(r))};
}

VkFormat vk_format_of(img::Format f);

struct Texture {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  uint32_t width = 0, height = 0;
  img::Format format = img::Format::RGBA32F;
};

struct Pass {
  Texture* target = nullptr;
  Texture* s0 = nullptr;
  Texture* s1 = nullptr;
  bool replace = true;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkBuffer ubo = VK_NULL_HANDLE;
  VkDeviceMemory ubo_memory = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
};

struct GlslGlowPeer::Impl {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory_props{};
  std::string name;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkSampler point = VK_NULL_HANDLE, linear = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorPool descriptors = VK_NULL_HANDLE;
  std::map<std::pair<VkFormat, bool>, VkRenderPass> render_passes; // (format, load)
  std::vector<VkShaderModule> modules;
  std::map<std::string, Texture, std::less<>> textures;
  std::vector<Pass> passes;

  ~Impl();
  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags flags) const;
  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags flags);
  void create_device();
  void create_texture(const effects::TextureDesc& t);
  void upload(Texture& t, const img::Image& image);
  VkRenderPass render_pass(VkFormat format, bool load);
  VkShaderModule module(EShLanguage stage, const std::string& glsl);
  void create_shared();
  void create_pass(const effects::EffectGraph& g, const effects::PassDesc& p);
  void transition(VkCommandBuffer cb, Texture& t, VkImageLayout to);
  void submit(VkCommandBuffer cb);
  VkCommandBuffer begin();
};

} // namespace tierlift::bench
