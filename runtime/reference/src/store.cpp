// What a texel holds and how a value is stored, in double (blur_model.h).
#include <cmath>

#include "tierlift/reference/blur_model.h"

namespace tierlift::ref {

namespace {

// k/255 as the image holds it: the same float img::quantize returns for step k.
float unorm8_step(double k) {
  return static_cast<float>(k / 255.0);
}

} // namespace

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

} // namespace tierlift::ref
