// Front-end throughput: parse+validate, assemble and disassemble every listing we hold
// (bytes/s and listings/s), and the peer — SPIRV-Tools' text assembler on the SPIR-V text
// of an equivalent 8-tap GLSL blur compiled by glslang — measured in the same run.
// bench/run.sh prints the ratios.
#include <benchmark/benchmark.h>

#include <spirv-tools/libspirv.hpp>

#include "bench_inputs.h"
#include "glslang_peer.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"

using namespace tierlift;

namespace {

void BM_ParseValidate(benchmark::State& state) {
  const auto& listings = bench::all_listings();
  for (auto _ : state) {
    for (const auto& l : listings) {
      auto r = assembly::parse_text(l.text, l.name);
      if (r.program) benchmark::DoNotOptimize(assembly::validate(*r.program, r.diags));
    }
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bench::total_bytes(listings)));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(listings.size()));
}
BENCHMARK(BM_ParseValidate);

std::vector<ir::Program> parsed_listings() {
  std::vector<ir::Program> out;
  for (const auto& l : bench::all_listings())
    if (auto r = assembly::parse_text(l.text, l.name); r.program)
      out.push_back(std::move(*r.program));
  return out;
}

void BM_ParseValidateAssemble(benchmark::State& state) {
  const auto& listings = bench::all_listings();
  for (auto _ : state) {
    for (const auto& l : listings) {
      auto r = assembly::parse_text(l.text, l.name);
      if (r.program && assembly::validate(*r.program, r.diags))
        benchmark::DoNotOptimize(assembly::assemble(*r.program));
    }
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bench::total_bytes(listings)));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(listings.size()));
}
BENCHMARK(BM_ParseValidateAssemble);

void BM_AssembleOnly(benchmark::State& state) {
  auto programs = parsed_listings();
  for (auto _ : state)
    for (const auto& p : programs) benchmark::DoNotOptimize(assembly::assemble(p));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(programs.size()));
}
BENCHMARK(BM_AssembleOnly);

void BM_Disassemble(benchmark::State& state) {
  std::vector<std::vector<uint32_t>> streams;
  size_t bytes = 0;
  for (const auto& p : parsed_listings()) {
    streams.push_back(assembly::assemble(p));
    bytes += streams.back().size() * 4;
  }
  for (auto _ : state)
    for (const auto& t : streams) {
      ir::DiagnosticSink d;
      benchmark::DoNotOptimize(assembly::disassemble(t, d));
    }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(bytes));
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(streams.size()));
}
BENCHMARK(BM_Disassemble);

// The peer's input: SPIR-V assembly text of the same 8-tap blur as Listing 2.
std::string peer_spirv_text() {
  glslang::InitializeProcess();
  std::vector<uint32_t> words = bench::glslang_to_spirv(EShLangFragment, bench::kGlslFragment8);
  glslang::FinalizeProcess();
  std::string text;
  if (!words.empty()) {
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    tools.Disassemble(words, &text, SPV_BINARY_TO_TEXT_OPTION_NONE);
  }
  return text;
}

void BM_Peer_SpirvToolsAssemble(benchmark::State& state) {
  std::string text = peer_spirv_text();
  if (text.empty()) {
    state.SkipWithError("glslang could not build the peer's input");
    return;
  }
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
  for (auto _ : state) {
    std::vector<uint32_t> words;
    benchmark::DoNotOptimize(tools.Assemble(text, &words));
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(text.size()));
  state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_Peer_SpirvToolsAssemble);

} // namespace

BENCHMARK_MAIN();
