// Format names and the store rule of each target format.
#include <cmath>
#include <limits>

#include "tierlift/image/image.h"

namespace tierlift::img {

std::string_view format_name(Format f) {
  switch (f) {
  case Format::RGBA8: return "rgba8";
  case Format::RGBA16F: return "rgba16f";
  case Format::RGBA32F: return "rgba32f";
  }
  return "?";
}

std::optional<Format> parse_format(std::string_view name) {
  for (Format f : {Format::RGBA8, Format::RGBA16F, Format::RGBA32F}) {
    if (name == format_name(f)) return f;
  }
  return std::nullopt;
}

namespace {

// UNORM8: NaN stores 0 (as Vulkan and D3D conversions do); otherwise clamp, then round to
// nearest with ties up. value·255 is exact in double (24 + 8 bits), so the tie is decided
// on the float's true value.
float quantize_unorm8(float value) {
  if (std::isnan(value)) return 0.0f;
  double v = std::fmin(std::fmax(static_cast<double>(value), 0.0), 1.0);
  double k = std::floor(v * 255.0 + 0.5);
  return static_cast<float>(k / 255.0);
}

// IEEE binary16, round to nearest even. Working on the magnitude scaled by a power of two
// keeps every step exact, so std::rint (default mode: nearest even) does the rounding.
float quantize_half(float value) {
  if (std::isnan(value) || std::isinf(value)) return value;
  double a = std::fabs(static_cast<double>(value));
  // 65504 is the largest half; values from the midpoint to 65536 (65520) round up to inf.
  if (a >= 65520.0) return std::copysign(std::numeric_limits<float>::infinity(), value);
  const double step = half_step(a);
  double r = std::rint(a / step) * step;
  return std::copysign(static_cast<float>(r), value);
}

} // namespace

double half_step(double a) {
  if (a < 0x1p-14) return 0x1p-24; // subnormal halves: fixed spacing
  int e = 0;
  std::frexp(a, &e);                  // a = m·2^e, m in [0.5, 1)
  return std::ldexp(1.0, e - 1 - 10); // 10 fraction bits below the leading one
}

float quantize(Format f, float value) {
  switch (f) {
  case Format::RGBA8: return quantize_unorm8(value);
  case Format::RGBA16F: return quantize_half(value);
  case Format::RGBA32F: return value;
  }
  return value;
}

void quantize_in_place(Image& image) {
  if (image.format == Format::RGBA32F) return;
  for (float& v : image.rgba) v = quantize(image.format, v);
}

} // namespace tierlift::img
