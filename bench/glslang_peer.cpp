#include "glslang_peer.h"

#include "tierlift/glsl/glsl.h"

namespace tierlift::bench {

const char* const kGlslVertex8 = R"(#version 450
layout(location = 0) in vec4 pos;
layout(location = 3) in vec4 uv;
layout(set = 0, binding = 0, std140) uniform VS { vec4 c[8]; };
layout(location = 0) out vec4 t[8];
void main() {
  gl_Position = pos;
  for (int k = 0; k < 8; ++k) t[k] = uv + c[k];
})";

const char* const kGlslFragment8 = R"(#version 450
layout(location = 0) in vec4 t[8];
layout(set = 0, binding = 2) uniform sampler2D s0;
layout(set = 0, binding = 1, std140) uniform PS { vec4 c[8]; };
layout(location = 0) out vec4 oC0;
void main() {
  vec4 r0 = texture(s0, t[0].xy) * c[0];
  for (int k = 1; k < 8; ++k) r0 += texture(s0, t[k].xy) * c[k];
  oC0 = r0;
})";

std::vector<uint32_t> glslang_to_spirv(EShLanguage stage, const char* source) {
  // The library's plain Vulkan compile (tierlift/glsl), so the peer and the GLSL pass kind
  // share one glslang driver.
  return glsl::compile_vulkan_glsl(
      stage == EShLangVertex ? glsl::Stage::Vertex : glsl::Stage::Fragment, source);
}

} // namespace tierlift::bench
