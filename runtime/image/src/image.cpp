// Format names and the store rule of each target format.
#include "tierlift/image/image.h"
#include "tierlift/rounding/rounding.h"

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

float quantize(Format f, float value) {
  switch (f) {
  case Format::RGBA8: return rounding::unorm8_nearest(value);
  case Format::RGBA16F: return rounding::half_nearest_even(value);
  case Format::RGBA32F: return value;
  }
  return value;
}

void quantize_in_place(Image& image) {
  if (image.format == Format::RGBA32F) return;
  for (float& v : image.rgba) v = quantize(image.format, v);
}

} // namespace tierlift::img
