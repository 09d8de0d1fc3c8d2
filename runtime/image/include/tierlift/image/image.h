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

// Largest width or height tierlift accepts anywhere (images, targets, textures).
inline constexpr uint32_t kMaxDimension = 16384;

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
// inf, NaN kept); RGBA32F = unchanged.
float quantize(Format f, float value);
void quantize_in_place(Image& image);

// The float→UNORM8 conversion of lavapipe (Mesa llvmpipe) when it writes a colour
// attachment: NaN and values ≤ 0 give 0, values ≥ 1 give 255, otherwise the float product
// fl32(value·255) rounded to the nearest integer with ties to even (llvmpipe multiplies by
// 255 in float and converts with the SSE/AVX cvtps2dq instruction, whose default rounding is
// nearest-even; measured identical on Mesa 22.3, x86-64). It differs from quantize's exact
// rule for only 128 floats in [0, 1]: those whose product, a hair off a midpoint k + ½, rounds
// onto it in float and then goes to the even side (fl32(0.5/255) = 0.00196078443 stores 0
// here, 1 in quantize). NUMERICS.md rule 34.
// quantize stays the exact rule (the analytic model uses it); the CPU device uses this one
// under ir::Rounding::Llvmpipe.
uint8_t unorm8_llvmpipe(float value);

// The float→half conversion of lavapipe when it writes an RGBA16F attachment: rounding
// toward zero (measured: every one of 65,536 probe values matched this rule, none matched
// nearest-even where they differ), so a finite value beyond 65504 stores ±65504; NaN and
// ±inf stay. quantize keeps nearest-even (the exact rule); the CPU device uses this one
// under ir::Rounding::Llvmpipe. NUMERICS.md rule 35.
// Takes a double so that the analytic model rounds its exact value (no float on the way).
float half_toward_zero(double value);

// The spacing of binary16 values at magnitude `a` (finite, ≥ 0): 2^-24 below 2^-14
// (subnormals), else 2^(e−10) in [2^e, 2^(e+1)). Dividing by it is exact (a power of two),
// so every half rounding is a rounding of a / half_step(a) to an integer.
double half_step(double a);

} // namespace tierlift::img
