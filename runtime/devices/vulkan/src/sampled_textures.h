// Internal: the textures one draw samples (prepare_draw's step between compiling the programs
// and binding the descriptors). A stage reads its resident texture in place or through its
// float shadow; without one, the pass's host image (or the unbound texture, (0, 0, 0, 1) as in
// D3D9) is uploaded for this draw, and a cube or volume sampler always reads the binding's
// host layers, uploaded likewise. What is uploaded belongs to `out` (PreparedDraw).
#pragma once

#include "bindings.h"
#include "pass_draw.h"

namespace tierlift::vulkan {

// Fills out.sampled, out.fetched and `images` for every sampler of the pixel program.
ir::Status bind_sampled(Device::Impl& d, const pass::Pass& pass, const DrawTextures& textures,
                        const codegen::CompiledPair& pair, PreparedDraw& out,
                        SampledImages& images);

} // namespace tierlift::vulkan
