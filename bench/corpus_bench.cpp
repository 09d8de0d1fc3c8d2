// `tierlift test` throughput: cases per second over our listings and tests/corpus,
// check-only and the full lift, in process and with 1 and 2 worker
// processes; and the floor it is held against, measured in the same run: the time lavapipe
// itself spends in vkCreateGraphicsPipelines for the pipelines of the same cases
// (vulkan::pipeline_creation_ms). bench/run.sh prints the ratios.
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include <benchmark/benchmark.h>

#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/runner.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/vulkan/pipeline_stats.h"
#include "tierlift/vulkan/process_device.h"

namespace {

using namespace tierlift;

const std::vector<corpus::Case>& cases() {
  static const std::vector<corpus::Case> all = [] {
    const std::vector<std::string> roots{std::string(TIERLIFT_SOURCE_DIR) + "/listings",
                                         std::string(TIERLIFT_SOURCE_DIR) + "/tests/corpus"};
    auto found = corpus::discover(roots);
    return found ? *found : std::vector<corpus::Case>{};
  }();
  return all;
}

// `tierlift test --generate 200 --profile ps_2_0 --seed 1`'s cases, as the command makes them
// (2D samplers, one colour output: what the differential run binds).
const std::vector<corpus::Case>& generated_cases() {
  static const std::vector<corpus::Case> all = *corpus::generated_cases("ps_2_0", 1, 200);
  return all;
}

// In process: the stages alone, no worker, no pipes. The full lift also reports the floor.
void BM_Corpus_InProcess(benchmark::State& state, bool check_only, bool per_set = false,
                         bool generated = false) {
  const std::vector<corpus::Case>& run = generated ? generated_cases() : cases();
  corpus::StageOptions o;
  o.check_only = check_only;
  o.one_pipeline_per_case = !per_set;
  if (!check_only) {
    ir::Result<vulkan::Device*> d = vulkan::process_device({});
    if (!d) {
      state.SkipWithError(d.message().c_str());
      return;
    }
    o.device = *d;
  }
  double floor_ms = 0, floor_cpu_ms = 0;
  long pipelines = 0;
  size_t n = 0;
  for (auto _ : state) {
    const double before = vulkan::pipeline_creation_ms();
    const long made_before = vulkan::pipeline_creations();
    const double cpu_before = vulkan::pipeline_creation_cpu_ms();
    for (const corpus::Case& c : run) benchmark::DoNotOptimize(corpus::run_case(c, o));
    floor_ms += vulkan::pipeline_creation_ms() - before;
    pipelines += vulkan::pipeline_creations() - made_before;
    floor_cpu_ms += vulkan::pipeline_creation_cpu_ms() - cpu_before;
    n += run.size();
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["cases"] = static_cast<double>(run.size());
  state.counters["floor_ms_per_case"] = n ? floor_ms / static_cast<double>(n) : 0;
  state.counters["floor_cpu_ms_per_case"] = n ? floor_cpu_ms / static_cast<double>(n) : 0;
  state.counters["pipelines_per_case"] =
      n ? static_cast<double>(pipelines) / static_cast<double>(n) : 0;
}

// Worker processes (`tierlift test --worker`), as a run uses them: pipes, process start,
// one Vulkan device per worker.
void BM_Corpus_Workers(benchmark::State& state, bool check_only) {
  const auto out = std::filesystem::temp_directory_path() /
                   ("tierlift_bench_corpus_" + std::to_string(::getpid()));
  corpus::RunOptions o;
  o.worker_argv = {TIERLIFT_CLI_PATH, "test", "--worker"};
  if (check_only) o.worker_argv.push_back("--check-only");
  o.jobs = static_cast<unsigned>(state.range(0));
  o.out_dir = out.string();
  o.rerun = false;
  size_t n = 0;
  for (auto _ : state) {
    auto r = corpus::run_corpus(cases(), o);
    if (!r) state.SkipWithError(r.message().c_str());
    n += cases().size();
  }
  std::filesystem::remove_all(out);
  state.SetItemsProcessed(static_cast<int64_t>(n));
}

} // namespace

BENCHMARK_CAPTURE(BM_Corpus_InProcess, CheckOnly, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Corpus_InProcess, FullLift, false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
// The same on 200 generated ps_2_0 programs (`tierlift test --generate 200 --profile ps_2_0
// --seed 1`).
BENCHMARK_CAPTURE(BM_Corpus_InProcess, FullLiftGenerated, false, false, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
// The same with a module and pipeline per input set (the differential run before
// StageOptions::one_pipeline_per_case), for the ratio in the same run.
BENCHMARK_CAPTURE(BM_Corpus_InProcess, FullLiftPipelinePerSet, false, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_Corpus_Workers, CheckOnly, true)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_Corpus_Workers, FullLift, false)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
// In process as in a worker (corpus::worker_environment): lavapipe rasterises on the calling
// thread unless LP_NUM_THREADS says otherwise.
int main(int argc, char** argv) {
  ::setenv("LP_NUM_THREADS", "0", 0);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
