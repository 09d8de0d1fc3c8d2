// Translation time per listing — parse, validate, codegen to SPIR-V, spirv-val — against the
// peer: glslang compiling a GLSL shader of the same work to SPIR-V, plus the same spirv-val,
// measured in the same run. bench/run.sh prints the ratios.
#include <benchmark/benchmark.h>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "tierlift/asm/parser.h"
#include "tierlift/asm/validator.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/listings/embedded.h"

using namespace tierlift;

namespace {

std::string article(const char* name) {
  auto text = listings::find_embedded(std::string("gpugems21/") + name);
  return text ? std::string(*text) : std::string();
}

void translate(benchmark::State& state, const char* name) {
  std::string text = article(name);
  for (auto _ : state) {
    auto r = as::parse_text(text, name);
    if (!r.program || !as::validate(*r.program, r.diags)) {
      state.SkipWithError("listing does not validate");
      return;
    }
    auto module = codegen::compile(*r.program, {}, r.diags);  // runs spirv-val in-process
    if (!module) {
      state.SkipWithError("codegen failed");
      return;
    }
    benchmark::DoNotOptimize(module->words.data());
  }
}

// GLSL doing the work of Listing 1 (8 offset texcoords) and Listing 2 (8 weighted taps).
const char* kGlslVertex8 = R"(#version 450
layout(location = 0) in vec4 pos;
layout(location = 3) in vec4 uv;
layout(set = 0, binding = 0, std140) uniform VS { vec4 c[8]; };
layout(location = 0) out vec4 t[8];
void main() {
  gl_Position = pos;
  for (int k = 0; k < 8; ++k) t[k] = uv + c[k];
})";
const char* kGlslFragment8 = R"(#version 450
layout(location = 0) in vec4 t[8];
layout(set = 0, binding = 2) uniform sampler2D s0;
layout(set = 0, binding = 1, std140) uniform PS { vec4 c[8]; };
layout(location = 0) out vec4 oC0;
void main() {
  vec4 r0 = texture(s0, t[0].xy) * c[0];
  for (int k = 1; k < 8; ++k) r0 += texture(s0, t[k].xy) * c[k];
  oC0 = r0;
})";

void glslang_compile(benchmark::State& state, EShLanguage stage, const char* source) {
  glslang::InitializeProcess();
  for (auto _ : state) {
    glslang::TShader shader(stage);
    shader.setStrings(&source, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    if (!shader.parse(GetDefaultResources(), 100, false, EShMsgDefault)) {
      state.SkipWithError("glslang parse failed");
      break;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(EShMsgDefault)) {
      state.SkipWithError("glslang link failed");
      break;
    }
    std::vector<uint32_t> words;
    glslang::GlslangToSpv(*program.getIntermediate(stage), words);
    std::string error;
    if (!codegen::validate(words, &error)) {
      state.SkipWithError("spirv-val rejected glslang's module");
      break;
    }
    benchmark::DoNotOptimize(words.data());
  }
  glslang::FinalizeProcess();
}

void BM_Translate_Listing1(benchmark::State& s) { translate(s, "listing1_blur8_coords.vsh"); }
void BM_Translate_Listing2(benchmark::State& s) {
  translate(s, "listing2_blur8_weighted_sum.psh");
}
void BM_Translate_Listing3(benchmark::State& s) { translate(s, "listing3_blur4_coords.vsh"); }
void BM_Translate_Listing4(benchmark::State& s) {
  translate(s, "listing4_blur4_weighted_sum.psh");
}
void BM_Peer_Glslang_Vertex8(benchmark::State& s) {
  glslang_compile(s, EShLangVertex, kGlslVertex8);
}
void BM_Peer_Glslang_Fragment8(benchmark::State& s) {
  glslang_compile(s, EShLangFragment, kGlslFragment8);
}

BENCHMARK(BM_Translate_Listing1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Translate_Listing2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Translate_Listing3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Translate_Listing4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Peer_Glslang_Vertex8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Peer_Glslang_Fragment8)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
