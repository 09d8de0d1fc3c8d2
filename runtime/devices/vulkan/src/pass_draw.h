// Internal: the one draw both public paths share. Device::draw (host images in, host image
// out) and TextureSet::draw (textures that stay on the device) differ only in where the
// sampled textures and the target come from; programs, geometry, descriptors, pipeline,
// barriers and the render pass are this file's.
//
// A draw is made in two steps: prepare_draw creates every object the draw needs (SPIR-V,
// pipeline, descriptor set, framebuffer, vertex and uniform buffers) and record_draw records
// it into a command buffer. TextureSet keeps prepared draws (draw_cache.h), so a pass drawn
// again — the next frame of an effect — records its commands and nothing else.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "resident.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/pass/pass.h"
#include "tierlift/vulkan/texture_set.h"

namespace tierlift::vulkan {

class ProgramReuse;

struct DrawTextures {
  // The texture each sampler reads, by slot (StageTextures: the vertex stage's sN at
  // kMaxSamplers + N). nullptr: the pass's own host image for that sampler (uploaded as
  // R32G32B32A32_SFLOAT for this draw only), or the unbound texture (0, 0, 0, 1) when it has
  // none.
  std::array<Resident*, pass::kSamplerSlots> stages{};
  Resident* target = nullptr;
  // Render targets 1..3 (oC1..oC3), for a pass with pass.color_targets > 1, and the stencil
  // buffer (Resident::stencil) for a pass with a stencil test. Resident textures only.
  std::array<Resident*, 3> more_targets{};
  Resident* stencil = nullptr;
  Resident* depth = nullptr; // the depth buffer (Resident::depth) for a pass with a depth state
  // Device::draw: the target's starting contents, uploaded before the draw (setup), and
  // where the result is read back to after it (in the same submit as the draw). Must have
  // the target's size and format. nullptr: the target stays on the device.
  img::Image* host_target = nullptr;
  // Set: the pixel module records this pixel (codegen::TracePixel) into a storage buffer,
  // which draw_pass reads into trace_out. Such a draw is never cached.
  const codegen::TracePixel* trace = nullptr;
  ShaderTrace* trace_out = nullptr;
  // Set (TextureSet::set_reuse_programs): the programs are compiled for any constants and
  // the compiled modules and pipeline are found again there (program_reuse.h).
  ProgramReuse* reuse = nullptr;
};

// Everything one draw of one pass needs, owned by `objects` (destroyed with the entry).
// Host textures of the pass (and the unbound texture) are uploaded by prepare_draw.
struct PreparedDraw {
  Cleanup objects;
  std::vector<std::unique_ptr<Resident>> host_textures;
  std::array<Resident*, pass::kSamplerSlots> sampled{}; // by slot: those the programs read
  std::array<bool, pass::kSamplerSlots> fetched{};      // those reading RGBA8 bytes in place
  Resident* target = nullptr;
  std::array<Resident*, 3> more_targets{}; // as in DrawTextures, those the pass draws into
  Resident* stencil = nullptr; // the depth/stencil attachment: the stencil or the depth buffer
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  Buffer vertices, indices;
  uint32_t index_count = 0;
  VkViewport viewport{};
  VkRect2D scissor{};
  bool visible = false; // something to draw (the render pass still runs: loadOp LOAD)
  // DrawTextures::trace: the buffer the module records into (zeroed) and what it records.
  Buffer trace;
  std::optional<codegen::TraceInfo> trace_info;
};

// Creates what drawing `pass` into textures.target needs (host_target is ignored here).
// On failure (draw_failure) `out` holds nothing that outlives it.
ir::Status prepare_draw(Device::Impl& d, const pass::Pass& pass, const DrawTextures& textures,
                        PreparedDraw& out);

// Records the draw: sampled textures made current and readable, the targets made the colour
// attachments (and the stencil buffer the depth/stencil one), the render pass with the draw.
// Advances the textures' tracked layouts.
void record_draw(VkCommandBuffer cb, const Device::Impl& d, PreparedDraw& draw);

// Records `draw` alone, submits it and waits. On failure the textures' tracked layouts are
// restored (nothing changed on the device).
ir::Status submit_draw(Device::Impl& d, PreparedDraw& draw);

// Draws `pass` into textures.target now (prepare, submit, wait); the report holds setup_ms
// and draw_ms. On failure (draw_failure) nothing was submitted that changes any texture, and
// host_target is unchanged.
ir::Result<pass::DrawReport> draw_pass(Device::Impl& d, const pass::Pass& pass,
                                       const DrawTextures& textures);

} // namespace tierlift::vulkan
