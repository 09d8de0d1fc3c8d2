// Translation time per listing — parse, validate, codegen to SPIR-V, spirv-val — against the
// peer: glslang compiling a GLSL shader of the same work to SPIR-V, plus the same spirv-val,
// measured in the same run. bench/run.sh prints the ratios.
#include <benchmark/benchmark.h>

#include "glslang_peer.h"

#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
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
    auto r = assembly::parse_text(text, name);
    if (!r.program || !assembly::validate(*r.program, r.diags)) {
      state.SkipWithError("listing does not validate");
      return;
    }
    auto module = codegen::compile(*r.program, {}, r.diags); // runs spirv-val in-process
    if (!module) {
      state.SkipWithError("codegen failed");
      return;
    }
    benchmark::DoNotOptimize(module->words.data());
  }
}

void glslang_compile(benchmark::State& state, EShLanguage stage, const char* source) {
  glslang::InitializeProcess();
  for (auto _ : state) {
    std::vector<uint32_t> words = bench::glslang_to_spirv(stage, source);
    if (words.empty() || !codegen::validate(words)) {
      state.SkipWithError("glslang failed or spirv-val rejected its module");
      break;
    }
    benchmark::DoNotOptimize(words.data());
  }
  glslang::FinalizeProcess();
}

void BM_Translate_Listing1(benchmark::State& s) {
  translate(s, "listing1_blur8_coords.vsh");
}
void BM_Translate_Listing2(benchmark::State& s) {
  translate(s, "listing2_blur8_weighted_sum.psh");
}
void BM_Translate_Listing3(benchmark::State& s) {
  translate(s, "listing3_blur4_coords.vsh");
}
void BM_Translate_Listing4(benchmark::State& s) {
  translate(s, "listing4_blur4_weighted_sum.psh");
}
void BM_Peer_Glslang_Vertex8(benchmark::State& s) {
  glslang_compile(s, EShLangVertex, bench::kGlslVertex8);
}
void BM_Peer_Glslang_Fragment8(benchmark::State& s) {
  glslang_compile(s, EShLangFragment, bench::kGlslFragment8);
}

BENCHMARK(BM_Translate_Listing1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Translate_Listing2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Translate_Listing3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Translate_Listing4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Peer_Glslang_Vertex8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Peer_Glslang_Fragment8)->Unit(benchmark::kMicrosecond);

} // namespace

BENCHMARK_MAIN();
