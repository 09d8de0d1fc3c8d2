// The two RGBA8 store rules, exact (ties up) and lavapipe's, and the values of the 256 bytes
// (rounding.h).
#include <cmath>

#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding {

float unorm8_nearest(float value) {
  if (std::isnan(value)) return 0.0f;
  double v = std::fmin(std::fmax(static_cast<double>(value), 0.0), 1.0);
  double k = std::floor(v * 255.0 + 0.5);
  return static_cast<float>(k / 255.0);
}

const std::array<float, 256>& unorm8_levels() {
  static const std::array<float, 256> levels = [] {
    std::array<float, 256> t{};
    for (uint32_t k = 0; k < 256; ++k) t[k] = static_cast<float>(k) / 255.0f;
    return t;
  }();
  return levels;
}

uint8_t unorm8_llvmpipe(float value) {
  // llvmpipe clamps with min(1, x) and leaves the lower end to the saturating integer packs
  // after the conversion: NaN and every value ≤ 0 store 0 (measured, NaN included).
  if (!(value > 0.0f)) return 0;
  if (!(value < 1.0f)) return 255;
  // One fl32 multiply, as the JIT code does; the product lies in (0, 255).
  const float scaled = value * 255.0f;
  // Ties to even, written out so that it does not depend on the FPU rounding mode.
  const float lower = std::floor(scaled);
  const float rest = scaled - lower; // exact (Sterbenz)
  int k = static_cast<int>(lower);
  if (rest > 0.5f || (rest == 0.5f && (k & 1) != 0)) ++k;
  return static_cast<uint8_t>(k);
}

} // namespace tierlift::rounding
