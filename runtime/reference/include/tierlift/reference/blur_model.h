// The analytic model of a blur pass, in double: the exact image a full-screen quad with
// the given taps must produce, from the sample positions of the conventions (pixel centre,
// filter, addressing, sub-texel precision) and the store rule of the target format. It
// shares no code with the CPU device, so agreement between the two means something.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/image/io.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/reference/taps.h"

namespace tierlift::ref {

enum class Filter { Point, Linear };
// D3DTADDRESS modes (d3d9-isa.md §10.2).
enum class Address { Wrap, Mirror, Clamp, Border, MirrorOnce };

struct SamplerModel {
  Filter filter = Filter::Linear;
  Address address_u = Address::Clamp, address_v = Address::Clamp;
  std::array<double, 4> border{0, 0, 0, 0}; // BORDER colour (D3D9 default 0x00000000)
};

struct PassModel {
  ir::Conventions conventions; // pixel_center and subtexel_bits are used
  SamplerModel sampler;
  uint32_t target_width = 0, target_height = 0; // 0 = the source's size
  img::Format target_format = img::Format::RGBA32F;
  // Texture coordinates of the full-screen quad at screen x = 0 / x = W (and y).
  double u0 = 0, v0 = 0, u1 = 1, v1 = 1;
};

// The texture coordinate of pixel (i, j)'s sample point, before any tap offset:
// u = u0 + (u1 − u0)·x/W with x = i (D3D9) or i + 0.5 (modern).
std::array<double, 2> pixel_uv(uint32_t i, uint32_t j, uint32_t width, uint32_t height,
                               const PassModel& model);

// One filtered read at (u, v), in double. Linear: i0 = floor(u·N − 0.5), α = frac, with
// positions within 1e-9 texel of a texel centre snapped onto it (the tap is meant to hit
// it; double rounding must not turn an exact read into a 1e-16 blend); α quantised to
// subtexel_bits (round to nearest) when > 0. Point: floor(u·N).
std::array<double, 4> sample(const img::Image& texture, double u, double v,
                             const SamplerModel& sampler, int subtexel_bits = 0);
// The texel index an address mode maps i to, or -1 for "border colour".
int64_t address_texel(int64_t i, int64_t n, Address mode);

// The blur pass: pixel = Σ_k weight_k · sample(uv + offset_k), stored with img::quantize.
img::LoadResult blur_pass(const std::vector<Tap>& taps, const img::Image& source,
                          const PassModel& model);

// A tap as a whole-texel displacement: the plain discrete convolution's view.
struct TexelTap {
  int64_t dx = 0, dy = 0;
  std::array<double, 4> weight{};
};
// The texels the author meant: offset·size rounded down (+1e-6 slack), so (k + 0.5)/W
// (the article's half-texel offsets) and k/W (without them) both mean tap k.
std::vector<TexelTap> intended_texel_taps(const std::vector<Tap>& taps, uint32_t width,
                                          uint32_t height);
// out(i, j) = Σ_k w_k · T[addr(i + dx_k), addr(j + dy_k)], stored with img::quantize.
// Target and source sizes must be equal.
img::LoadResult discrete_convolution(const std::vector<TexelTap>& taps, const img::Image& source,
                                     const PassModel& model);

// The corner model: a tap whose sample point lies on a texel centre reads that texel; one
// that lies half a texel off (on an edge or a corner between texels, as a D3D9 quad without
// the half-texel offset does) reads the plain mean of the 2 or 4 texels around it. Written
// from that rule alone (no bilinear weights). Positions are classified with a tolerance of
// 1e-5 texel (offsets come from float constants); any other position is an error. Target and
// source sizes must be equal. Stored with img::quantize.
img::LoadResult corner_model(const std::vector<Tap>& taps, const img::Image& source,
                             const PassModel& model);

// What the corner model predicts the no-half-texel pass differs from the plain convolution
// by: corner_model − discrete_convolution(intended_texel_taps), per value, unquantised
// (RGBA32F image of signed differences), and its largest magnitude.
struct CornerPrediction {
  img::Image difference;
  double max_abs = 0;
  double rmse = 0;
};
std::optional<CornerPrediction> predict_corner_difference(const std::vector<Tap>& taps,
                                                          const img::Image& source,
                                                          const PassModel& model,
                                                          std::string* error = nullptr);

} // namespace tierlift::ref
