// Buffers, images, one-shot submits and pixel conversion for the Vulkan device.
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fmt/format.h>

#include "pipeline.h"
#include "tierlift/rounding/rounding.h"
#include "vk_internal.h"

namespace tierlift::vulkan {
namespace {

// A memory type allowed by `bits` with all `flags`, or UINT32_MAX.
uint32_t find_memory(const Device::Impl& d, uint32_t bits, VkMemoryPropertyFlags flags) {
  for (uint32_t i = 0; i < d.memory.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (d.memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  return UINT32_MAX;
}

// "1.5 GiB", "3.0 MiB", "512 bytes"
std::string size_words(uint64_t bytes) {
  if (bytes >= (1ull << 30)) return fmt::format("{:.1f} GiB", double(bytes) / double(1ull << 30));
  if (bytes >= (1ull << 20)) return fmt::format("{:.1f} MiB", double(bytes) / double(1ull << 20));
  return fmt::format("{} bytes", bytes);
}

uint64_t bytes_per_texel(VkFormat f) {
  switch (f) {
  case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
  case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
  case VK_FORMAT_S8_UINT: return 1;
  default: return 4;
  }
}

std::string format_words(VkFormat f) {
  switch (f) {
  case VK_FORMAT_R32G32B32A32_SFLOAT: return "RGBA32F";
  case VK_FORMAT_R16G16B16A16_SFLOAT: return "RGBA16F";
  case VK_FORMAT_R8G8B8A8_UNORM: return "RGBA8";
  case VK_FORMAT_S8_UINT: return "stencil";
  default: return "depth/stencil";
  }
}

// The memory, or why not in words (`what` names the object the memory is for).
ir::Status allocate(Device::Impl& d, Cleanup& cleanup, const VkMemoryRequirements& req,
                    VkMemoryPropertyFlags flags, VkDeviceMemory& out, const std::string& what) {
  uint32_t type = find_memory(d, req.memoryTypeBits, flags);
  if (type == UINT32_MAX) type = find_memory(d, req.memoryTypeBits, 0);
  if (type == UINT32_MAX) return draw_failure("no suitable Vulkan memory type");
  VkMemoryAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = type;
  VkResult r = vkAllocateMemory(d.device, &ai, nullptr, &out);
  if (r != VK_SUCCESS) return draw_failure(allocation_failed(r, what, req.size));
  cleanup.destroy_later(d.device, out, vkFreeMemory);
  return ir::ok_status();
}

} // namespace

std::string allocation_failed(VkResult r, const std::string& what, uint64_t bytes) {
  return fmt::format("{} while allocating {} ({})", vk_result_words(r), what, size_words(bytes));
}

std::string image_words(uint32_t width, uint32_t height, VkFormat format) {
  return fmt::format("a {}x{} {} image", width, height, format_words(format));
}

uint64_t image_bytes(uint32_t width, uint32_t height, VkFormat format) {
  return uint64_t{width} * height * bytes_per_texel(format);
}

ir::Status create_buffer(Device::Impl& d, Cleanup& cleanup, VkDeviceSize size,
                         VkBufferUsageFlags usage, Buffer& out) {
  VkBufferCreateInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bi.size = size == 0 ? 16 : size;
  bi.usage = usage;
  bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  const std::string what = "a host buffer";
  VkResult r = vkCreateBuffer(d.device, &bi, nullptr, &out.buffer);
  if (r != VK_SUCCESS) return draw_failure(allocation_failed(r, what, bi.size));
  VkDevice dev = d.device;
  VkBuffer buf = out.buffer;
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(dev, buf, &req);
  // Memory is freed after the buffer is destroyed (cleanup runs in reverse order).
  ir::Status err = allocate(
      d, cleanup, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
      out.memory, what);
  if (!err) {
    vkDestroyBuffer(dev, buf, nullptr);
    return err;
  }
  cleanup.destroy_later(dev, buf, vkDestroyBuffer);
  if ((r = vkBindBufferMemory(dev, buf, out.memory, 0)) != VK_SUCCESS)
    return draw_failure(vk_error("vkBindBufferMemory", r));
  if ((r = vkMapMemory(dev, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped)) != VK_SUCCESS)
    return draw_failure(vk_error("vkMapMemory", r));
  out.size = bi.size;
  return ir::ok_status();
}

ir::Status create_image(Device::Impl& d, Cleanup& cleanup, uint32_t width, uint32_t height,
                        VkFormat format, VkImageUsageFlags usage, Image2D& out) {
  return create_layered_image(d, cleanup, width, height, pass::TextureShape::Tex2D, 1, format,
                              usage, out);
}

ir::Status create_layered_image(Device::Impl& d, Cleanup& cleanup, uint32_t width, uint32_t height,
                                pass::TextureShape shape, uint32_t layers, VkFormat format,
                                VkImageUsageFlags usage, Image2D& out, uint32_t levels) {
  using pass::TextureShape;
  const bool cube = shape == TextureShape::Cube, volume = shape == TextureShape::Volume;
  VkImageCreateInfo ii{};
  ii.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  ii.flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  ii.imageType = volume ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  ii.format = format;
  ii.extent = {width, height, volume ? layers : 1};
  ii.mipLevels = levels;
  ii.arrayLayers = cube ? 6 : 1;
  ii.samples = VK_SAMPLE_COUNT_1_BIT;
  ii.tiling = VK_IMAGE_TILING_OPTIMAL;
  ii.usage = usage;
  ii.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  const std::string what = image_words(width, height, format);
  VkResult r = vkCreateImage(d.device, &ii, nullptr, &out.image);
  if (r != VK_SUCCESS)
    return draw_failure(
        allocation_failed(r, what, image_bytes(width, height, format) * (cube ? 6 : layers)));
  VkDevice dev = d.device;
  VkImage img = out.image;
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(dev, img, &req);
  ir::Status err = allocate(d, cleanup, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, out.memory, what);
  if (!err) {
    vkDestroyImage(dev, img, nullptr);
    return err;
  }
  cleanup.destroy_later(dev, img, vkDestroyImage);
  if ((r = vkBindImageMemory(dev, img, out.memory, 0)) != VK_SUCCESS)
    return draw_failure(vk_error("vkBindImageMemory", r));
  VkImageViewCreateInfo vi{};
  vi.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
  vi.image = img;
  vi.viewType = cube     ? VK_IMAGE_VIEW_TYPE_CUBE
                : volume ? VK_IMAGE_VIEW_TYPE_3D
                         : VK_IMAGE_VIEW_TYPE_2D;
  vi.format = format;
  const VkImageAspectFlags aspect = format_aspects(format);
  vi.subresourceRange = {aspect, 0, levels, 0, cube ? 6u : 1u};
  if ((r = vkCreateImageView(dev, &vi, nullptr, &out.view)) != VK_SUCCESS)
    return draw_failure(vk_error("vkCreateImageView", r));
  cleanup.destroy_later(dev, out.view, vkDestroyImageView);
  out.format = format;
  out.width = width;
  out.height = height;
  out.shape = shape;
  out.layers = cube ? 6 : volume ? layers : 1;
  out.aspect = aspect;
  out.levels = levels;
  return ir::ok_status();
}

VkImageAspectFlags format_aspects(VkFormat format) {
  switch (format) {
  case VK_FORMAT_S8_UINT: return VK_IMAGE_ASPECT_STENCIL_BIT;
  case VK_FORMAT_D16_UNORM:
  case VK_FORMAT_X8_D24_UNORM_PACK32:
  case VK_FORMAT_D32_SFLOAT: return VK_IMAGE_ASPECT_DEPTH_BIT;
  case VK_FORMAT_D16_UNORM_S8_UINT:
  case VK_FORMAT_D24_UNORM_S8_UINT:
  case VK_FORMAT_D32_SFLOAT_S8_UINT: return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
  default: return VK_IMAGE_ASPECT_COLOR_BIT;
  }
}

ir::Status begin_commands(Device::Impl& d, VkCommandBuffer& cb) {
  VkCommandBufferAllocateInfo ai{};
  ai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  ai.commandPool = d.pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  cb = VK_NULL_HANDLE;
  VkResult r = vkAllocateCommandBuffers(d.device, &ai, &cb);
  if (r != VK_SUCCESS) {
    cb = VK_NULL_HANDLE;
    return draw_failure(vk_error("vkAllocateCommandBuffers", r));
  }
  VkCommandBufferBeginInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if ((r = vkBeginCommandBuffer(cb, &bi)) != VK_SUCCESS) {
    vkFreeCommandBuffers(d.device, d.pool, 1, &cb);
    cb = VK_NULL_HANDLE;
    return draw_failure(vk_error("vkBeginCommandBuffer", r));
  }
  return ir::ok_status();
}

ir::Status submit_commands(Device::Impl& d, VkCommandBuffer& cb) {
  Cleanup cleanup;
  VkCommandBuffer owned = cb;
  cb = VK_NULL_HANDLE;
  cleanup.add([&] { vkFreeCommandBuffers(d.device, d.pool, 1, &owned); });
  VkResult r = vkEndCommandBuffer(owned);
  if (r != VK_SUCCESS) return draw_failure(vk_error("vkEndCommandBuffer", r));
  VkFenceCreateInfo fi{};
  fi.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkFence fence = VK_NULL_HANDLE;
  if ((r = vkCreateFence(d.device, &fi, nullptr, &fence)) != VK_SUCCESS)
    return draw_failure(vk_error("vkCreateFence", r));
  cleanup.add([&] { vkDestroyFence(d.device, fence, nullptr); });
  VkSubmitInfo si{};
  si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  si.commandBufferCount = 1;
  si.pCommandBuffers = &owned;
  count_queue_submission();
  if ((r = vkQueueSubmit(d.queue, 1, &si, fence)) != VK_SUCCESS)
    return draw_failure(vk_error("vkQueueSubmit", r));
  if ((r = vkWaitForFences(d.device, 1, &fence, VK_TRUE, UINT64_MAX)) != VK_SUCCESS)
    return draw_failure(vk_error("vkWaitForFences", r));
  return ir::ok_status();
}

ir::Status submit_and_wait(Device::Impl& d, const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBuffer cb = VK_NULL_HANDLE;
  if (ir::Status err = begin_commands(d, cb); !err) return err;
  record(cb);
  return submit_commands(d, cb);
}

void image_barrier(VkCommandBuffer cb, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkAccessFlags src_access, VkAccessFlags dst_access,
                   VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage,
                   VkImageAspectFlags aspect) {
  VkImageMemoryBarrier b{};
  b.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  b.srcAccessMask = src_access;
  b.dstAccessMask = dst_access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  // A cube's six faces and a mip chain's levels too.
  b.subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
  vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

VkFormat vk_format(img::Format f) {
  switch (f) {
  case img::Format::RGBA8: return VK_FORMAT_R8G8B8A8_UNORM;
  case img::Format::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
  case img::Format::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
  return VK_FORMAT_R32G32B32A32_SFLOAT;
}

uint32_t bytes_per_pixel(img::Format f) {
  switch (f) {
  case img::Format::RGBA8: return 4;
  case img::Format::RGBA16F: return 8;
  case img::Format::RGBA32F: return 16;
  }
  return 16;
}

void pack_pixels(const img::Image& image, void* dst) {
  size_t n = image.rgba.size();
  switch (image.format) {
  case img::Format::RGBA8: {
    auto* p = static_cast<uint8_t*>(dst);
    for (size_t i = 0; i < n; ++i) {
      float v = image.rgba[i];
      v = v > 0 ? (v < 1 ? v : 1) : 0; // NaN → 0
      p[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
    }
    break;
  }
  case img::Format::RGBA16F: {
    auto* p = static_cast<uint16_t*>(dst);
    for (size_t i = 0; i < n; ++i) p[i] = rounding::half_bits(image.rgba[i]);
    break;
  }
  case img::Format::RGBA32F: std::memcpy(dst, image.rgba.data(), n * sizeof(float)); break;
  }
}

void unpack_pixels(const void* src, img::Image& image) {
  size_t n = image.rgba.size();
  switch (image.format) {
  case img::Format::RGBA8: {
    const std::array<float, 256>& levels = rounding::unorm8_levels(); // k/255.0f
    auto* p = static_cast<const uint8_t*>(src);
    for (size_t i = 0; i < n; ++i) image.rgba[i] = levels[p[i]];
    break;
  }
  case img::Format::RGBA16F: {
    auto* p = static_cast<const uint16_t*>(src);
    for (size_t i = 0; i < n; ++i) image.rgba[i] = rounding::half_from_bits(p[i]);
    break;
  }
  case img::Format::RGBA32F: std::memcpy(image.rgba.data(), src, n * sizeof(float)); break;
  }
}

} // namespace tierlift::vulkan
