// The glow of issue 5 at 1920×1080, downsample 4, default blur profile, measured in one run:
//   * BM_Glow_Vulkan/<case>: the steady-state frame on the Vulkan device (lavapipe);
//   * BM_Glow_VulkanVsGlsl/<case>: the Vulkan frame and the same graph written by hand in
//     GLSL (glsl_glow_peer.h) on the same device, alternating frame for frame; run.sh
//     prints Vulkan / GLSL (the lift's cost: ≤ 1.0 is the aim);
//   * BM_Glow_Interpreter/<case>: the steady-state frame on the CPU device;
//   * BM_Glow_InterpreterVsOpenCV/<case>: the CPU device's frame and OpenCV's, alternating
//     frame for frame; run.sh prints interpreter / OpenCV (the target is <= 2.0);
//   * BM_Glow_OpenCV: the same glow written with OpenCV (rgb × alpha, resize INTER_AREA,
//     sepFilter2D with the plan's own taps, resize INTER_LINEAR, add) in float;
//   * BM_GlowScale_<device>/<w>x<h>/taps:<n> (glow_frames.h): frame time against size and
//     taps; run.sh fits the exponent of time against pixels × taps.
// A frame on a tierlift device is glow_frames.h's (every pass, then finish(); setup
// outside the loop). On the OpenCV side one frame is the five calls below into buffers kept
// across frames (the idiomatic use).
//
// Each device benchmark also compares its final frame with OpenCV's once, after the loop
// (counters max_abs_vs_opencv, rmse_vs_opencv, identical_vs_opencv): a sanity check that the
// peer does the same work, not a test (the tests hold the agreement targets). In RGBA32F the
// two differ by a few 1e-5 at most, near sharp edges: the passes address texels with
// normalised float uv (an ulp of u ≈ 0.5 is ~1e-4 texel at 1920 wide), which moves the
// bilinear weights of the downsample and upsample reads; OpenCV indexes texels exactly.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <glslang/Public/ShaderLang.h>

#include "glow_frames.h"
#include "glsl_glow_peer.h"
#include "opencv_glow.h"
#include "tierlift/effects/glow/glow.h"
#include "tierlift/image/compare.h"

using namespace tierlift;

namespace {

constexpr uint32_t kW = 1920, kH = 1080;
constexpr unsigned kDownsample = 4;

// The scene every benchmark draws, made once, in RGBA32F (its colours are multiples of
// 1/255, so RGBA8 stores them exactly).
const img::Image& scene() {
  return bench::glow_scene(kW, kH);
}

effects::PlanResult make_plan(effects::Tier tier, img::Format format) {
  return bench::glow_plan(tier, format, kW, kH);
}

// ---- the OpenCV glow ----------------------------------------------------------------------

// The peer itself is bench::OpenCvGlow (opencv_glow.h), shared with bench_cpu_glow.

// OpenCV's final frame for `taps` as an img::Image (once, for the comparison).
img::Image opencv_final(const std::vector<effects::BlurTap>& taps) {
  bench::OpenCvGlow g(taps, kDownsample);
  const cv::Mat& f = g.run(bench::wrap(scene()));
  img::Image out(kW, kH, img::Format::RGBA32F);
  cv::Mat(f).copyTo(bench::wrap(out)); // wrap(out) shares out's storage
  return out;
}

void BM_Glow_OpenCV(benchmark::State& state) {
  const effects::PlanResult plan = make_plan(effects::Tier::Dx9, img::Format::RGBA32F);
  if (!plan) {
    state.SkipWithError(plan.message().c_str());
    return;
  }
  bench::OpenCvGlow g(plan->taps, kDownsample);
  const cv::Mat in = bench::wrap(scene());
  for (auto _ : state) {
    const cv::Mat& f = g.run(in);
    benchmark::DoNotOptimize(f.data);
    benchmark::ClobberMemory();
  }
  state.counters["taps"] = double(plan->taps.size());
  state.SetLabel("OpenCV " CV_VERSION ", " + std::to_string(cv::getNumThreads()) + " threads");
}

// ---- the glow on a tierlift device --------------------------------------------------------

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// One frame of ours, then one of the peer's, each iteration, so that a load that comes and
// goes on the machine falls on both; each frame returns an error message (empty: fine).
// Counters <ours>_ms and <peer>_ms (median frames) and <ours>_over_<peer>. False after a
// failure (the benchmark is skipped with its message).
bool alternate_frames(benchmark::State& state, const std::string& ours_name,
                      const std::function<std::string()>& ours, const std::string& peer_name,
                      const std::function<std::string()>& peer) {
  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  std::vector<double> ours_ms, peer_ms;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    std::string error = ours();
    const auto t1 = Clock::now();
    if (error.empty()) error = peer();
    const auto t2 = Clock::now();
    if (!error.empty()) {
      state.SkipWithError(error.c_str());
      return false;
    }
    ours_ms.push_back(ms(t0, t1));
    peer_ms.push_back(ms(t1, t2));
  }
  state.counters[ours_name + "_ms"] = median(ours_ms);
  state.counters[peer_name + "_ms"] = median(peer_ms);
  state.counters[ours_name + "_over_" + peer_name] = median(ours_ms) / median(peer_ms);
  return true;
}

void run_device(benchmark::State& state, effects::PassDevice& dev, effects::Tier tier,
                img::Format format) {
  const effects::PlanResult plan = make_plan(tier, format);
  img::Image final_frame;
  if (!bench::run_device_frames(state, dev, plan, scene(), &final_frame)) return;
  // OpenCV works in float throughout; its final frame gets the target's store rule (RGBA8:
  // clamp to [0, 1] and 255 steps) so that the check compares like with like. The RGBA8
  // graph also rounds every intermediate texture, so a few LSB differ there.
  img::Image peer = opencv_final(plan->taps);
  peer.format = format;
  img::quantize_in_place(peer);
  if (auto c = img::compare(final_frame, peer)) {
    state.counters["max_abs_vs_opencv"] = c->max_abs_all;
    state.counters["rmse_vs_opencv"] = c->rmse_all;
    state.counters["identical_vs_opencv"] = c->identical_share;
  }
}

void BM_Glow_Vulkan(benchmark::State& state, effects::Tier tier, img::Format format) {
  std::string error;
  vulkan::Device* vk = bench::bench_vulkan_device(&error);
  if (!vk) {
    state.SkipWithError(error.c_str());
    return;
  }
  std::unique_ptr<effects::PassDevice> dev = effects::make_vulkan_pass_device(*vk);
  run_device(state, *dev, tier, format);
  state.SetLabel(vk->name());
}

// Vulkan against the hand-written GLSL chain of the same graph on the same device (its own
// instance), frame for frame: each iteration runs one frame of each, so a load that comes
// and goes on the machine falls on both. Counters: the median frame of each and their
// ratio (bench/run.sh prints it; the aim is <= 1.0).
void BM_Glow_VulkanVsGlsl(benchmark::State& state, effects::Tier tier, img::Format format) {
  static const bool glslang_ready = glslang::InitializeProcess();
  const effects::PlanResult plan = make_plan(tier, format);
  std::string error;
  vulkan::Device* vk = bench::bench_vulkan_device(&error);
  if (!plan || !glslang_ready || !vk) {
    state.SkipWithError(!plan ? plan.message().c_str() : vk ? "glslang failed" : error.c_str());
    return;
  }
  img::Image input = scene();
  input.format = format;
  img::quantize_in_place(input);
  std::unique_ptr<bench::GlslGlowPeer> peer =
      bench::GlslGlowPeer::create(plan->graph, input, &error);
  std::unique_ptr<effects::PassDevice> ours = effects::make_vulkan_pass_device(*vk);
  const effects::ImageMap inputs{{std::string(effects::kSceneTexture), input}};
  auto our_frame = [&]() -> std::string {
    for (const effects::PassDesc& p : plan->graph.passes)
      if (auto s = ours->draw(p); !s) return s.message();
    return ours->finish().message();
  };
  if (peer && (error = ours->begin_run(plan->graph, inputs).message()).empty())
    error = peer->frame(); // both warm: first-touch of every texture's pages
  if (error.empty()) error = our_frame();
  if (!error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
  if (!alternate_frames(state, "vulkan", our_frame, "glsl", [&] { return peer->frame(); })) return;
  state.counters["passes"] = double(plan->graph.passes.size());
  // That the peer does the same work (RGBA32F, where it can read its frame back): its final
  // frame against ours, once, after the loop (counter glsl_max_abs_vs_vulkan).
  img::Image peer_final;
  ir::Result<img::Image> ours_final = ours->read_texture(std::string(effects::kFinalTexture));
  if (format == img::Format::RGBA32F && ours_final &&
      peer->read(std::string(effects::kFinalTexture), peer_final).empty())
    if (auto c = img::compare(*ours_final, peer_final))
      state.counters["glsl_max_abs_vs_vulkan"] = c->max_abs_all;
  state.SetLabel(vk->name());
}

// The interpreter on every core (threads 0).
void BM_Glow_Interpreter(benchmark::State& state, effects::Tier tier, img::Format format) {
  effects::CpuPassDevice dev(0);
  run_device(state, dev, tier, format);
}

// The interpreter against OpenCV, frame for frame, as BM_Glow_VulkanVsGlsl pairs Vulkan with
// its peer: each iteration runs one interpreter frame (every core) and one OpenCV frame (its
// own threads), so a load that comes and goes falls on both. Counters: the median frame of
// each and their ratio (bench/run.sh prints it; the target is <= 2.0). OpenCV runs the float
// glow whatever the case's format: the peer is the same for every case.
void BM_Glow_InterpreterVsOpenCV(benchmark::State& state, effects::Tier tier, img::Format format) {
  const effects::PlanResult plan = make_plan(tier, format);
  const effects::PlanResult float_plan = make_plan(effects::Tier::Dx9, img::Format::RGBA32F);
  if (!plan || !float_plan) {
    state.SkipWithError((plan ? float_plan : plan).message().c_str());
    return;
  }
  img::Image input = scene();
  input.format = format;
  img::quantize_in_place(input);
  effects::CpuPassDevice dev(0);
  const effects::ImageMap inputs{{std::string(effects::kSceneTexture), input}};
  auto frame = [&]() -> std::string {
    for (const effects::PassDesc& p : plan->graph.passes)
      if (auto s = dev.draw(p); !s) return p.name + ": " + s.message();
    return dev.finish().message();
  };
  bench::OpenCvGlow peer(float_plan->taps, kDownsample);
  const cv::Mat in = bench::wrap(scene());
  std::string error = dev.begin_run(plan->graph, inputs).message();
  if (error.empty()) error = frame(); // both warm, as in run_device_frames
  benchmark::DoNotOptimize(peer.run(in).data);
  if (!error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
  auto peer_frame = [&] {
    benchmark::DoNotOptimize(peer.run(in).data);
    benchmark::ClobberMemory();
    return std::string();
  };
  if (!alternate_frames(state, "interpreter", frame, "opencv", peer_frame)) return;
  state.counters["passes"] = double(plan->graph.passes.size());
}

using effects::Tier;
using img::Format;

BENCHMARK(BM_Glow_OpenCV)->Unit(benchmark::kMillisecond)->UseRealTime();

#define TIERLIFT_GLOW_CASES(fn, ...)                                                               \
  BENCHMARK_CAPTURE(fn, dx9_rgba32f, Tier::Dx9, Format::RGBA32F)->__VA_ARGS__;                     \
  BENCHMARK_CAPTURE(fn, dx9_rgba8, Tier::Dx9, Format::RGBA8)->__VA_ARGS__;                         \
  BENCHMARK_CAPTURE(fn, dx8_rgba8, Tier::Dx8, Format::RGBA8)->__VA_ARGS__
TIERLIFT_GLOW_CASES(BM_Glow_Vulkan, Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0));
TIERLIFT_GLOW_CASES(BM_Glow_VulkanVsGlsl,
                    Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0));
TIERLIFT_GLOW_CASES(BM_Glow_Interpreter,
                    Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0));
TIERLIFT_GLOW_CASES(BM_Glow_InterpreterVsOpenCV,
                    Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0));

// Scaling of the devices this file knows (another device's file registers its own).
[[maybe_unused]] const bool kScalingRegistered = [] {
  bench::register_glow_scaling("Vulkan", [](std::string* error) {
    vulkan::Device* vk = bench::bench_vulkan_device(error);
    return vk ? effects::make_vulkan_pass_device(*vk) : nullptr;
  });
  bench::register_glow_scaling(
      "Interpreter",
      [](std::string*) -> std::unique_ptr<effects::PassDevice> {
        return std::make_unique<effects::CpuPassDevice>(0);
      },
      1);
  return true;
}();

} // namespace

BENCHMARK_MAIN();
