// The glow of issue 5 at 1920×1080, downsample 4, default blur profile: frame time on the
// Vulkan device (lavapipe) and on the CPU interpreter, against the same glow written with
// OpenCV (rgb × alpha, resize INTER_AREA, sepFilter2D with the plan's own taps, resize
// INTER_LINEAR, add) in float, measured in the same run. bench/run.sh prints the ratios.
//
// What one frame is, on a tierlift device: begin_run (the scene handed over), every pass of
// the plan in order, and the final frame read back — what `tierlift glow` does for one
// image, minus reading the intermediate textures back. Building the plan (parsing the
// listings) and creating the Vulkan device happen once, outside the loop. On the OpenCV side
// one frame is the five calls below into buffers kept across frames (the idiomatic use).
//
// Each device benchmark also compares its final frame with OpenCV's once, after the loop
// (counters max_abs_vs_opencv, rmse_vs_opencv, identical_vs_opencv): a sanity check that the
// peer does the same work, not a test (the tests hold the agreement targets). In RGBA32F the
// two differ by a few 1e-5 at most, near sharp edges: the passes address texels with
// normalised float uv (an ulp of u ≈ 0.5 is ~1e-4 texel at 1920 wide), which moves the
// bilinear weights of the downsample and upsample reads; OpenCV indexes texels exactly.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "tierlift/effects/default_scene.h"
#include "tierlift/effects/device.h"
#include "tierlift/effects/glow.h"
#include "tierlift/image/compare.h"
#include "tierlift/vulkan/device.h"

using namespace tierlift;

namespace {

constexpr uint32_t kW = 1920, kH = 1080;
constexpr unsigned kDownsample = 4;

// The scene every benchmark draws, made once, in RGBA32F (its colours are multiples of
// 1/255, so RGBA8 stores them exactly).
const img::Image& scene() {
  static const img::Image s = effects::make_default_scene(kW, kH, img::Format::RGBA32F);
  return s;
}

effects::GlowPlan make_plan(effects::Tier tier, img::Format format) {
  effects::GlowParams p;
  p.tier = tier;
  p.width = kW;
  p.height = kH;
  p.downsample = kDownsample;
  p.format = format;
  p.subtexel_bits = 0; // as the tests and `tierlift glow` run it (exact bilinear weights)
  return effects::build_glow(p);
}

// ---- the OpenCV glow ----------------------------------------------------------------------

// The plan's taps (offsets −R..R, texels of the small texture) as a sepFilter2D kernel;
// sepFilter2D correlates, so kernel[R + k] weights the texel at offset k.
cv::Mat kernel_from_taps(const std::vector<effects::BlurTap>& taps) {
  int r = 0;
  for (const effects::BlurTap& t : taps) r = std::max(r, std::abs(t.offset));
  cv::Mat k = cv::Mat::zeros(2 * r + 1, 1, CV_32F);
  for (const effects::BlurTap& t : taps) k.at<float>(t.offset + r) += float(t.weight);
  return k;
}

struct OpenCvGlow {
  cv::Mat kernel;
  cv::Mat mask, sources, small, blurred, glow, final;

  explicit OpenCvGlow(const std::vector<effects::BlurTap>& taps) : kernel(kernel_from_taps(taps)) {}

  // `in` is RGBA float. Sources = (r·a, g·a, b·a, 0): a zero alpha makes `add` keep the
  // scene's alpha, as the composite pass does (it adds rgb only).
  const cv::Mat& run(const cv::Mat& in) {
    const int from_to[] = {3, 0, 3, 1, 3, 2, -1, 3}; // -1: channel filled with zero
    mask.create(in.size(), in.type());
    cv::mixChannels(&in, 1, &mask, 1, from_to, 4);
    cv::multiply(in, mask, sources);
    const cv::Size small_size((in.cols + int(kDownsample) - 1) / int(kDownsample),
                              (in.rows + int(kDownsample) - 1) / int(kDownsample));
    cv::resize(sources, small, small_size, 0, 0, cv::INTER_AREA);
    // BORDER_REPLICATE: the blur passes sample with clamp addressing.
    cv::sepFilter2D(small, blurred, -1, kernel, kernel, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
    cv::resize(blurred, glow, in.size(), 0, 0, cv::INTER_LINEAR);
    cv::add(in, glow, final);
    return final;
  }
};

cv::Mat wrap(const img::Image& im) {
  return cv::Mat(int(im.height), int(im.width), CV_32FC4, const_cast<float*>(im.rgba.data()));
}

// OpenCV's final frame for `taps` as an img::Image (once, for the comparison).
img::Image opencv_final(const std::vector<effects::BlurTap>& taps) {
  OpenCvGlow g(taps);
  const cv::Mat& f = g.run(wrap(scene()));
  img::Image out(kW, kH, img::Format::RGBA32F);
  cv::Mat(f).copyTo(wrap(out)); // wrap(out) shares out's storage
  return out;
}

void BM_Glow_OpenCV(benchmark::State& state) {
  const effects::GlowPlan plan = make_plan(effects::Tier::Dx9, img::Format::RGBA32F);
  if (!plan) {
    state.SkipWithError(plan.error.c_str());
    return;
  }
  OpenCvGlow g(plan.taps);
  const cv::Mat in = wrap(scene());
  for (auto _ : state) {
    const cv::Mat& f = g.run(in);
    benchmark::DoNotOptimize(f.data);
    benchmark::ClobberMemory();
  }
  state.counters["taps"] = double(plan.taps.size());
  state.SetLabel("OpenCV " CV_VERSION ", " + std::to_string(cv::getNumThreads()) + " threads");
}

// ---- the glow on a tierlift device --------------------------------------------------------

// One frame (see the top of the file). Empty string on success.
std::string device_frame(effects::PassDevice& dev, const effects::GlowPlan& plan,
                         const effects::ImageMap& inputs, img::Image& final_frame) {
  if (std::string e = dev.begin_run(plan.graph, inputs); !e.empty()) return e;
  for (const effects::PassDesc& p : plan.graph.passes)
    if (std::string e = dev.run_pass(p); !e.empty()) return p.name + ": " + e;
  return dev.read_texture(std::string(effects::kFinalTexture), final_frame);
}

void run_device(benchmark::State& state, effects::PassDevice& dev, effects::Tier tier,
                img::Format format) {
  const effects::GlowPlan plan = make_plan(tier, format);
  if (!plan) { // e.g. a tier whose generator is not built ("tier dx8: not built yet")
    state.SkipWithError(plan.error.c_str());
    return;
  }
  img::Image input = scene();
  input.format = format;
  img::quantize_in_place(input); // stored in the graph's format, as run_graph does
  const effects::ImageMap inputs{{std::string(effects::kSceneTexture), input}};
  img::Image final_frame;
  for (auto _ : state) {
    if (std::string e = device_frame(dev, plan, inputs, final_frame); !e.empty()) {
      state.SkipWithError(e.c_str());
      return;
    }
    benchmark::DoNotOptimize(final_frame.rgba.data());
  }
  state.counters["passes"] = double(plan.graph.passes.size());
  // OpenCV works in float throughout; its final frame gets the target's store rule (RGBA8:
  // clamp to [0, 1] and 255 steps) so that the check compares like with like. The RGBA8
  // graph also rounds every intermediate texture, so a few LSB differ there.
  img::Image peer = opencv_final(plan.taps);
  peer.format = format;
  img::quantize_in_place(peer);
  if (auto c = img::compare(final_frame, peer)) {
    state.counters["max_abs_vs_opencv"] = c->max_abs_all;
    state.counters["rmse_vs_opencv"] = c->rmse_all;
    state.counters["identical_vs_opencv"] = c->identical_share;
  }
}

// Created once for every Vulkan benchmark (instance and logical device, no validation).
vulkan::Device* vulkan_device(std::string* error) {
  static std::string create_error;
  static const std::unique_ptr<vulkan::Device> dev = vulkan::Device::create({}, &create_error);
  *error = create_error;
  return dev.get();
}

// A frame takes about a second on lavapipe: MinTime 2 s gives a few frames.
void BM_Glow_Vulkan(benchmark::State& state, effects::Tier tier, img::Format format) {
  std::string error;
  vulkan::Device* vk = vulkan_device(&error);
  if (!vk) {
    state.SkipWithError(error.c_str());
    return;
  }
  std::unique_ptr<effects::PassDevice> dev = effects::make_vulkan_pass_device(*vk);
  run_device(state, *dev, tier, format);
  state.SetLabel(vk->name());
}

// The interpreter on every core (threads 0). Seconds a frame: a fixed, small iteration count.
void BM_Glow_Interpreter(benchmark::State& state, effects::Tier tier, img::Format format) {
  effects::CpuPassDevice dev(0);
  run_device(state, dev, tier, format);
}

using effects::Tier;
using img::Format;

BENCHMARK(BM_Glow_OpenCV)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_CAPTURE(BM_Glow_Vulkan, dx9_rgba32f, Tier::Dx9, Format::RGBA32F)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Glow_Vulkan, dx9_rgba8, Tier::Dx9, Format::RGBA8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);
BENCHMARK_CAPTURE(BM_Glow_Vulkan, dx8_rgba8, Tier::Dx8, Format::RGBA8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

BENCHMARK_CAPTURE(BM_Glow_Interpreter, dx9_rgba32f, Tier::Dx9, Format::RGBA32F)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_Glow_Interpreter, dx9_rgba8, Tier::Dx9, Format::RGBA8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(BM_Glow_Interpreter, dx8_rgba8, Tier::Dx8, Format::RGBA8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);

} // namespace

BENCHMARK_MAIN();
