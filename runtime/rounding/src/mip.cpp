// lavapipe's level-of-detail arithmetic (rounding.h, NUMERICS.md M1-M2).
#include <bit>
#include <cmath>

#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding {

float fast_log2_llvmpipe(float x) {
  const auto bits = std::bit_cast<uint32_t>(x);
  const int32_t e = static_cast<int32_t>((bits >> 23) & 0xffu) - 127;
  const float m = std::bit_cast<float>((bits & 0x7fffffu) | 0x3f800000u); // in [1, 2)
  return static_cast<float>(e - 1) + m;
}

int32_t nearest_level_llvmpipe(float lod) {
  if (std::isnan(lod)) return 0;
  constexpr float kLimit = 1073741824.0f; // 2^30: beyond every level, and convertible
  const float clamped = lod < -kLimit ? -kLimit : (lod > kLimit ? kLimit : lod);
  return static_cast<int32_t>(std::nearbyint(clamped)); // the default mode: ties to even
}

int32_t nearest_level_from_rho_llvmpipe(float rho) {
  const float scaled = flush(rho * static_cast<float>(M_SQRT2));
  const auto bits = std::bit_cast<uint32_t>(scaled);
  return static_cast<int32_t>((bits >> 23) & 0xffu) - 127;
}

} // namespace tierlift::rounding
