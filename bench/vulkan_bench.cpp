// The Vulkan device (lavapipe by default) against the CPU interpreter on the article's 8-tap
// blur (Listings 1 + 2) at 1920×1080 RGBA8, in the same run, in Mpix/s. bench/run.sh prints
// the ratio.
//
// What one Vulkan iteration is: Device::draw as it stands. It compiles the pair to SPIR-V,
// builds the pipeline, allocates and uploads the texture and the target, draws and reads
// back on every call (it keeps no pipeline cache), so the figure includes all of that; the
// counters setup_ms (compile, pipeline, resources, uploads) and draw_ms (submit to fence:
// draw and readback) split it. Device creation (instance, logical device) happens once,
// outside the loop, without the validation layer.
#include <benchmark/benchmark.h>

#include <memory>
#include <optional>
#include <string>

#include "tierlift/asm/parser.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/cpu/run_job.h"
#include "tierlift/listings/embedded.h"
#include "tierlift/vulkan/device.h"

using namespace tierlift;

namespace {

constexpr uint32_t kW = 1920, kH = 1080;

std::shared_ptr<const ir::Program> listing(const char* name) {
  auto text = listings::find_embedded(std::string("gpugems21/") + name);
  auto r = as::parse_text(std::string(text.value_or("")), name);
  return r.program ? std::make_shared<const ir::Program>(std::move(*r.program)) : nullptr;
}

// Horizontal taps at -3.5 … +3.5 texels with the half texel (texel centres), weights 1/8:
// the same pass as bench/interpreter_bench.cpp.
float offset(int k) {
  return (float(k) - 3.5f + 0.5f) / float(kW);
}

std::optional<cpu::Pass> blur_pass() {
  cpu::RunRequest r;
  r.vs = listing("listing1_blur8_coords.vsh");
  r.ps = listing("listing2_blur8_weighted_sum.psh");
  if (!r.vs || !r.ps) return std::nullopt;
  r.width = kW;
  r.height = kH;
  r.format = img::Format::RGBA8;
  std::string err;
  for (int k = 0; k < 8; ++k) {
    r.constants.push_back(*cpu::parse_const_setting(
        "vs:c" + std::to_string(k) + "=" + std::to_string(offset(k)) + ",0,0,0", err));
    r.constants.push_back(
        *cpu::parse_const_setting("ps:c" + std::to_string(k) + "=0.125,0.125,0.125,0.125", err));
  }
  r.attrs.push_back(*cpu::parse_attr_setting("v3=quad-uv", err));
  r.textures.push_back({0, "builtin:noise:1920x1080"});
  r.filter = cpu::Filter::Linear;
  r.address = cpu::AddressMode::Clamp;
  cpu::RunDiagnostics d;
  return cpu::pass_from_request(r, d);
}

void set_rate(benchmark::State& state) {
  state.SetItemsProcessed(int64_t(state.iterations()) * kW * kH);
  state.counters["Mpix/s"] =
      benchmark::Counter(double(kW) * kH * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Vulkan_Listing2(benchmark::State& state) {
  auto pass = blur_pass();
  if (!pass) {
    state.SkipWithError("could not build the pass");
    return;
  }
  std::string err;
  auto dev = vulkan::Device::create({}, &err);
  if (!dev) {
    state.SkipWithError(err.c_str());
    return;
  }
  pass->conventions.subtexel_bits = int(dev->subtexel_bits());
  img::Image target(kW, kH, img::Format::RGBA8);
  double setup_ms = 0, draw_ms = 0;
  for (auto _ : state) {
    vulkan::DrawResult r = dev->draw(*pass, target);
    if (!r.ok) {
      state.SkipWithError(r.error.c_str());
      return;
    }
    setup_ms += r.setup_ms;
    draw_ms += r.draw_ms;
    benchmark::DoNotOptimize(target.rgba.data());
  }
  set_rate(state);
  state.counters["setup_ms"] = benchmark::Counter(setup_ms, benchmark::Counter::kAvgIterations);
  state.counters["draw_ms"] = benchmark::Counter(draw_ms, benchmark::Counter::kAvgIterations);
  state.SetLabel(dev->name());
}

// The CPU interpreter on the same pass, every core (cpu::draw threads = 0), measured in this
// run so the ratio compares like with like.
void BM_Vulkan_PeerInterpreter_Listing2_AllCores(benchmark::State& state) {
  auto pass = blur_pass();
  if (!pass) {
    state.SkipWithError("could not build the pass");
    return;
  }
  img::Image target(kW, kH, img::Format::RGBA8);
  for (auto _ : state) {
    auto stats = cpu::draw(*pass, target, 0);
    benchmark::DoNotOptimize(stats.pixels_shaded);
  }
  set_rate(state);
}

BENCHMARK(BM_Vulkan_Listing2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Vulkan_PeerInterpreter_Listing2_AllCores)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
