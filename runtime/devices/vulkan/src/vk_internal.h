// Internal to the Vulkan device: the state behind Device and the small resource helpers the
// draw uses. Not part of the public API (device.h is).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "tierlift/codegen/unorm8_decode.h"
#include "tierlift/pass/pass.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan {

// Every failure inside the draw layer (a draw, a TextureSet call, the resources they create):
// `message` about "vulkan", rule kDrawRule (device.h). Device creation has its own rules.
inline ir::Failure draw_failure(std::string message) {
  return ir::fail("vulkan", std::string(kDrawRule), std::move(message));
}

// A VkResult in words: "out of device memory" (never the bare number).
std::string vk_result_words(VkResult r);
// "out of host memory in vkCreateImage"
std::string vk_error(const char* what, VkResult r);
// A failed allocation as a sentence: "out of device memory while allocating a 16384x16384
// RGBA32F image (4.0 GiB)"; `what` from image_words, or "a host buffer".
std::string allocation_failed(VkResult r, const std::string& what, uint64_t bytes);
std::string image_words(uint32_t width, uint32_t height, VkFormat format); // "a 4x4 RGBA8 image"
uint64_t image_bytes(uint32_t width, uint32_t height, VkFormat format);

struct Unorm8Converter; // unorm8_to_float.h

struct Device::Impl {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props{};
  VkPhysicalDeviceMemoryProperties memory{};
  // codegen::CodegenOptions::point_sampling_floors: this device is lavapipe and
  // DeviceOptions::llvmpipe_point_sampling leaves it on.
  bool point_sampling_floors = false;
  // How in-place RGBA8 reads decode this device's values into k/255.0f, chosen when the
  // device is created by reading every level (unorm8_probe.h, codegen/unorm8_decode.h);
  // false in_place: no decode is exact here, and RGBA8 textures are read through their
  // exact float copy instead.
  codegen::Unorm8Decode unorm8_decode = codegen::Unorm8Decode::RoundAndRebuild;
  bool unorm8_in_place = true;
  // VkPhysicalDeviceFeatures::fragmentStoresAndAtomics, enabled where the device has it: a
  // traced pixel module (codegen::TracePixel) writes a storage buffer.
  bool fragment_stores = false;
  // VK_EXT_non_seamless_cube_map enabled (DeviceOptions::per_face_cubes and the device offers
  // it): cube samplers filter each face on its own. false: a LINEAR cube read is refused.
  bool cube_faces_alone = false;

  std::unique_ptr<Unorm8Converter> unorm8; // created on first use
  // pipeline_cache.h: created on first use, saved when pipelines were added.
  VkPipelineCache pipeline_cache = VK_NULL_HANDLE;
  bool pipeline_cache_failed = false, pipeline_cache_dirty = false;

  mutable std::mutex messages_mutex;
  std::vector<std::string> messages;
  // DeviceOptions::on_destroyed: told the messages left after the handles are destroyed.
  std::function<void(const std::vector<std::string>&)> on_destroyed;

  ~Impl();
};

// Destroys what was created, in reverse order, when it goes out of scope: every early
// return of the draw cleans up without a goto ladder.
class Cleanup {
public:
  Cleanup() = default;
  Cleanup(const Cleanup&) = delete;
  Cleanup& operator=(const Cleanup&) = delete;
  ~Cleanup() {
    for (auto it = fns_.rbegin(); it != fns_.rend(); ++it) (*it)();
  }
  void add(std::function<void()> fn) { fns_.push_back(std::move(fn)); }
  // Destroys `handle` with `destroy` (a vkDestroy*/vkFree* taking device, handle, allocator)
  // when the cleanup runs.
  template <class Handle, class Destroy>
  void destroy_later(VkDevice dev, Handle handle, Destroy destroy) {
    add([dev, handle, destroy] { destroy(dev, handle, nullptr); });
  }

private:
  std::vector<std::function<void()>> fns_;
};

// A host-visible, coherent, persistently mapped buffer.
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;
};
// The buffer is registered with `cleanup`.
ir::Status create_buffer(Device::Impl& d, Cleanup& cleanup, VkDeviceSize size,
                         VkBufferUsageFlags usage, Buffer& out);

struct Image2D {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  uint32_t width = 0, height = 0;
  // A cube (six array layers, a cube view) or a volume (depth `layers`, a 3D view) for a
  // sampled cube or volume texture (pass::TextureShape); 2D otherwise, with one layer.
  pass::TextureShape shape = pass::TextureShape::Tex2D;
  uint32_t layers = 1;
  // COLOR, or for a stencil buffer STENCIL (with DEPTH when the format has both: barriers and
  // attachment views then name both aspects).
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  uint32_t levels = 1; // mip levels (a 2D texture with a mip chain), all in the view
};
// The aspects of `format`: COLOR, DEPTH, STENCIL or DEPTH|STENCIL.
VkImageAspectFlags format_aspects(VkFormat format);
ir::Status create_image(Device::Impl& d, Cleanup& cleanup, uint32_t width, uint32_t height,
                        VkFormat format, VkImageUsageFlags usage, Image2D& out);
// The same for a cube (`layers` = 6) or volume (`layers` slices) texture, or a 2D texture of
// `levels` mip levels (each max(1, previous / 2), all in the view).
ir::Status create_layered_image(Device::Impl& d, Cleanup& cleanup, uint32_t width, uint32_t height,
                                pass::TextureShape shape, uint32_t layers, VkFormat format,
                                VkImageUsageFlags usage, Image2D& out, uint32_t levels = 1);

// Records commands into a fresh primary command buffer, submits it and waits for it.
ir::Status submit_and_wait(Device::Impl& d, const std::function<void(VkCommandBuffer)>& record);
// The same in two halves, for a command buffer recorded over several calls (TextureSet's
// batch: one submit for a whole frame). submit_commands ends, submits, waits for and frees
// `cb`, which is VK_NULL_HANDLE afterwards (also on failure).
ir::Status begin_commands(Device::Impl& d, VkCommandBuffer& cb);
ir::Status submit_commands(Device::Impl& d, VkCommandBuffer& cb);

// Layout transition of a whole colour image (one level, one layer).
void image_barrier(VkCommandBuffer cb, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkAccessFlags src_access, VkAccessFlags dst_access,
                   VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage,
                   VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);

// Pixels of an img::Image in a Vulkan format's bytes and back.
VkFormat vk_format(img::Format f);
uint32_t bytes_per_pixel(img::Format f);
void pack_pixels(const img::Image& image, void* dst);
void unpack_pixels(const void* src, img::Image& image);

} // namespace tierlift::vulkan
