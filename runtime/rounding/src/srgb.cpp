// The sRGB transfer functions of IEC 61966-2-1 and the two tables the devices read them
// through (rounding.h, NUMERICS.md S1–S3).
#include <cmath>
#include <limits>

#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding {

double srgb_to_linear_exact(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb_exact(double l) {
  return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

const std::array<float, 256>& srgb_decode_levels() {
  static const std::array<float, 256> levels = [] {
    std::array<float, 256> t{};
    for (int k = 0; k < 256; ++k) t[k] = static_cast<float>(srgb_to_linear_exact(k / 255.0));
    return t;
  }();
  return levels;
}

const std::array<float, 256>& srgb_encode_thresholds() {
  static const std::array<float, 256> thresholds = [] {
    std::array<float, 256> t{};
    t[0] = -std::numeric_limits<float>::infinity(); // never compared
    for (int k = 1; k < 256; ++k) {
      // The byte reaches k where 255·encode(l) reaches k − ½, that is where l reaches the
      // decode of (k − ½)/255; the least float at or above that point.
      const double edge = srgb_to_linear_exact((k - 0.5) / 255.0);
      float f = static_cast<float>(edge);
      if (static_cast<double>(f) < edge) f = std::nextafter(f, 2.0f);
      t[k] = f;
    }
    return t;
  }();
  return thresholds;
}

uint8_t srgb_encode_byte(float linear) {
  // The binary search the SPIR-V makes (codegen's sRGB write): eight compares, each
  // "linear ≥ threshold", so NaN and everything below the first threshold give 0.
  const std::array<float, 256>& t = srgb_encode_thresholds();
  uint32_t k = 0;
  for (uint32_t step = 128; step >= 1; step /= 2)
    if (linear >= t[k + step]) k += step;
  return static_cast<uint8_t>(k);
}

float srgb_encoded(float linear) {
  return static_cast<float>(srgb_encode_byte(linear)) * kSrgbByteScale;
}

} // namespace tierlift::rounding
