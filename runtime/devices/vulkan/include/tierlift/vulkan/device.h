// The Vulkan device: one headless Vulkan instance and logical device (lavapipe by default)
// that draws the device-neutral pass description (pass::Pass) with tierlift's own SPIR-V.
//
// How a pass maps onto Vulkan:
//   * Programs: compile_pair(vertex, pixel) with link-time pruning. A pass without a vertex
//     program gets a generated vs_2_0 pass-through (v0 → oPos, v1/v2 → oD0/oD1, v3+N → oTN)
//     fed with `transformed` or, for `constant_inputs`, the full-screen quad carrying the
//     same values at all four corners (equal vertex values interpolate to themselves). A pass
//     without a pixel program gets `mov oC0, v0` (D3D9's fixed function passes oD0).
//   * D3D9 pixel centres: the viewport is offset by (+0.5, +0.5) pixel (DXVK's choice; the
//     shader's fix-up specialization constants stay 0). An exact binary offset, so vertex
//     positions snap to the same 1/256-pixel grid as the CPU device's rasteriser. Modern
//     centres: no offset. The scissor is the D3D9 viewport clipped to the target.
//   * Render targets RGBA8 UNORM, RGBA16F, RGBA32F, up to four (MRT: oC# at colour
//     attachment #, all blended alike); a stencil buffer is a depth/stencil attachment
//     (S8_UINT where the device renders to it, else D24S8 / D32S8) with the pass's D3D9
//     stencil state on both faces, loaded and stored like the colour targets; a depth buffer
//     is a D32_SFLOAT attachment with the pass's ZENABLE / ZWRITEENABLE / ZFUNC (pass/depth.h:
//     the SPIR-V clamps oDepth to [0, 1] before it writes FragDepth). The target image's
//     current contents are uploaded first (loadOp LOAD), so blending sees the stored destination,
//     and read back as floats (RGBA8: k/255; RGBA16F: the half's value). TextureSet (texture_set.h)
//     keeps targets and textures on the device between draws instead; both paths share one draw.
//   * Textures: each bound stage's img::Image uploaded as R32G32B32A32_SFLOAT; unbound
//     stages get a 1×1 (0, 0, 0, 1) texture. Samplers: point/linear, wrap/mirror/clamp/
//     border with D3D9's transparent black border (opaque black/white also map; any other
//     border colour or MirrorOnce is an error). One mip level, unnormalised LOD 0. Cube
//     samplers filter each face on its own (VK_EXT_non_seamless_cube_map, clamped at the
//     edges; cube_faces_filtered_alone()).
//   * Constants: codegen::pack_uniforms with the pass's ConstantBanks and bump-env states.
// Nothing throws: every failure is returned as an ir::Result whose error is about "vulkan"
// (rule kDrawRule for a draw).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/ir/result_diagnostics.h"
#include "tierlift/pass/pass.h"

namespace tierlift::vulkan {

class TextureSet;

// What the Vulkan device draws beyond one colour target with programmable stages: up to four
// render targets (oC0..oC3; TextureSet::draw binds them), an 8-bit stencil buffer with
// D3D9's one-sided stencil state or a float depth buffer with its depth state (not both in one
// pass), and a pixel stage given as SPIR-V (a GLSL pass); a pass asking for more is refused
// (pass::check_supported). Device::draw has one host target and neither buffer, so there a
// pass with more targets, a stencil test or a depth state is refused as "not bound".
inline constexpr pass::Capabilities kCapabilities{
    .max_color_targets = 4, .depth_stencil = true, .spirv_pixel_stage = true};

struct DeviceOptions {
  // Enable VK_LAYER_KHRONOS_validation with a messenger that collects every warning and
  // error (tests require none).
  bool validation = false;
  // Case-insensitive substring of the physical device name. Empty: prefer a CPU device
  // (lavapipe, "llvmpipe"), else the first device.
  std::string gpu_filter;
  // With `validation`: also enable the layer's synchronization validation (hazards between
  // commands: missing or wrong barriers). Slower; tests of barrier-heavy paths use it.
  bool synchronization_validation = false;
  // On lavapipe, a point read of a resident RGBA8 texture samples it with the device's own
  // point sampler and decodes the value, instead of computing the texel index in the shader
  // and fetching (codegen::CodegenOptions::point_sampling_floors): lavapipe picks the
  // interpreter's texel, and samples 8-bit texels faster than it fetches them. Ignored on
  // any other device. false: the fetch everywhere (tests cover both paths on lavapipe).
  bool llvmpipe_point_sampling = true;
  // Read every RGBA8 level once when the device is created and decode in-place RGBA8 reads
  // with the cheapest decode exact for all of them (unorm8_reads()). false: the general
  // decode on every device, nothing read (tests cover both on lavapipe).
  bool choose_unorm8_decode = true;
  // Read RGBA8 texels in place and decode them: point reads with edge clamping fetch the
  // stored bytes, and the float copy every other read samples is drawn by such a read.
  // false: neither, every RGBA8 read samples a float copy converted from the stored bytes by
  // a compute shader, as on a device where no decode is exact (unorm8_reads() "float copy";
  // tests cover it on lavapipe).
  bool unorm8_in_place = true;
  // Filter each cube face on its own, clamped at its edges, as Direct3D 9 and the CPU device do
  // (NUMERICS.md T4), through VK_EXT_non_seamless_cube_map where the device offers it. A device
  // without it (or false here) filters across face edges, as Vulkan does by default, so a
  // LINEAR cube read would differ near the edges: such a draw is refused in words, and POINT
  // cube reads (clamped within the face either way) still draw. false: tests of the refusal.
  bool per_face_cubes = true;
  // Called once when the device is destroyed, after vkDestroyDevice and vkDestroyInstance,
  // with every message not cleared before. With `validation` these include the layer's
  // report of Vulkan objects created and never destroyed (it checks at both calls); tests
  // fail on any.
  std::function<void(const std::vector<std::string>&)> on_destroyed;
};

// The rules of Device::create's failures. Only kNoDeviceRule (the loader found no driver,
// or the driver enumerates no physical device) describes a machine without Vulkan, which a
// caller may treat as "cannot run here" (ir::failed_with(r, kNoDeviceRule)); every other
// failure (kDeviceRule) is a fault to report.
inline constexpr std::string_view kNoDeviceRule = "no-vulkan-device";
inline constexpr std::string_view kDeviceRule = "vulkan-device";
// The rule of a failed draw or TextureSet call (texture_set.h); its subject is "vulkan".
inline constexpr std::string_view kDrawRule = "vulkan";

class Device {
public:
  // The device, or why not (no Vulkan driver, no device matching the filter, validation
  // layer missing, any Vulkan call failing): one error about "vulkan" whose message names the
  // Debian package to install where one is missing.
  static ir::Result<std::unique_ptr<Device>> create(const DeviceOptions& options);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  std::string name() const;       // physical device name, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  uint32_t subtexel_bits() const; // VkPhysicalDeviceLimits::subTexelPrecisionBits
  // How a point read of a resident RGBA8 texture turns this device's value into k/255.0f,
  // chosen when the device was created by reading every level: "none" (the value already
  // is), "two multiplies" (lavapipe), "round and rebuild", or "float copy" (no decode is
  // exact here: such textures are read through their exact RGBA32F copy).
  std::string unorm8_reads() const;
  // Whether cube samplers filter each face on its own (VK_EXT_non_seamless_cube_map enabled,
  // DeviceOptions::per_face_cubes). false: LINEAR cube reads are refused (NUMERICS.md T4).
  bool cube_faces_filtered_alone() const;

  // Draws `pass` into `target`: its format selects the attachment format, its current
  // pixels are the destination blending reads; on success it holds the stored result and
  // the report its timings: setup_ms (compile, pipeline, resources, uploads of host images)
  // and draw_ms (submit to fence: float copies of sampled textures, the draw, readback);
  // the pixel counters stay 0. On failure the target is unchanged.
  ir::Result<pass::DrawReport> draw(const pass::Pass& pass, img::Image& target);

  // Stores the pipelines made so far in the user's cache directory for the next run
  // (pipeline_cache.h; also done when the device is destroyed). Failures are ignored.
  void save_pipeline_cache();

  // Validation messages collected so far (one line each: severity, id, text).
  std::vector<std::string> messages() const;
  void clear_messages();

  struct Impl;

private:
  friend class TextureSet; // draws with the same internals (texture_set.h)
  explicit Device(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace tierlift::vulkan
