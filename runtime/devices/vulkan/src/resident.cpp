// Resident textures: creation, the float shadow, and the recorded moves between uses.
#include "resident.h"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "pass_draw.h"
#include "synthetic_programs.h"

namespace tierlift::vulkan {
namespace {

constexpr VkFormat kSampledFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

constexpr VkPipelineStageFlags kFragmentTests =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

// Sampled images are read by the pixel stage and, for vs_3_0's texldl (vertex texture fetch),
// by the vertex stage.
constexpr VkPipelineStageFlags kShaderReads =
    VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;

struct Use {
  VkPipelineStageFlags stage;
  VkAccessFlags access;
};

// What the commands that left an image in `layout` did to it (the barrier's first scope).
// Read-only layouts contribute an execution dependency only (write-after-read).
Use last_use(VkImageLayout layout) {
  switch (layout) {
  case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
    return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT};
  case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL: return {VK_PIPELINE_STAGE_TRANSFER_BIT, 0};
  case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
    return {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
  case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL: return {kShaderReads, 0};
  case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
    return {kFragmentTests, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
  default: return {VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0};
  }
}

// What the commands after the barrier do in `layout` (its second scope).
Use next_use(VkImageLayout layout) {
  switch (layout) {
  case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
    return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT};
  case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
    return {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT};
  case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
    // loadOp LOAD and blending read the attachment, the store writes it.
    return {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
  case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL: return {kShaderReads, VK_ACCESS_SHADER_READ_BIT};
  case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
    // loadOp LOAD and the stencil test read the buffer, the stencil operations write it.
    return {kFragmentTests, VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
  default: return {VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0};
  }
}

bool read_only(VkImageLayout layout) {
  return layout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL ||
         layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

// A texture never written holds zeros: clear it before its first use.
void clear_if_new(VkCommandBuffer cb, Resident& r) {
  if (r.stored.layout != VK_IMAGE_LAYOUT_UNDEFINED) return;
  transition(cb, r.stored, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  const VkImageSubresourceRange range{r.stored.image.aspect, 0, VK_REMAINING_MIP_LEVELS, 0,
                                      VK_REMAINING_ARRAY_LAYERS};
  if (r.depth_stencil()) {
    const VkClearDepthStencilValue zero{r.depth ? r.depth_clear : 1.0f, 0};
    vkCmdClearDepthStencilImage(cb, r.stored.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                &zero, 1, &range);
  } else {
    const VkClearColorValue zero{};
    vkCmdClearColorImage(cb, r.stored.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1,
                         &range);
  }
  r.shadow_current = false;
}

VkBufferImageCopy whole_image(const Resident& r) {
  VkBufferImageCopy copy{};
  const VkImageAspectFlags aspect = r.stencil ? VkImageAspectFlags{VK_IMAGE_ASPECT_STENCIL_BIT}
                                    : r.depth ? VkImageAspectFlags{VK_IMAGE_ASPECT_DEPTH_BIT}
                                              : VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT};
  // A cube's six faces and a volume's slices lie one after the other in the buffer.
  const Image2D& im = r.stored.image;
  copy.imageSubresource = {aspect, 0, 0, im.shape == pass::TextureShape::Cube ? 6u : 1u};
  copy.imageExtent = {r.width, r.height, im.shape == pass::TextureShape::Volume ? im.layers : 1u};
  return copy;
}

} // namespace

Resident::~Resident() = default;

ir::Status create_resident(Device::Impl& d, uint32_t width, uint32_t height, img::Format format,
                           std::unique_ptr<Resident>& out) {
  auto r = std::make_unique<Resident>();
  r->width = width;
  r->height = height;
  r->format = format;
  const VkFormat vf = vk_format(format);
  VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                            VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  // RGBA8 is also read in place: a point read fetches the stored bytes (record_as_fetched).
  if (r->samples_stored() || format == img::Format::RGBA8) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
  if (ir::Status err = create_image(d, r->objects, width, height, vf, usage, r->stored.image); !err)
    return err;
  out = std::move(r);
  return ir::ok_status();
}

ir::Status create_layered_resident(Device::Impl& d, uint32_t width, uint32_t height,
                                   pass::TextureShape shape, uint32_t layers,
                                   std::unique_ptr<Resident>& out) {
  auto r = std::make_unique<Resident>();
  r->width = width;
  r->height = height;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (ir::Status err = create_layered_image(d, r->objects, width, height, shape, layers,
                                            kSampledFormat, usage, r->stored.image);
      !err)
    return err;
  out = std::move(r);
  return ir::ok_status();
}

ir::Status create_mip_resident(Device::Impl& d, uint32_t width, uint32_t height, uint32_t levels,
                               std::unique_ptr<Resident>& out) {
  auto r = std::make_unique<Resident>();
  r->width = width;
  r->height = height;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (ir::Status err = create_layered_image(d, r->objects, width, height, pass::TextureShape::Tex2D,
                                            1, kSampledFormat, usage, r->stored.image, levels);
      !err)
    return err;
  out = std::move(r);
  return ir::ok_status();
}

ir::Status create_stencil_resident(Device::Impl& d, uint32_t width, uint32_t height,
                                   std::unique_ptr<Resident>& out) {
  constexpr VkFormat kCandidates[] = {VK_FORMAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT,
                                      VK_FORMAT_D32_SFLOAT_S8_UINT};
  constexpr VkFormatFeatureFlags kNeeds = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                          VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
                                          VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  VkFormat chosen = VK_FORMAT_UNDEFINED;
  for (VkFormat f : kCandidates) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(d.physical, f, &props);
    if ((props.optimalTilingFeatures & kNeeds) == kNeeds) {
      chosen = f;
      break;
    }
  }
  if (chosen == VK_FORMAT_UNDEFINED)
    return draw_failure("the Vulkan device has no stencil format it can render to and copy");
  auto r = std::make_unique<Resident>();
  r->width = width;
  r->height = height;
  r->stencil = true;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (ir::Status err = create_image(d, r->objects, width, height, chosen, usage, r->stored.image);
      !err)
    return err;
  out = std::move(r);
  return ir::ok_status();
}

uint32_t Resident::packed_bytes() const {
  return stencil ? 1u : depth ? 4u : bytes_per_pixel(format);
}

ir::Status create_depth_resident(Device::Impl& d, uint32_t width, uint32_t height, float clear,
                                 std::unique_ptr<Resident>& out) {
  constexpr VkFormatFeatureFlags kNeeds = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                          VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
                                          VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  VkFormatProperties props;
  vkGetPhysicalDeviceFormatProperties(d.physical, VK_FORMAT_D32_SFLOAT, &props);
  if ((props.optimalTilingFeatures & kNeeds) != kNeeds)
    return draw_failure("the Vulkan device cannot render to and copy a D32_SFLOAT depth buffer");
  auto r = std::make_unique<Resident>();
  r->width = width;
  r->height = height;
  r->depth = true;
  r->depth_clear = clear;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (ir::Status err =
          create_image(d, r->objects, width, height, VK_FORMAT_D32_SFLOAT, usage, r->stored.image);
      !err)
    return err;
  out = std::move(r);
  return ir::ok_status();
}

ir::Status ensure_shadow(Device::Impl& d, Resident& r) {
  if (r.stencil) return draw_failure("a stencil buffer cannot be sampled");
  if (r.depth) return draw_failure("a depth buffer cannot be sampled");
  if (r.samples_stored() || r.shadow) return ir::ok_status();
  const bool unorm8 = r.format == img::Format::RGBA8;
  VkFormatProperties src, dst;
  vkGetPhysicalDeviceFormatProperties(d.physical, vk_format(r.format), &src);
  vkGetPhysicalDeviceFormatProperties(d.physical, kSampledFormat, &dst);
  const bool can = unorm8 || ((src.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT) &&
                              (dst.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT));
  if (!can)
    return draw_failure(
        fmt::format("the Vulkan device cannot convert {} textures to RGBA32F for sampling",
                    img::format_name(r.format)));
  std::unique_ptr<Resident> shadow;
  std::unique_ptr<PreparedDraw> draw;
  ir::Status err = create_resident(d, r.width, r.height, img::Format::RGBA32F, shadow);
  if (err && unorm8 && d.unorm8_in_place) {
    draw = std::make_unique<PreparedDraw>();
    DrawTextures textures;
    textures.stages[0] = &r;
    textures.target = shadow.get();
    err = prepare_draw(d, texel_copy_pass(r.width, r.height), textures, *draw);
    if (err && !draw->fetched[0])
      err = draw_failure("the RGBA8 shadow's draw does not read in place");
  } else if (err && unorm8) {
    err = create_unorm8_scratch(d, r.objects, r.width, r.height, r.unorm8);
  }
  if (!err) return err;
  // Only once complete: a failed call leaves no half-made shadow.
  r.shadow = std::move(shadow);
  r.to_shadow = std::move(draw);
  return ir::ok_status();
}

void transition(VkCommandBuffer cb, TrackedImage& t, VkImageLayout to) {
  if (t.layout == to && read_only(to)) return;
  const Use src = last_use(t.layout), dst = next_use(to);
  image_barrier(cb, t.image.image, t.layout, to, src.access, dst.access, src.stage, dst.stage,
                t.image.aspect);
  t.layout = to;
}

void record_upload(VkCommandBuffer cb, Resident& r, VkBuffer staging) {
  transition(cb, r.stored, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
  // A mip chain's levels lie one after the other in the buffer, level 0 first (RGBA32F).
  std::vector<VkBufferImageCopy> copies(r.stored.image.levels, whole_image(r));
  VkDeviceSize offset = 0;
  for (uint32_t k = 0; k < copies.size(); ++k) {
    const uint32_t w = std::max(1u, r.width >> k), h = std::max(1u, r.height >> k);
    copies[k].bufferOffset = offset;
    copies[k].imageSubresource.mipLevel = k;
    copies[k].imageExtent.width = w;
    copies[k].imageExtent.height = h;
    offset += VkDeviceSize{w} * h * 16;
  }
  vkCmdCopyBufferToImage(cb, staging, r.stored.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<uint32_t>(copies.size()), copies.data());
  r.shadow_current = false;
}

void record_as_target(VkCommandBuffer cb, Resident& r) {
  clear_if_new(cb, r);
  transition(cb, r.stored, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  r.shadow_current = false; // the pass about to run writes it
}

void record_as_stencil(VkCommandBuffer cb, Resident& r) {
  clear_if_new(cb, r);
  transition(cb, r.stored, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
}

void record_as_sampled(VkCommandBuffer cb, const Device::Impl& d, Resident& r) {
  clear_if_new(cb, r);
  if (!r.samples_stored() && !r.shadow_current) {
    TrackedImage& shadow = r.shadow->stored;
    if (r.to_shadow) {
      record_draw(cb, d, *r.to_shadow); // reads r in place, renders the shadow
    } else if (r.format == img::Format::RGBA8) {
      transition(cb, r.stored, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
      transition(cb, shadow, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
      record_unorm8_to_float(cb, d, r.unorm8, r.stored.image.image, shadow.image.image, r.width,
                             r.height);
    } else {
      // NEAREST blit of the same size: every texel converted on its own, no filtering.
      transition(cb, r.stored, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
      transition(cb, shadow, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
      VkImageBlit blit{};
      blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      blit.srcOffsets[1] =
          blit.dstOffsets[1] = {static_cast<int32_t>(r.width), static_cast<int32_t>(r.height), 1};
      vkCmdBlitImage(cb, r.stored.image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     shadow.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                     VK_FILTER_NEAREST);
    }
    r.shadow_current = true;
  }
  transition(cb, r.sampled_tracked(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void record_as_fetched(VkCommandBuffer cb, Resident& r) {
  clear_if_new(cb, r);
  transition(cb, r.stored, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void record_readback(VkCommandBuffer cb, Resident& r, VkBuffer staging) {
  clear_if_new(cb, r);
  transition(cb, r.stored, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  const VkBufferImageCopy copy = whole_image(r);
  vkCmdCopyImageToBuffer(cb, r.stored.image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging, 1,
                         &copy);
  VkBufferMemoryBarrier bb{};
  bb.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
  bb.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  bb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  bb.buffer = staging;
  bb.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                       nullptr, 1, &bb, 0, nullptr);
}

} // namespace tierlift::vulkan
