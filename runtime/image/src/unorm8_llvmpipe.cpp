// lavapipe's float→UNORM8 store rule (see image.h, NUMERICS.md rule 34).
#include <cmath>

#include "tierlift/image/image.h"

namespace tierlift::img {

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

} // namespace tierlift::img
