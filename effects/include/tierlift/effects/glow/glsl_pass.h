// A user's GLSL fragment shader as a one-pass graph (`tierlift glsl FILE -o OUT`): the shader
// drawn over a full-screen quad into texture "final", every sampler it declares reading the
// input texture "scene". The Vulkan device draws it; the interpreter has no GLSL and the
// analytic device no model of an arbitrary shader, so only the Vulkan device runs this graph
// (the blur of docs/glsl.md is the effect checked three ways).
// The vertex stage is glow/quad4_coords.vsh with all four texture coordinates set to the
// quad uv plus half a texel (texel centres, as OpenGL puts its pixel centres), so inputs at
// locations 0..3 read that coordinate. The pass's ps_2_0 twin, which gives the Vulkan device
// the interface (samplers, inputs), is generated: it declares t0..t3 and every stage the
// GLSL samples.
#pragma once

#include "tierlift/effects/glow/glow.h"
#include "tierlift/glsl/glsl.h"

namespace tierlift::effects {

// The texture coordinates the quad's vertex stage writes (locations 0..3).
inline constexpr uint32_t kGlslPassInputs = 4;

// The graph at width × height in `format`, sampling with `filter` and clamp addressing.
// Refused (in `error`, naming the shader's file): an input at location 4 or above.
PlanResult build_glsl_pass(const glsl::FragmentShader& shader, uint32_t width, uint32_t height,
                           img::Format format, pass::Filter filter);

} // namespace tierlift::effects
