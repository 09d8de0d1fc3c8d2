// The glow on the CPU device: the block executor (the default) against the per-pixel VM it
// replaced (Executor::Scalar, the "before") and against the same glow written with OpenCV
// (opencv_glow.h), measured in the same run. bench/run.sh prints the ratios.
//
// One frame is what bench_glow.cpp calls a frame: begin_run (the scene handed over), every
// pass of the plan, the final frame read back. Plans are built outside the loop, and every
// benchmark runs one untimed frame first (first touch of the buffers: on a shared machine
// that first frame alone can take several times a warm one).
//
// Arguments of the size sweep: {size, taps} with size 0 = 480×270, 1 = 1920×1080,
// 2 = 3840×2160 (downsample 4 always) and taps 13 (the default profile, σ = 8 and 1.5 px) or
// 25 (one Gaussian σ = 16 px), so that time can be fitted against pixels × taps.
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <string>
#include <utility>

#include "opencv_glow.h"
#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/scenes/default_scene.h"

using namespace tierlift;

namespace {

constexpr unsigned kDownsample = 4;
constexpr std::array<std::pair<uint32_t, uint32_t>, 3> kSizes{
    {{480, 270}, {1920, 1080}, {3840, 2160}}};

const img::Image& scene(uint32_t w, uint32_t h) {
  static std::map<std::pair<uint32_t, uint32_t>, img::Image> cache;
  auto it = cache.find({w, h});
  if (it == cache.end())
    it =
        cache.emplace(std::make_pair(w, h), effects::make_default_scene(w, h, img::Format::RGBA32F))
            .first;
  return it->second;
}

effects::PlanResult make_plan(uint32_t w, uint32_t h, int taps, effects::Tier tier,
                              img::Format format) {
  effects::EffectParams p;
  p.tier = tier;
  p.width = w;
  p.height = h;
  p.downsample = kDownsample;
  p.format = format;
  p.subtexel_bits = 0;
  if (taps == 25) p.profile.terms = {effects::Gaussian{16, 1}};
  return effects::build_glow(p);
}

std::string frame(effects::PassDevice& dev, const effects::EffectPlan& plan,
                  const effects::ImageMap& inputs, img::Image& out) {
  if (ir::Status s = dev.begin_run(plan.graph, inputs); !s) return s.message();
  for (const effects::PassDesc& p : plan.graph.passes)
    if (auto s = dev.draw(p); !s) return p.name + ": " + s.message();
  ir::Result<img::Image> read = dev.read_texture(std::string(effects::kFinalTexture));
  if (!read) return read.message();
  out = std::move(*read); // a frame's copy, as the devices' readback costs
  return {};
}

void run_cpu(benchmark::State& state, uint32_t w, uint32_t h, int taps, effects::Tier tier,
             img::Format format, cpu::Executor executor, unsigned threads = 0) {
  const effects::PlanResult plan = make_plan(w, h, taps, tier, format);
  if (!plan) {
    state.SkipWithError(plan.message().c_str());
    return;
  }
  img::Image input = scene(w, h);
  input.format = format;
  img::quantize_in_place(input);
  const effects::ImageMap inputs{{std::string(effects::kSceneTexture), input}};
  effects::CpuPassDevice dev(threads, executor);
  img::Image out;
  // One frame before timing: the device's buffers and the first touch of every page.
  if (std::string e = frame(dev, *plan, inputs, out); !e.empty()) {
    state.SkipWithError(e.c_str());
    return;
  }
  for (auto _ : state) {
    if (std::string e = frame(dev, *plan, inputs, out); !e.empty()) {
      state.SkipWithError(e.c_str());
      return;
    }
    benchmark::DoNotOptimize(out.rgba.data());
  }
  state.counters["taps"] = double(plan->taps.size());
  state.counters["pixels"] = double(w) * h;
}

// ---- the size × taps sweep (dx9, RGBA32F) -------------------------------------------------

void BM_CpuGlow_OpenCV(benchmark::State& state) {
  const auto [w, h] = kSizes[size_t(state.range(0))];
  const effects::PlanResult plan =
      make_plan(w, h, int(state.range(1)), effects::Tier::Dx9, img::Format::RGBA32F);
  if (!plan) {
    state.SkipWithError(plan.message().c_str());
    return;
  }
  bench::OpenCvGlow g(plan->taps, kDownsample);
  const cv::Mat in = bench::wrap(scene(w, h));
  g.run(in); // warm-up, as the devices get
  for (auto _ : state) {
    const cv::Mat& f = g.run(in);
    benchmark::DoNotOptimize(f.data);
    benchmark::ClobberMemory();
  }
  state.counters["taps"] = double(plan->taps.size());
  state.counters["pixels"] = double(w) * h;
  state.SetLabel("OpenCV " CV_VERSION ", " + std::to_string(cv::getNumThreads()) + " threads");
}

void BM_CpuGlow_Block(benchmark::State& state) {
  const auto [w, h] = kSizes[size_t(state.range(0))];
  run_cpu(state, w, h, int(state.range(1)), effects::Tier::Dx9, img::Format::RGBA32F,
          cpu::Executor::Auto);
}

void BM_CpuGlow_Scalar(benchmark::State& state) {
  const auto [w, h] = kSizes[size_t(state.range(0))];
  run_cpu(state, w, h, int(state.range(1)), effects::Tier::Dx9, img::Format::RGBA32F,
          cpu::Executor::Scalar);
}

void sweep(benchmark::internal::Benchmark* b) {
  for (int64_t size = 0; size < 3; ++size)
    for (int64_t taps : {13, 25}) b->Args({size, taps});
  b->ArgNames({"size", "taps"})->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(BM_CpuGlow_OpenCV)->Apply(sweep);
BENCHMARK(BM_CpuGlow_Block)->Apply(sweep);
// The per-pixel VM takes seconds a frame: 1080p only, two frames.
BENCHMARK(BM_CpuGlow_Scalar)
    ->Args({1, 13})
    ->ArgNames({"size", "taps"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);

// ---- one thread each (OpenCV too), 1080p, 13 taps: CPU time is the figure to read on a
// machine shared with other work (the wall-clock rows above suffer from it).

void BM_CpuGlow_OneThread_OpenCV(benchmark::State& state) {
  const int before = cv::getNumThreads();
  cv::setNumThreads(1);
  const effects::PlanResult plan =
      make_plan(1920, 1080, 13, effects::Tier::Dx9, img::Format::RGBA32F);
  bench::OpenCvGlow g(plan->taps, kDownsample);
  const cv::Mat in = bench::wrap(scene(1920, 1080));
  g.run(in); // warm-up, as the devices get
  for (auto _ : state) {
    const cv::Mat& f = g.run(in);
    benchmark::DoNotOptimize(f.data);
    benchmark::ClobberMemory();
  }
  cv::setNumThreads(before);
}
void BM_CpuGlow_OneThread_Block(benchmark::State& state) {
  run_cpu(state, 1920, 1080, 13, effects::Tier::Dx9, img::Format::RGBA32F, cpu::Executor::Auto, 1);
}
void BM_CpuGlow_OneThread_Scalar(benchmark::State& state) {
  run_cpu(state, 1920, 1080, 13, effects::Tier::Dx9, img::Format::RGBA32F, cpu::Executor::Scalar,
          1);
}
BENCHMARK(BM_CpuGlow_OneThread_OpenCV)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuGlow_OneThread_Block)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuGlow_OneThread_Scalar)->Unit(benchmark::kMillisecond)->Iterations(2);

// ---- the tiers and formats of bench_glow.cpp at 1080p, block and per-pixel ----------------

void BM_CpuGlow_Tier(benchmark::State& state, effects::Tier tier, img::Format format,
                     cpu::Executor executor) {
  run_cpu(state, 1920, 1080, 13, tier, format, executor);
}

using effects::Tier;
using img::Format;
BENCHMARK_CAPTURE(BM_CpuGlow_Tier, block_dx9_rgba8, Tier::Dx9, Format::RGBA8, cpu::Executor::Auto)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuGlow_Tier, block_dx8_rgba8, Tier::Dx8, Format::RGBA8, cpu::Executor::Auto)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuGlow_Tier, scalar_dx9_rgba8, Tier::Dx9, Format::RGBA8,
                  cpu::Executor::Scalar)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_CpuGlow_Tier, scalar_dx8_rgba8, Tier::Dx8, Format::RGBA8,
                  cpu::Executor::Scalar)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);

} // namespace

BENCHMARK_MAIN();
