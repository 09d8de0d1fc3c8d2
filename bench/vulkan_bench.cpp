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

#include "blur8_pass.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/listings/embedded.h"
#include "tierlift/pass/setup.h"
#include "tierlift/vulkan/device.h"

using namespace tierlift;

namespace {

constexpr uint32_t kW = bench::kBlurWidth, kH = bench::kBlurHeight;

std::optional<cpu::Pass> blur_pass() {
  return bench::blur8_pass();
}

void BM_Vulkan_Listing2(benchmark::State& state) {
  auto pass = blur_pass();
  if (!pass) {
    state.SkipWithError("could not build the pass");
    return;
  }
  auto created = vulkan::Device::create({});
  if (!created) {
    state.SkipWithError(created.message().c_str());
    return;
  }
  std::unique_ptr<vulkan::Device> dev = std::move(created).value();
  pass->conventions.subtexel_bits = int(dev->subtexel_bits());
  img::Image target(kW, kH, img::Format::RGBA8);
  double setup_ms = 0, draw_ms = 0;
  for (auto _ : state) {
    ir::Result<pass::DrawReport> r = dev->draw(*pass, target);
    if (!r) {
      state.SkipWithError(r.message().c_str());
      return;
    }
    setup_ms += r->setup_ms;
    draw_ms += r->draw_ms;
    benchmark::DoNotOptimize(target.rgba.data());
  }
  bench::set_blur_rate(state);
  state.counters["setup_ms"] = benchmark::Counter(setup_ms, benchmark::Counter::kAvgIterations);
  state.counters["draw_ms"] = benchmark::Counter(draw_ms, benchmark::Counter::kAvgIterations);
  state.SetLabel(dev->name());
}

// The CPU interpreter on the same pass, every core (cpu::draw threads = 0), measured in this
// run so the ratio compares like with like.
void BM_Vulkan_PeerInterpreter_Listing2_AllCores(benchmark::State& state) {
  bench::time_interpreter(state, 0);
}

BENCHMARK(BM_Vulkan_Listing2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Vulkan_PeerInterpreter_Listing2_AllCores)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
