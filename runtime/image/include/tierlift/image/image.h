// Images as every device stores them: RGBA floats holding exactly the value the target
// format stores (after quantisation), so that images of any two ways compare directly.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace tierlift::img {

enum class Format { RGBA8, RGBA16F, RGBA32F };
std::string_view format_name(Format f); // "rgba8", "rgba16f", "rgba32f"
std::optional<Format> parse_format(std::string_view name);

// Largest width or height tierlift accepts anywhere (images, targets, textures, scenes).
inline constexpr uint32_t kMaxDimension = 16384;
// The size cap, the one check every input of a size reads: each side 1..kMaxDimension.
constexpr bool valid_size(uint32_t width, uint32_t height) {
  return width >= 1 && height >= 1 && width <= kMaxDimension && height <= kMaxDimension;
}

struct Image {
  uint32_t width = 0, height = 0;
  Format format = Format::RGBA32F;
  std::vector<float> rgba; // row-major, top row first, 4 floats per pixel

  Image() = default;
  Image(uint32_t w, uint32_t h, Format f = Format::RGBA32F)
      : width(w), height(h), format(f), rgba(size_t{w} * h * 4, 0.0f) {}
  float* at(uint32_t x, uint32_t y) { return &rgba[(size_t{y} * width + x) * 4]; }
  const float* at(uint32_t x, uint32_t y) const { return &rgba[(size_t{y} * width + x) * 4]; }
};

// The store rule of a format: RGBA8 = clamp to [0,1] then round to nearest of 255 steps
// (D3D9 / Vulkan UNORM conversion); RGBA16F = round to nearest even half float (overflow to
// inf, NaN kept); RGBA32F = unchanged. These are the exact rules; lavapipe's differ
// (tierlift/rounding/rounding.h has both).
float quantize(Format f, float value);
void quantize_in_place(Image& image);

} // namespace tierlift::img
