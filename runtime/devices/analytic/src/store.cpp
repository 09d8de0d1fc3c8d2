// What a texel holds and how a value is stored, in double (blur_model.h).
#include <algorithm>
#include <cmath>

#include "tierlift/analytic/blur_model.h"

namespace tierlift::analytic {

namespace {

// k/255 as the image holds it: the same float img::quantize returns for step k.
float unorm8_step(double k) {
  return static_cast<float>(k / 255.0);
}

} // namespace

float half_toward_zero_model(double value) {
  if (std::isnan(value) || std::isinf(value) || value == 0.0) return static_cast<float>(value);
  // binary16: 1 sign bit, 5 exponent bits (bias 15), 10 fraction bits. A finite non-zero
  // half is ±2^(e − 15)·(1 + f/1024) for e in 1..30 or ±2^-14·f/1024, so the halves around
  // |v| ≥ 2^-14 with 2^k ≤ |v| < 2^(k+1) are spaced 2^(k − 10) apart, and 2^-24 below 2^-14.
  // Toward zero keeps the largest multiple of that spacing not above |v|; beyond the largest
  // finite half, 65504 = 2^15·(1 + 1023/1024), it stays there (NUMERICS.md rule 35).
  const double a = std::fabs(value);
  constexpr double kMaxHalf = 65504.0;
  double stored = kMaxHalf;
  if (a < kMaxHalf) {
    int e = 0;
    std::frexp(a, &e); // a = m·2^e, m in [½, 1): 2^(e − 1) ≤ a < 2^e
    const int k = std::max(e - 1, -14);
    const double spacing = std::ldexp(1.0, k - 10);
    stored = std::floor(a / spacing) * spacing; // a / spacing: exact (a power of two)
  }
  return static_cast<float>(std::copysign(stored, value)); // every half is a float
}

double texel_value(const img::Image& image, uint32_t x, uint32_t y, int channel) {
  const float v = image.at(x, y)[channel];
  if (image.format != img::Format::RGBA8) return v;
  if (!(v > 0.0f)) return 0.0; // NaN too: an 8-bit texel has no NaN
  if (!(v < 1.0f)) return 1.0;
  return std::nearbyint(double(v) * 255.0) / 255.0;
}

float store_value(img::Format format, double value, Unorm8Ties ties) {
  if (format != img::Format::RGBA8) {
    // Out-of-range doubles become ±inf, not an undefined conversion.
    const double limit = 3.4028234663852886e38;
    const float f = std::isnan(value) ? static_cast<float>(value)
                    : value > limit   ? INFINITY
                    : value < -limit  ? -INFINITY
                                      : static_cast<float>(value);
    return img::quantize(format, f);
  }
  if (!(value > 0.0)) return 0.0f;
  if (!(value < 1.0)) return 1.0f;
  const double x = value * 255.0;
  const double k = std::floor(x), rest = x - k;
  if (std::fabs(rest - 0.5) <= 1e-9) {
    const bool odd = std::fmod(k, 2.0) != 0.0;
    return unorm8_step(ties == Unorm8Ties::HalfUp || odd ? k + 1 : k);
  }
  return unorm8_step(rest > 0.5 ? k + 1 : k);
}

} // namespace tierlift::analytic
