// Interpreter throughput for the article's 8-tap blur (Listings 1 + 2) at 1920×1080 RGBA8,
// one core and all cores, in Mpix/s; and, for scale, the same pass written as a plain C++
// loop (8 bilinear taps per pixel, same offsets, weights and store) — the peer measured in
// the same run. bench/run.sh prints the ratios.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "blur8_pass.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/image/builtin.h"
#include "tierlift/listings/embedded.h"
#include "tierlift/pass/setup.h"

using namespace tierlift;

namespace {

constexpr uint32_t kW = bench::kBlurWidth, kH = bench::kBlurHeight;

float offset(int k) {
  return bench::blur8_offset(k);
}
void BM_Interpreter_Listing2_OneCore(benchmark::State& s) {
  bench::time_interpreter(s, 1);
}
void BM_Interpreter_Listing2_AllCores(benchmark::State& s) {
  bench::time_interpreter(s, 0);
}

// The peer: the same pass as straight-line C++ (D3D9 centres: u = x/W + offset).
void BM_Peer_PlainLoop(benchmark::State& state) {
  const img::Image noise = img::builtin_noise(kW, kH);
  const img::Image* src = &noise;
  img::Image target(kW, kH, img::Format::RGBA8);
  for (auto _ : state) {
    for (uint32_t y = 0; y < kH; ++y) {
      const float v = float(y) / kH;
      const float fy = v * kH - 0.5f;
      const int y0 = int(std::floor(fy));
      const float b = fy - float(y0);
      const int ya = std::clamp(y0, 0, int(kH) - 1), yb = std::clamp(y0 + 1, 0, int(kH) - 1);
      for (uint32_t x = 0; x < kW; ++x) {
        float acc[4] = {0, 0, 0, 0};
        for (int k = 0; k < 8; ++k) {
          const float fx = (float(x) / kW + offset(k)) * kW - 0.5f;
          const int x0 = int(std::floor(fx));
          const float a = fx - float(x0);
          const int xa = std::clamp(x0, 0, int(kW) - 1), xb = std::clamp(x0 + 1, 0, int(kW) - 1);
          const float *p00 = src->at(xa, ya), *p10 = src->at(xb, ya), *p01 = src->at(xa, yb),
                      *p11 = src->at(xb, yb);
          for (int c = 0; c < 4; ++c)
            acc[c] += 0.125f * ((1 - a) * (1 - b) * p00[c] + a * (1 - b) * p10[c] +
                                (1 - a) * b * p01[c] + a * b * p11[c]);
        }
        float* out = target.at(x, y);
        for (int c = 0; c < 4; ++c) out[c] = img::quantize(img::Format::RGBA8, acc[c]);
      }
    }
    benchmark::DoNotOptimize(target.rgba.data());
  }
  bench::set_blur_rate(state);
}

BENCHMARK(BM_Interpreter_Listing2_OneCore)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Interpreter_Listing2_AllCores)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Peer_PlainLoop)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
