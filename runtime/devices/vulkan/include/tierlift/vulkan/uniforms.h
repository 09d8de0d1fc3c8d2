// A stage's uniform block as the Vulkan device fills it, straight from the pass state: the
// constant bank (what D3D9 sets through SetVertexShaderConstantF/I/B and
// SetPixelShaderConstantF) and the texture stages' D3DTSS_BUMPENV* states. The layout is
// the one the code generator gave the module (std140, docs/spirv-mapping.md).
#pragma once

#include <cstdint>
#include <vector>

#include "tierlift/codegen/codegen.h"
#include "tierlift/pass/pass.h"

namespace tierlift::vulkan {

// The bytes of `module`'s uniform block as 32-bit words; empty when it has none. c# at
// 16·# (missing registers 0), i# and b# (vs_2_0) and the bump-environment states of
// `pass`'s texture stages (ps_1_x) after the floats.
std::vector<uint32_t> pack_uniforms(const codegen::ShaderModule& module,
                                    const pass::ConstantBank& bank, const pass::Pass& pass);

} // namespace tierlift::vulkan
