// `tierlift test` throughput: cases per second over our listings and tests/corpus and over
// generated ps_2_0 programs, check-only and the full lift, in process and with 1 and 2
// worker processes; and the floors the full lift is held against, measured in the same run
// on the same SPIR-V:
//   1. lavapipe's own vkCreateGraphicsPipelines time for the case's pipelines
//      (vulkan::pipeline_creation_ms);
//   2. that plus the first draw of one pixel with each pipeline (vulkan::draw_submission_ms):
//      llvmpipe compiles the shaders to machine code at the first draw, not at pipeline
//      creation, so floor 1 leaves out the driver's largest piece of work.
// bench/run.sh prints the ratios.
//
// Every benchmark runs its cases once before it measures (a warm-up): the first run of a
// program on a machine also pays llvmpipe's compile without its on-disk shader cache, and
// the first run of a process its pages; measured runs are warm alike.
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>

#include <benchmark/benchmark.h>

#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/runner.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/vulkan/pipeline_stats.h"
#include "tierlift/vulkan/process_device.h"

namespace {

using namespace tierlift;
using Clock = std::chrono::steady_clock;

const std::vector<corpus::Case>& our_cases() {
  static const std::vector<corpus::Case> all = [] {
    const std::vector<std::string> roots{std::string(TIERLIFT_SOURCE_DIR) + "/listings",
                                         std::string(TIERLIFT_SOURCE_DIR) + "/tests/corpus"};
    auto found = corpus::discover(roots);
    return found ? *found : std::vector<corpus::Case>{};
  }();
  return all;
}

// `tierlift test --generate N --profile ps_2_0 --seed 1`'s cases, as the command makes them
// (2D samplers, one colour output: what the differential run binds).
const std::vector<corpus::Case>& generated_cases(size_t n) {
  static const std::vector<corpus::Case> all = *corpus::generated_cases("ps_2_0", 1, 2000);
  static std::vector<corpus::Case> first_200(all.begin(), all.begin() + 200);
  return n == 200 ? first_200 : all;
}

enum class Corpus { Ours, Generated200, Generated2000 };
const std::vector<corpus::Case>& cases_of(Corpus c) {
  return c == Corpus::Ours ? our_cases() : generated_cases(c == Corpus::Generated200 ? 200 : 2000);
}

double process_cpu_ms() {
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// The driver's time for one stretch of work: pipeline creations and draw submissions.
struct DriverTime {
  double create_ms = 0, create_cpu_ms = 0, draw_ms = 0, draw_cpu_ms = 0;
  long pipelines = 0, submits = 0;
  static DriverTime now() {
    return {vulkan::pipeline_creation_ms(), vulkan::pipeline_creation_cpu_ms(),
            vulkan::draw_submission_ms(),   vulkan::draw_submission_cpu_ms(),
            vulkan::pipeline_creations(),   vulkan::queue_submissions()};
  }
  DriverTime since(const DriverTime& before) const {
    DriverTime d = now();
    return {d.create_ms - before.create_ms, d.create_cpu_ms - before.create_cpu_ms,
            d.draw_ms - before.draw_ms,     d.draw_cpu_ms - before.draw_cpu_ms,
            d.pipelines - before.pipelines, d.submits - before.submits};
  }
  void add(const DriverTime& o) {
    create_ms += o.create_ms;
    create_cpu_ms += o.create_cpu_ms;
    draw_ms += o.draw_ms;
    draw_cpu_ms += o.draw_cpu_ms;
    pipelines += o.pipelines;
    submits += o.submits;
  }
};

// In process: the stages alone, no worker, no pipes. The full lift also measures the floors:
// floor 1 from the run's own pipeline creations; floor 2 from a second run of each case,
// untimed, on a 1x1 target (the same SPIR-V: the module does not depend on the size), whose
// pipeline creations and draw submissions are the driver's own work: every pipeline the case
// needs, and each one's first draw, where llvmpipe compiles its shaders (the K input sets
// alternate point and linear filtering, which llvmpipe compiles as two variants).
void BM_Corpus_InProcess(benchmark::State& state, bool check_only, bool per_set, Corpus which) {
  const std::vector<corpus::Case>& run = cases_of(which);
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
  corpus::StageOptions floor_run = o;
  floor_run.size = 1;
  for (const corpus::Case& c : run) { // the warm-up
    benchmark::DoNotOptimize(corpus::run_case(c, o));
    if (!check_only) benchmark::DoNotOptimize(corpus::run_case(c, floor_run));
  }
  DriverTime lift_driver, floor;
  double lift_ms = 0, lift_cpu_ms = 0;
  size_t n = 0;
  for (auto _ : state) {
    for (const corpus::Case& c : run) {
      const DriverTime before = DriverTime::now();
      const double cpu0 = process_cpu_ms();
      const auto t0 = Clock::now();
      benchmark::DoNotOptimize(corpus::run_case(c, o));
      lift_ms += ms_since(t0);
      lift_cpu_ms += process_cpu_ms() - cpu0;
      lift_driver.add(DriverTime::now().since(before));
      if (check_only) continue;
      state.PauseTiming();
      const DriverTime floor_before = DriverTime::now();
      benchmark::DoNotOptimize(corpus::run_case(c, floor_run));
      floor.add(DriverTime::now().since(floor_before));
      state.ResumeTiming();
    }
    n += run.size();
  }
  const double cases = static_cast<double>(std::max<size_t>(n, 1));
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["cases"] = static_cast<double>(run.size());
  state.counters["lift_ms_per_case"] = lift_ms / cases;
  // All threads of the process: lavapipe's queue thread (where llvmpipe compiles at the first
  // draw, and rasterises) included.
  state.counters["lift_cpu_ms_per_case"] = lift_cpu_ms / cases;
  state.counters["floor_ms_per_case"] = lift_driver.create_ms / cases;
  state.counters["floor_cpu_ms_per_case"] = lift_driver.create_cpu_ms / cases;
  state.counters["pipelines_per_case"] = static_cast<double>(lift_driver.pipelines) / cases;
  // Queue submissions (uploads, draws, read-backs), each a hand-over to lavapipe's queue
  // thread and back.
  state.counters["submits_per_case"] = static_cast<double>(lift_driver.submits) / cases;
  state.counters["floor2_ms_per_case"] = (floor.create_ms + floor.draw_ms) / cases;
  state.counters["floor2_cpu_ms_per_case"] = (floor.create_cpu_ms + floor.draw_cpu_ms) / cases;
  state.counters["floor2_draw_cpu_ms_per_case"] = floor.draw_cpu_ms / cases;
}

// Children's CPU time (workers collected so far), and this process's (the coordinator's).
double children_cpu_ms() {
  rusage u{};
  ::getrusage(RUSAGE_CHILDREN, &u);
  return (static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 +
          static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e3);
}

// Worker processes (`tierlift test --worker`), as a run uses them: pipes, process start,
// one Vulkan device per worker, the reports. Each iteration runs one worker and two, in
// alternating order (1 then 2, then 2 then 1, ...), so both see the same machine; the
// counters are the medians of each.
void BM_Corpus_Workers(benchmark::State& state, bool check_only, Corpus which) {
  const std::vector<corpus::Case>& run = cases_of(which);
  const auto out = std::filesystem::temp_directory_path() /
                   ("tierlift_bench_corpus_" + std::to_string(::getpid()));
  corpus::RunOptions o;
  o.worker_argv = {TIERLIFT_CLI_PATH, "test", "--worker"};
  if (check_only) o.worker_argv.push_back("--check-only");
  o.out_dir = out.string();
  o.rerun = false;
  struct Timing {
    double ms, cpu_ms, coordinator_cpu_ms;
  };
  auto one_run = [&](unsigned jobs) -> std::optional<Timing> {
    o.jobs = jobs;
    const double own0 = process_cpu_ms(), cpu0 = children_cpu_ms() + own0;
    const auto t0 = Clock::now();
    auto r = corpus::run_corpus(run, o);
    if (!r) {
      state.SkipWithError(r.message().c_str());
      return std::nullopt;
    }
    const double own = process_cpu_ms();
    return Timing{ms_since(t0), children_cpu_ms() + own - cpu0, own - own0};
  };
  if (!one_run(1) || !one_run(2)) return; // the warm-up
  std::vector<Timing> runs[2];
  size_t iteration = 0;
  for (auto _ : state) {
    for (unsigned k = 0; k < 2; ++k) {
      const unsigned jobs = (iteration % 2 == 0) == (k == 0) ? 1 : 2;
      std::optional<Timing> t = one_run(jobs);
      if (!t) return;
      runs[jobs - 1].push_back(*t);
    }
    ++iteration;
  }
  std::filesystem::remove_all(out);
  auto median = [](std::vector<Timing> v, double Timing::*field) {
    std::sort(v.begin(), v.end(),
              [&](const Timing& a, const Timing& b) { return a.*field < b.*field; });
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m].*field : (v[m - 1].*field + v[m].*field) / 2;
  };
  const double cases = static_cast<double>(run.size());
  state.SetItemsProcessed(static_cast<int64_t>(iteration * 2 * run.size()));
  state.counters["cases"] = cases;
  for (unsigned jobs : {1u, 2u}) {
    const std::string w = jobs == 1 ? "one" : "two";
    state.counters[w + "_cases_per_s"] = cases / median(runs[jobs - 1], &Timing::ms) * 1e3;
    state.counters[w + "_cpu_ms_per_case"] = median(runs[jobs - 1], &Timing::cpu_ms) / cases;
    // The coordinator's share (this process): one more process beside the workers on the
    // machine's cores, so what limits two workers against one.
    state.counters[w + "_coordinator_cpu_ms_per_case"] =
        median(runs[jobs - 1], &Timing::coordinator_cpu_ms) / cases;
  }
  state.counters["two_over_one"] = median(runs[0], &Timing::ms) / median(runs[1], &Timing::ms);
}

} // namespace

BENCHMARK_CAPTURE(BM_Corpus_InProcess, CheckOnly, true, false, Corpus::Ours)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Corpus_InProcess, FullLift, false, false, Corpus::Ours)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
// The same on 200 generated ps_2_0 programs (`tierlift test --generate 200 --profile ps_2_0
// --seed 1`).
BENCHMARK_CAPTURE(BM_Corpus_InProcess, FullLiftGenerated, false, false, Corpus::Generated200)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
// The same with a module and pipeline per input set (the differential run before
// StageOptions::one_pipeline_per_case), for the ratio in the same run.
BENCHMARK_CAPTURE(BM_Corpus_InProcess, FullLiftPipelinePerSet, false, true, Corpus::Ours)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
// 1 and 2 workers: our corpus, and 2,000 generated ps_2_0 programs (`tierlift test
// --generate 2000 --profile ps_2_0 --seed 1`).
BENCHMARK_CAPTURE(BM_Corpus_Workers, CheckOnly, true, Corpus::Ours)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(5);
BENCHMARK_CAPTURE(BM_Corpus_Workers, CheckOnlyGenerated, true, Corpus::Generated2000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Corpus_Workers, FullLift, false, Corpus::Ours)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_Corpus_Workers, FullLiftGenerated, false, Corpus::Generated2000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
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
