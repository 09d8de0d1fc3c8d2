// The stand-in programs a pass without a vertex or pixel program runs on the Vulkan device
// (see device.h): built as IR, so they go through the same code generator as any listing.
#pragma once

#include <memory>

#include "tierlift/ir/program.h"

namespace tierlift::vulkan {

// Vertex inputs of the pass-through vertex program: v0 position, v1/v2 colours, v3+N tN.
inline constexpr uint32_t kPassPosition = 0, kPassColor = 1, kPassTex = 3;

// vs_2_0: mov oPos, v0; mov oD0, v1; mov oD1, v2; mov oTN, v(3+N) for N = 0..7.
std::shared_ptr<const ir::Program> passthrough_vertex_program();
// ps_2_0: dcl v0; mov oC0, v0.
std::shared_ptr<const ir::Program> passthrough_pixel_program();
// ps_2_0: dcl t0; dcl_2d s0; texld r0, t0, s0; mov oC0, r0.
std::shared_ptr<const ir::Program> texel_copy_pixel_program();

} // namespace tierlift::vulkan
