// GLSL fragment shaders as passes of an effect graph. The seed's blur (and a user's own pass)
// is legacy desktop GLSL: gl_FragColor, texture2D, `varying`, loose `uniform sampler2D`. It
// reaches Vulkan by a mechanical mapping: glslang (the library, in-process) reads it as GLSL
// 4.50 for Vulkan with a preamble of #defines (texture2D → texture, varying → in,
// gl_FragColor → an output at location 0); each `varying TYPE NAME;` line is blanked and
// NAME becomes the leading components of a vec4 input at locations 0, 1, … in order (the
// vertex stage writes vec4s); samplers get the bindings tierlift's own SPIR-V uses (set 0,
// binding 2 + stage). Lines and columns stay the user's. docs/glsl.md says why this and not
// glslang's OpenGL front end. The SPIR-V then passes spirv-val with the Vulkan 1.1 rules, as
// codegen's does.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/result.h"

namespace tierlift::glsl {

// The first descriptor binding of a sampler: binding 2 + stage, as docs/spirv-mapping.md
// gives tierlift's own pixel stages (0 and 1 are the constant blocks).
inline constexpr uint32_t kFirstSamplerBinding = 2;

// What the preamble defines, ahead of the user's first line (it does not count in line
// numbers): the documented rewrite, in full.
extern const char* const kLegacyPreamble;

struct Sampler {
  std::string name;   // the uniform's name in the source
  uint32_t stage = 0; // s#: descriptor binding − kFirstSamplerBinding
};

// An input the shader reads (a legacy `varying`, or a 4.50 `in`): the interpolated vec4 the
// vertex stage writes at that location (oT#, # = location).
struct Input {
  std::string name;
  uint32_t location = 0;
};

struct FragmentShader {
  std::string file;              // as diagnostics name it
  std::vector<uint32_t> spirv;   // validated by spirv-val (Vulkan 1.1)
  std::vector<Sampler> samplers; // the samplers the shader reads, by stage
  std::vector<Input> inputs;     // by location
};

// The shader, or one error: rule kGlslRule (the source does not compile, or is refused) or
// kIoRule (the file could not be read: exit 2, not 1). Its message is already rendered,
// '\n'-ended: "file:line:col: error: message", the source line and a caret (glslang's own
// messages, positioned; the column is that of the token glslang quotes, 1 when it quotes
// none), kept verbatim (ir::fail_rendered); the subject is the file name.
using CompileResult = ir::Result<FragmentShader>;
inline constexpr std::string_view kGlslRule = "glsl";
inline constexpr std::string_view kIoRule = "io";

// Compiles legacy (or 4.50 Vulkan) GLSL fragment source. `file_name` is what diagnostics
// show. A `#version` line of the source is accepted and overridden (4.50 core): the
// preamble's #defines need 4.50. Non-sampler uniforms are refused with a positioned error
// (a graph pass has no values for them).
CompileResult compile_fragment(std::string_view source, const std::string& file_name);
// The same for a file (read within io::kListingCap).
CompileResult compile_fragment_file(const std::string& path);

enum class Stage { Vertex, Fragment };
// A plain compile of Vulkan GLSL (#version 450, every location and binding explicit) to
// SPIR-V 1.3 for Vulkan 1.1 — the peer the benchmarks measure tierlift's translation against.
// Empty on failure (`*log`, when given, gets glslang's messages).
std::vector<uint32_t> compile_vulkan_glsl(Stage stage, std::string_view source,
                                          std::string* log = nullptr);

} // namespace tierlift::glsl
