// lavapipe's float → half conversion when it stores an R16G16B16A16_SFLOAT attachment.
#include <cmath>
#include <limits>

#include "tierlift/image/image.h"

namespace tierlift::img {

float half_toward_zero(double value) {
  if (std::isnan(value) || std::isinf(value)) return static_cast<float>(value);
  const double a = std::fabs(value);
  // Toward zero never overflows: everything above the largest half stores the largest half.
  if (a >= 65504.0) return static_cast<float>(std::copysign(65504.0, value));
  const double step = half_step(a);
  // a / step is exact (a power-of-two scale), so floor truncates the true value.
  return std::copysign(static_cast<float>(std::floor(a / step) * step), value);
}

} // namespace tierlift::img
