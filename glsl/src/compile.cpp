// glslang in-process: the legacy preamble, automatic locations and bindings, reflection of
// the samplers, SPIR-V generation and spirv-val (glsl.h).
#include <algorithm>
#include <mutex>
#include <regex>

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "glslang_messages.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/glsl/glsl.h"
#include "tierlift/io/bounded_read.h"

namespace tierlift::glsl {

const char* const kLegacyPreamble = "#define texture2D texture\n"
                                    "#define varying in\n"
                                    "#define gl_FragColor tierlift_FragColor\n"
                                    "layout(location = 0) out vec4 tierlift_FragColor;\n";

namespace {

// glslang's process-wide tables: made once, kept for the life of the process (reachable
// from glslang's globals, so not a leak).
void init_glslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

constexpr auto kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

void set_vulkan_env(glslang::TShader& shader, EShLanguage stage) {
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
}

// The one textual rewrite (docs/glsl.md): a line `varying TYPE NAME;` (TYPE float or vec2..4)
// is blanked — spaces of the same length, so lines and columns stay the user's — and the
// preamble declares a vec4 at the next location with NAME a macro for its leading
// components. The vertex stage writes vec4 texture coordinates (tierlift's varyings are
// vec4), and a vec2 input at a vec4 output's location is an interface mismatch Vulkan's
// validation reports; reading .xy of a vec4 input is the same value without it.
std::string rewrite_varyings(std::string& text) {
  static const std::regex decl(
      R"(^([ \t]*)varying[ \t]+(float|vec2|vec3|vec4)[ \t]+([A-Za-z_][A-Za-z0-9_]*)[ \t]*;)");
  static const char* const kSwizzle[] = {"x", "xy", "xyz", "xyzw"};
  std::string preamble;
  uint32_t location = 0;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::smatch m;
    const std::string line = text.substr(start, end - start);
    if (std::regex_search(line, m, decl)) {
      const std::string type = m[2].str();
      const size_t n = type == "float" ? 1 : static_cast<size_t>(type.back() - '0');
      preamble += fmt::format("layout(location = {0}) in vec4 tierlift_varying{0};\n"
                              "#define {1} tierlift_varying{0}.{2}\n",
                              location, m[3].str(), kSwizzle[n - 1]);
      ++location;
      text.replace(start, static_cast<size_t>(m.length(0)), static_cast<size_t>(m.length(0)), ' ');
    }
    start = end + 1;
  }
  return preamble;
}

} // namespace

CompileResult compile_fragment(std::string_view source, const std::string& file_name) {
  init_glslang();
  const std::string text(source); // what diagnostics show
  std::string rewritten = text;
  // The output at location 0 is declared only for a source that writes gl_FragColor: a
  // Vulkan source declares its own, and a second one at location 0 would overlap it.
  std::string legacy = kLegacyPreamble;
  if (text.find("gl_FragColor") == std::string::npos)
    legacy.erase(legacy.find("layout(location = 0) out"));
  const std::string preamble = legacy + rewrite_varyings(rewritten);
  const char* strings[] = {rewritten.c_str()};
  const int lengths[] = {static_cast<int>(rewritten.size())};
  const char* names[] = {file_name.c_str()};
  glslang::TShader shader(EShLangFragment);
  shader.setStringsWithLengthsAndNames(strings, lengths, names, 1);
  shader.setPreamble(preamble.c_str());
  set_vulkan_env(shader, EShLangFragment);
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  // A combined sampler2D counts as a texture to glslang's binding map; both kinds start at 2.
  shader.setShiftBinding(glslang::EResTexture, kFirstSamplerBinding);
  shader.setShiftBinding(glslang::EResSampler, kFirstSamplerBinding);
  // 4.50 core whatever the source's #version says: the preamble's `layout` needs it, and the
  // legacy names it replaces are what a 1.10 source would use.
  if (!shader.parse(GetDefaultResources(), 450, ECoreProfile, true, false, kMessages)) {
    return ir::fail_rendered(file_name, std::string(kGlslRule),
                             render_glslang_log(shader.getInfoLog(), text, file_name));
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(kMessages) || !program.mapIO()) {
    return ir::fail_rendered(file_name, std::string(kGlslRule),
                             render_glslang_log(program.getInfoLog(), text, file_name));
  }
  program.buildReflection(EShReflectionIntermediateIO); // a fragment stage alone has inputs
  FragmentShader fs;
  fs.file = file_name;
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    const glslang::TType* type = u.getType();
    if (!type || type->getBasicType() != glslang::EbtSampler) {
      return ir::fail_rendered(
          file_name, std::string(kGlslRule),
          render_at_name(u.name,
                         fmt::format("uniform '{}': a GLSL pass takes sampler uniforms "
                                     "only (its textures); put constants in the source",
                                     u.name),
                         text, file_name));
    }
    const int binding = u.getBinding();
    if (binding < static_cast<int>(kFirstSamplerBinding) ||
        binding >= static_cast<int>(kFirstSamplerBinding + 16)) {
      return ir::fail_rendered(
          file_name, std::string(kGlslRule),
          render_at_name(
              u.name,
              fmt::format(
                  "sampler '{}' has binding {}: tierlift binds sampler s# at {} + # (# < 16)",
                  u.name, binding, kFirstSamplerBinding),
              text, file_name));
    }
    fs.samplers.push_back({u.name, static_cast<uint32_t>(binding) - kFirstSamplerBinding});
  }
  std::sort(fs.samplers.begin(), fs.samplers.end(),
            [](const Sampler& a, const Sampler& b) { return a.stage < b.stage; });
  for (int i = 0; i < program.getNumPipeInputs(); ++i) {
    const glslang::TObjectReflection& in = program.getPipeInput(i);
    const glslang::TType* type = in.getType();
    if (!type || !type->getQualifier().hasLocation() || in.name.starts_with("gl_")) continue;
    // A rewritten varying is known by its name in the user's source (the preamble's
    // "#define NAME tierlift_varyingK").
    std::string name = in.name;
    std::smatch m;
    const std::regex define("#define ([A-Za-z_][A-Za-z0-9_]*) " + in.name + "\\.");
    if (std::regex_search(preamble, m, define)) name = m[1];
    fs.inputs.push_back({name, type->getQualifier().layoutLocation});
  }
  std::sort(fs.inputs.begin(), fs.inputs.end(),
            [](const Input& a, const Input& b) { return a.location < b.location; });
  glslang::SpvOptions spv;
  spv.validate = false; // spirv-val below, with the rules tierlift's own modules meet
  glslang::GlslangToSpv(*program.getIntermediate(EShLangFragment), fs.spirv, &spv);
  if (ir::Status valid = codegen::validate(fs.spirv); !valid) {
    return ir::fail_rendered(file_name, std::string(kGlslRule),
                             fmt::format("{}: error: spirv-val rejects glslang's SPIR-V: {}\n",
                                         file_name, valid.message()));
  }
  return fs;
}

CompileResult compile_fragment_file(const std::string& path) {
  ir::Result<std::string> text = io::read_bounded(path, io::kListingCap);
  if (!text) {
    // "PATH: why" → "PATH: error: why", the form of the other diagnostics.
    std::string why = text.message();
    if (why.starts_with(path + ": ")) why.erase(0, path.size() + 2);
    return ir::fail_rendered(path, std::string(kIoRule), fmt::format("{}: error: {}\n", path, why));
  }
  if (text->starts_with("\xEF\xBB\xBF")) text->erase(0, 3); // a byte-order mark is no text
  return compile_fragment(*text, path);
}

std::vector<uint32_t> compile_vulkan_glsl(Stage stage, std::string_view source, std::string* log) {
  init_glslang();
  const EShLanguage lang = stage == Stage::Vertex ? EShLangVertex : EShLangFragment;
  const std::string text(source);
  const char* strings[] = {text.c_str()};
  glslang::TShader shader(lang);
  shader.setStrings(strings, 1);
  set_vulkan_env(shader, lang);
  if (!shader.parse(GetDefaultResources(), 100, false, EShMsgDefault)) {
    if (log) *log = shader.getInfoLog();
    return {};
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(EShMsgDefault)) {
    if (log) *log = program.getInfoLog();
    return {};
  }
  std::vector<uint32_t> words;
  glslang::GlslangToSpv(*program.getIntermediate(lang), words);
  return words;
}

} // namespace tierlift::glsl
