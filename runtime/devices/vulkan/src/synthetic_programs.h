// The stand-in programs a pass without a vertex or pixel program runs on the Vulkan device
// (see device.h): built as IR, so they go through the same code generator as any listing.
#pragma once

#include <memory>

#include "tierlift/ir/program.h"
#include "tierlift/pass/pass.h"

namespace tierlift::vulkan {

// Vertex inputs of the pass-through vertex program: v0 position, v1/v2 colours, v3+N tN.
inline constexpr uint32_t kPassPosition = 0, kPassColor = 1, kPassTex = 3;

// vs_2_0: mov oPos, v0; mov oD0, v1; mov oD1, v2; mov oTN, v(3+N) for N = 0..7.
std::shared_ptr<const ir::Program> passthrough_vertex_program();
// ps_2_0: dcl v0; mov oC0, v0.
std::shared_ptr<const ir::Program> passthrough_pixel_program();
// ps_2_0: dcl t0; dcl_2d s0; texld r0, t0, s0; mov oC0, r0.
std::shared_ptr<const ir::Program> texel_copy_pixel_program();

// The pass that copies texel (i, j) of its stage-0 texture to pixel (i, j) of a target of
// `width` × `height` texels: the full-screen quad, whose uv at pixel i is i/width (D3D9
// centres), plus half a texel, read by texel_copy_pixel_program through a POINT sampler with
// CLAMP addressing. An RGBA8 texture is thus read in place (its stored bytes, decoded).
pass::Pass texel_copy_pass(uint32_t width, uint32_t height);

} // namespace tierlift::vulkan
