// Internal: one texture that lives in device memory, and the commands that move it between
// its uses (upload, render target, sampled, readback) with the barriers each use needs.
//
// A texture is stored in its own format (RGBA8 UNORM, RGBA16F, RGBA32F): that is where a
// pass renders and blends (loadOp LOAD) and what a readback returns. Passes sample a
// R32G32B32A32_SFLOAT image: lavapipe filters float textures with exact float weights, which
// is what keeps the CPU device and lavapipe bit-identical (an RGBA8 UNORM texture may be
// filtered with fixed-point weights). For RGBA32F the stored image is sampled directly; for
// RGBA8 and RGBA16F a float "shadow" texture is made on the device when a pass samples the
// texture after it changed, exactly:
//   * RGBA16F by a same-size NEAREST blit (every half is a float; measured exact for all
//     63 490 non-NaN halves);
//   * RGBA8, on a device whose in-place reads decode exactly (Device::Impl::unorm8_in_place),
//     by a draw into the shadow that reads each texel in place (synthetic_programs.h:
//     texel_copy_pass, the same read a point-sampling pass makes);
//   * RGBA8 elsewhere, through the compute conversion of unorm8_to_float.h (lavapipe's own
//     blit is one ulp off in 126 of the 256 levels).
// The draw replaced the compute conversion (a copy to a buffer, the dispatch, a copy back)
// where it can: one render pass instead of three commands. Alternating against the
// hand-written GLSL chain, the 1080p RGBA8 glow went from 1.17–1.18 to 1.12–1.14 of its
// frame (dx9); dx8 did not move beyond noise.
// A point read of an RGBA8 texture with edge clamping needs no shadow: its shader fetches the
// stored bytes and converts them exactly itself (record_as_fetched), so the shadow is made
// only for the other reads (linear filtering, wrap or mirror addressing).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "tierlift/image/image.h"
#include "unorm8_to_float.h"
#include "vk_internal.h"

namespace tierlift::vulkan {

// An image and the layout its last command left it in. UNDEFINED: never written.
struct TrackedImage {
  Image2D image;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

struct PreparedDraw; // pass_draw.h

struct Resident {
  uint32_t width = 0, height = 0;
  img::Format format = img::Format::RGBA32F;
  // A D3D9 8-bit stencil buffer (create_stencil_resident): `stored` is a depth/stencil image
  // whose stencil aspect is the buffer; it is never sampled, and a readback returns one byte
  // per pixel. `format` is then meaningless.
  bool stencil = false;
  // A D3D9 depth buffer (create_depth_resident): `stored` is a D32_SFLOAT image, never
  // sampled; it starts at `depth_clear` (or what TextureSet::upload puts there), and a
  // readback returns one float per pixel. `format` is then meaningless.
  bool depth = false;
  float depth_clear = 1.0f;
  TrackedImage stored;         // in `format`
  bool shadow_current = false; // shadow holds the stored values
  Unorm8Scratch unorm8;        // RGBA8 converted by compute: the conversion's buffers
  Cleanup objects;             // owns the Vulkan objects above (destroyed with the texture)
  // RGBA8 / RGBA16F only, created on first sampling (ensure_shadow): the RGBA32F texture
  // passes sample, and for RGBA8 read in place the draw that fills it. Declared last so
  // that the draw goes first, then the shadow, then this texture's own objects.
  std::unique_ptr<Resident> shadow;
  std::unique_ptr<PreparedDraw> to_shadow;

  ~Resident(); // where PreparedDraw is complete (resident.cpp)

  bool samples_stored() const { return !stencil && !depth && format == img::Format::RGBA32F; }
  bool depth_stencil() const { return stencil || depth; } // an attachment, never sampled
  // Bytes of one pixel in an upload or readback buffer.
  uint32_t packed_bytes() const;
  // The image passes sample and its tracked layout (valid after ensure_shadow).
  TrackedImage& sampled_tracked() { return samples_stored() ? stored : shadow->stored; }
  const Image2D& sampled() const { return samples_stored() ? stored.image : shadow->stored.image; }
};

// A texture of `width` × `height` in `format` (sizes already checked by the caller). Its
// contents are zero until written: a texture whose stored layout is still UNDEFINED is
// cleared by the first command that uses it.
ir::Status create_resident(Device::Impl& d, uint32_t width, uint32_t height, img::Format format,
                           std::unique_ptr<Resident>& out);
// A cube or volume texture to sample (RGBA32F, `layers` faces or slices of `width` ×
// `height`), filled by record_upload from the layers one after the other; never a target.
ir::Status create_layered_resident(Device::Impl& d, uint32_t width, uint32_t height,
                                   pass::TextureShape shape, uint32_t layers,
                                   std::unique_ptr<Resident>& out);
// A 2D texture to sample with a mip chain (RGBA32F, `levels` levels from `width` × `height`,
// each max(1, previous / 2)), filled by record_upload from the levels one after the other,
// level 0 first; never a target.
ir::Status create_mip_resident(Device::Impl& d, uint32_t width, uint32_t height, uint32_t levels,
                               std::unique_ptr<Resident>& out);
// An 8-bit stencil buffer of `width` × `height`, all zero: VK_FORMAT_S8_UINT where the
// device can render to it and copy it, else the first of D24_UNORM_S8_UINT and
// D32_SFLOAT_S8_UINT that it can (the depth aspect is never tested or written).
ir::Status create_stencil_resident(Device::Impl& d, uint32_t width, uint32_t height,
                                   std::unique_ptr<Resident>& out);
// A depth buffer of `width` × `height` (VK_FORMAT_D32_SFLOAT), every pixel `clear` until an
// upload replaces it.
ir::Status create_depth_resident(Device::Impl& d, uint32_t width, uint32_t height, float clear,
                                 std::unique_ptr<Resident>& out);
// Creates the float shadow if the texture needs one and has none (before recording).
ir::Status ensure_shadow(Device::Impl& d, Resident& r);

// Layout change with the stages and accesses both layouts imply. Read-only to the same
// read-only layout records nothing (no hazard); every other pair records a barrier, so a
// write is always made available to the next use, across submits too.
void transition(VkCommandBuffer cb, TrackedImage& t, VkImageLayout to);

// Recorders. Each leaves the texture in the layout its use needs.
// Copies `staging` (pixels packed in r.format, pack_pixels) into the stored image.
void record_upload(VkCommandBuffer cb, Resident& r, VkBuffer staging);
// Makes the stored image the colour attachment of a render pass (loadOp LOAD reads it).
void record_as_target(VkCommandBuffer cb, Resident& r);
// Makes a stencil or depth buffer the depth/stencil attachment of a render pass (loaded and
// stored).
void record_as_stencil(VkCommandBuffer cb, Resident& r);
// Makes the image passes sample current and SHADER_READ_ONLY_OPTIMAL (ensure_shadow first).
void record_as_sampled(VkCommandBuffer cb, const Device::Impl& d, Resident& r);
// Makes the stored RGBA8 image itself SHADER_READ_ONLY_OPTIMAL, for a stage whose reads fetch
// its bytes (codegen::CodegenOptions::stage_fetch_unorm8): no float shadow is made or needed.
void record_as_fetched(VkCommandBuffer cb, Resident& r);
// Copies the stored image into `staging` and makes it visible to the host (a stencil
// buffer: its stencil aspect, one byte per pixel, rows packed).
void record_readback(VkCommandBuffer cb, Resident& r, VkBuffer staging);

} // namespace tierlift::vulkan
