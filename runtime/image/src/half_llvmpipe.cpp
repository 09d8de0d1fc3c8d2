// lavapipe's float → half conversion when it stores an R16G16B16A16_SFLOAT attachment.
#include <cmath>
#include <limits>

#include "tierlift/image/image.h"

namespace tierlift::img {

float half_toward_zero(float value) {
  if (std::isnan(value) || std::isinf(value)) return value;
  const double a = std::fabs(static_cast<double>(value));
  // Toward zero never overflows: everything above the largest half stores the largest half.
  if (a >= 65504.0) return std::copysign(65504.0f, value);
  double step;
  if (a < 0x1p-14) {
    step = 0x1p-24; // subnormal halves: fixed spacing
  } else {
    int e = 0;
    std::frexp(a, &e);                  // a = m·2^e, m in [0.5, 1)
    step = std::ldexp(1.0, e - 1 - 10); // 10 fraction bits below the leading one
  }
  // a / step is exact (a power-of-two scale), so floor truncates the true value.
  return std::copysign(static_cast<float>(std::floor(a / step) * step), value);
}

} // namespace tierlift::img
