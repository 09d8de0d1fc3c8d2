// The RGBA16F store rules (exact nearest-even and lavapipe's toward-zero) and the binary16
// bit codec (rounding.h).
#include <bit>
#include <cmath>
#include <limits>

#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding {

double half_step(double a) {
  if (a < 0x1p-14) return 0x1p-24; // subnormal halves: fixed spacing
  int e = 0;
  std::frexp(a, &e);                  // a = m·2^e, m in [0.5, 1)
  return std::ldexp(1.0, e - 1 - 10); // 10 fraction bits below the leading one
}

// Working on the magnitude scaled by a power of two keeps every step exact, so std::rint
// (default mode: nearest even) does the rounding.
float half_nearest_even(float value) {
  if (std::isnan(value) || std::isinf(value)) return value;
  double a = std::fabs(static_cast<double>(value));
  // 65504 is the largest half; values from the midpoint to 65536 (65520) round up to inf.
  if (a >= 65520.0) return std::copysign(std::numeric_limits<float>::infinity(), value);
  const double step = half_step(a);
  double r = std::rint(a / step) * step;
  return std::copysign(static_cast<float>(r), value);
}

float half_toward_zero(double value) {
  if (std::isnan(value) || std::isinf(value)) return static_cast<float>(value);
  const double a = std::fabs(value);
  // Toward zero never overflows: everything above the largest half stores the largest half.
  if (a >= 65504.0) return static_cast<float>(std::copysign(65504.0, value));
  const double step = half_step(a);
  // a / step is exact (a power-of-two scale), so floor truncates the true value.
  return std::copysign(static_cast<float>(std::floor(a / step) * step), value);
}

uint16_t half_bits(float value) {
  uint32_t x = std::bit_cast<uint32_t>(value);
  uint32_t sign = (x >> 16) & 0x8000u;
  uint32_t exp = (x >> 23) & 0xFFu;
  uint32_t man = x & 0x7FFFFFu;
  if (exp == 0xFF) return static_cast<uint16_t>(sign | 0x7C00u | (man ? 0x200u | (man >> 13) : 0));
  int e = static_cast<int>(exp) - 127 + 15;
  if (e >= 31) return static_cast<uint16_t>(sign | 0x7C00u);
  uint32_t m = man | 0x800000u;     // implicit bit
  int shift = e <= 0 ? 14 - e : 13; // subnormal halves shift further
  if (shift > 24) return static_cast<uint16_t>(sign);
  uint32_t half = m >> shift;
  uint32_t rest = m & ((1u << shift) - 1u), mid = 1u << (shift - 1);
  if (rest > mid || (rest == mid && (half & 1u))) ++half; // nearest even; may carry into exp
  uint32_t bits = e <= 0 ? half : ((static_cast<uint32_t>(e) << 10) + (half - 0x400u));
  return static_cast<uint16_t>(sign | bits);
}

float half_from_bits(uint16_t h) {
  uint32_t sign = (h & 0x8000u) ? 1u : 0u;
  uint32_t exp = (h >> 10) & 0x1Fu, man = h & 0x3FFu;
  float v;
  if (exp == 0)
    v = std::ldexp(static_cast<float>(man), -24);
  else if (exp == 31)
    v = man ? std::numeric_limits<float>::quiet_NaN() : INFINITY;
  else
    v = std::ldexp(static_cast<float>(man | 0x400u), static_cast<int>(exp) - 25);
  return sign ? -v : v;
}

} // namespace tierlift::rounding
