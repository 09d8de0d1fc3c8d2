// The analytic model of a blur pass, in double: the exact image a full-screen quad with
// the given taps must produce, from the sample positions of the conventions (pixel centre,
// filter, addressing, sub-texel precision) and the store rule of the target format. It
// shares no arithmetic with the CPU device, so agreement between the two means something;
// what the two share is the D3D9 address rule (tierlift/pass/addressing.h), a table of
// index facts rather than arithmetic.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/analytic/taps.h"
#include "tierlift/image/image.h"
#include "tierlift/image/io.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/pass/addressing.h"

namespace tierlift::analytic {

enum class Filter { Point, Linear };
// D3DTADDRESS modes and their rule are the device-neutral pass state's (one definition).
using pass::AddressMode;

struct SamplerModel {
  Filter filter = Filter::Linear;
  AddressMode address_u = AddressMode::Clamp, address_v = AddressMode::Clamp;
  std::array<double, 4> border{0, 0, 0, 0}; // BORDER colour (D3D9 default 0x00000000)
};

// How an RGBA8 store rounds a value exactly half-way between two steps. D3D9 and Vulkan
// leave it open ("one of the two nearest"); D3D10's rule adds ½ and truncates (HalfUp, the
// rule of img::quantize); lavapipe rounds to even (rounding::unorm8_llvmpipe). Ties are common
// in the glow: bilinear midpoints and power-of-two weights average 8-bit texels exactly.
enum class Unorm8Ties { HalfUp, ToEven };

// The value a texel of `image` holds, in double: RGBA8 texels are exactly k/255 (the float
// in the image is only the nearest float to it), other formats their float.
double texel_value(const img::Image& image, uint32_t x, uint32_t y, int channel);

// The store rule of a target format, from an exact (double) value: RGBA8 clamps to [0, 1]
// (NaN → 0) and rounds to the nearest k/255, a value within 1e-9 of a step of a midpoint
// being a tie that goes by `ties` (the tolerance absorbs double rounding of sums that are
// exact midpoints); other formats: img::quantize of the value as float.
float store_value(img::Format format, double value, Unorm8Ties ties);

// RGBA16F as lavapipe stores it (NUMERICS.md rule 35): the half float toward zero from the
// value, finite values beyond 65504 as ±65504, ±inf and NaN kept. The model's own rounding,
// written from the IEEE 754 binary16 definition (it shares nothing with img::).
float half_toward_zero_model(double value);

struct PassModel {
  ir::Conventions conventions; // pixel_center and subtexel_bits are used
  Unorm8Ties unorm8_ties = Unorm8Ties::HalfUp;
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
// positions within snap_tolerance(N) texel of a texel centre or of the midpoint between two
// texels snapped onto it; α quantised to subtexel_bits (round to nearest) when > 0.
// Point: floor(u·N) (positions within 1e-9 of a texel edge snapped onto it).
// Why snap: a pass's taps are meant to hit centres (the half-texel rule) or midpoints (the
// downsample's averaging reads, taps without the half texel), but its coordinates come from
// float constants (k/W is rarely a float) and devices interpolate them in float, so the
// position is off by up to a few ulps of u times N texels, and a device cannot tell where
// within that it is. At a midpoint that matters beyond its size: averaging two 8-bit texels
// lands exactly on a rounding tie, and a 1e-7 texel shift decides which way the store
// rounds. The model takes the meant position; the shift it drops moves a value by at most
// snap·|texel difference|, far below every RGBA32F target at sizes up to kMaxDimension
// (16384 · 2^-21 = 0.008 texel would not be; at 1920 texels it is 0.0009).
double snap_tolerance(uint32_t texels); // max(1e-9, N · 2^-21) texels
std::array<double, 4> sample(const img::Image& texture, double u, double v,
                             const SamplerModel& sampler, int subtexel_bits = 0);
// One filtered read at a float coordinate as the devices take it (quad_coords.h gives the
// coordinate): point: texel ⌊fl32(u·N)⌋; linear: x = fl32(u·N) − ½ in fp32 (clamp addressing
// clamps u·N to N and x to 0 first), weights 1 − α and α with α = x − ⌊x⌋ (exact in fp32,
// quantised when subtexel_bits > 0); weights and the weighted sum in double. No snapping:
// the position is the devices' own.
// `texel_max`, when given, receives the largest |texel| per channel among those read.
std::array<double, 4> sample_at_float(const img::Image& texture, float u, float v,
                                      const SamplerModel& sampler, int subtexel_bits = 0,
                                      std::array<double, 4>* texel_max = nullptr);
// The same read in the devices' own fp32 arithmetic, for the few values the double model
// cannot place on one side of an RGBA8 rounding boundary (linear_pass.h): the texels' floats;
// bilinear as lerp(β, lerp(α, t00, t10), lerp(α, t01, t11)) with lerp(a, x, y) =
// fma(a, y − x, x), the filter unit's arithmetic in lavapipe's float-texture path.
std::array<float, 4> sample_fp32(const img::Image& texture, float u, float v,
                                 const SamplerModel& sampler, int subtexel_bits = 0);
// The blur pass: pixel = Σ_k weight_k · sample(scale_k·uv + offset_k), one texture (every
// tap's sampler stage reads `source`), stored with img::quantize. linear_pass.h has the
// general form (several textures, blending, ps_1_x ranges).
img::ImageResult blur_pass(const std::vector<Tap>& taps, const img::Image& source,
                           const PassModel& model);

} // namespace tierlift::analytic
