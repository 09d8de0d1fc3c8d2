// The pass two benchmarks time: the article's 8-tap blur (Listings 1 + 2) at 1920×1080
// RGBA8 over seeded noise, horizontal taps at −3.5 … +3.5 texels carrying the half texel
// (texel centres), weights 1/8, linear filtering, clamp addressing.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <optional>

#include "tierlift/cpu/draw.h"

namespace tierlift::bench {

inline constexpr uint32_t kBlurWidth = 1920, kBlurHeight = 1080;

// Offset constant of tap k (0..7), in uv.
float blur8_offset(int k);
// The pass, built the way `tierlift run` builds it; nullopt if the listings do not load.
std::optional<cpu::Pass> blur8_pass();

// Items processed and the Mpix/s counter of a benchmark that blurs one whole frame an
// iteration.
void set_blur_rate(benchmark::State& state);
// The interpreter timed on the pass: cpu::draw on `threads` threads (0: every core) into an
// RGBA8 target each iteration, with set_blur_rate's counters. Both benchmark programs run it,
// so each ratio compares figures of one run.
void time_interpreter(benchmark::State& state, unsigned threads);

} // namespace tierlift::bench
