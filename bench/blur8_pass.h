// The pass two benchmarks time: the article's 8-tap blur (Listings 1 + 2) at 1920×1080
// RGBA8 over seeded noise, horizontal taps at −3.5 … +3.5 texels carrying the half texel
// (texel centres), weights 1/8, linear filtering, clamp addressing.
#pragma once

#include <cstdint>
#include <optional>

#include "tierlift/cpu/draw.h"

namespace tierlift::bench {

inline constexpr uint32_t kBlurWidth = 1920, kBlurHeight = 1080;

// Offset constant of tap k (0..7), in uv.
float blur8_offset(int k);
// The pass, built the way `tierlift run` builds it; nullopt if the listings do not load.
std::optional<cpu::Pass> blur8_pass();

} // namespace tierlift::bench
