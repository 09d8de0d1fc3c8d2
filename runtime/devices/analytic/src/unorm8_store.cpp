// The RGBA8 store's two halves (unorm8_store.h).
#include "unorm8_store.h"

#include <cmath>

namespace tierlift::analytic::detail {

std::optional<int> unorm8_settled(double v, double e) {
  if (std::isnan(v)) return 0;
  // In steps: the value's reach, widened by the rounding of x·255 to fp32 and by the double
  // rounding of v·255 itself (far below either).
  const double y = v * 255.0;
  const double reach =
      255.0 * e + kFp32Unit * (std::fabs(y) + 255.0 * e) + 1e-12 * (1 + std::fabs(y));
  const double lo = y - reach, hi = y + reach;
  if (hi < 0.5) return 0;     // every x stores 0 (x ≤ 0 included)
  if (lo > 254.5) return 255; // every x stores 255 (x ≥ 1 included)
  // Boundaries k + ½ within [lo, hi]: none when ⌊hi − ½⌋ < ⌈lo − ½⌉.
  if (std::floor(hi - 0.5) < std::ceil(lo - 0.5)) return static_cast<int>(std::floor(y + 0.5));
  return std::nullopt;
}

int unorm8_of_fp32(float x, Unorm8Ties ties, bool* tie) {
  *tie = false;
  if (!(x > 0.0f)) return 0;
  if (!(x < 1.0f)) return 255;
  const float y = x * 255.0f; // the devices' fp32 product
  const float k = std::floor(y);
  const float rest = y - k; // exact
  if (rest == 0.5f) {
    *tie = true;
    const bool odd = std::fmod(k, 2.0f) != 0.0f;
    return static_cast<int>(k) + ((ties == Unorm8Ties::HalfUp || odd) ? 1 : 0);
  }
  return static_cast<int>(k) + (rest > 0.5f ? 1 : 0);
}

} // namespace tierlift::analytic::detail
