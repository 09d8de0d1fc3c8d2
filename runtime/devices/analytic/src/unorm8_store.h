// Internal to linear_pass: the RGBA8 store, decided in double where the double value settles
// it and in the devices' fp32 arithmetic where it does not (linear_pass.h, "RGBA8").
#pragma once

#include <cstdint>
#include <optional>

#include "tierlift/analytic/blur_model.h"

namespace tierlift::analytic::detail {

// One fp32 rounding moves a value by at most this much relative to it (round to nearest).
inline constexpr double kFp32Unit = 0x1p-24;

// The 8-bit step every value x of [v − e, v + e] stores under the float devices' rule
// (x ≤ 0 → 0, x ≥ 1 → 255, else fl32(x·255) rounded to nearest), or nullopt when a rounding
// boundary k + ½ lies within reach (the rounding of x·255 to fp32 included). NaN stores 0.
std::optional<int> unorm8_settled(double v, double e);

// The float devices' store of an fp32 value x: NaN and x ≤ 0 → 0, x ≥ 1 → 255, else
// y = fl32(x·255) rounded to the nearest integer, an exact tie by `ties`. *tie is set when y
// lies exactly half-way: the one case D3D9 and Vulkan leave to the device.
int unorm8_of_fp32(float x, Unorm8Ties ties, bool* tie);

// D3D9's product rule in fp32 (NUMERICS.md rule 8): a zero factor gives +0.
inline float product_fp32(float a, float b) {
  return (a == 0.0f || b == 0.0f) ? 0.0f : a * b;
}

} // namespace tierlift::analytic::detail
