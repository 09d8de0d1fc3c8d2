// The ideal glow and the distance of a run to it (docs/design.md, "ideal glow"): the scene's
// glow sources (rgb × alpha) convolved with the profile's continuous kernel at full
// resolution, in double — no downsample, no truncation, no quantisation, no half-texel shift.
//
// The scene is piecewise constant (texel j covers [j, j + 1)), so the continuous convolution
// sampled at pixel centre i is exact as a sum over texels with cell weights
//   K(d) = ∫_{d−½}^{d+½} k(x) dx,   d = i − j,
// where k is the profile's continuous 1D kernel (each term normalised to its weight over the
// whole line): a Gaussian gives weight · (Φ((d + ½)/σ) − Φ((d − ½)/σ)); the sawtooth
// 1 − frac(|x|/period) on |x| ≤ radius is integrated per cell by the midpoint rule on 64
// sub-cells and normalised by its integral over the line. Cells are kept out to 8σ (the
// Gaussian mass beyond is below 1.3e-15) and to the sawtooth's radius; the 2D kernel is the
// product of the two axes, as the glow blurs x then y.
#pragma once

#include <cstdint>
#include <vector>

#include "tierlift/effects/glow/blur_profile.h"
#include "tierlift/image/image.h"

namespace tierlift::effects {

// An RGB image in double (3 values a pixel, row-major, top row first).
struct RgbImage {
  uint32_t width = 0, height = 0;
  std::vector<double> rgb;
  double* at(uint32_t x, uint32_t y) { return &rgb[(size_t{y} * width + x) * 3]; }
  const double* at(uint32_t x, uint32_t y) const { return &rgb[(size_t{y} * width + x) * 3]; }
};

// The cell weights K(−R..R) of the profile's continuous kernel at full resolution
// (max_taps is ignored: the ideal is not cut short). Empty when the profile has no term.
std::vector<double> ideal_kernel(const BlurProfile& profile);

// rgb × alpha of every pixel, in double (what the extract pass computes, unquantised).
RgbImage glow_sources(const img::Image& scene);

// The sources convolved with ideal_kernel on x, then on y (clamped at nothing: outside the
// image is 0, as the glow's textures are).
RgbImage ideal_glow(const RgbImage& sources, const BlurProfile& profile);

// The glow texture as the composite reads it at each full-resolution pixel: bilinear, in
// double, at texel position (i + ½)/n − ½ on each axis, clamped to the edge (n = downsample).
RgbImage upsample_glow(const img::Image& glow, uint32_t width, uint32_t height, unsigned n);

// The final frame the ideal glow gives: scene rgb + intensity × glow (not clamped).
RgbImage ideal_final(const img::Image& scene, const RgbImage& glow, double intensity);

// The image as a display shows it: every value clamped to [0, 1] (NaN stays NaN, so it still
// counts as far off). The report measures the final frame so on both sides: a bright light
// plus its glow above 1 is white on screen whatever the target format stores, and without
// the clamp every 8-bit or ps.1.x configuration would carry that same saturation error
// (0.0885 RMSE on the built-in scene at intensity 3), hiding what its own choices cost.
RgbImage displayed(RgbImage image);

// rgb of an image, in double.
RgbImage rgb_of(const img::Image& image);

// Distance of `actual` to `ideal` over every rgb value: the largest |difference|, the root
// mean square, and the share of pixels whose largest channel difference is above 1/255.
struct IdealError {
  double max_abs = 0, rmse = 0, share_off = 0;
};
IdealError error_against(const RgbImage& ideal, const RgbImage& actual);

} // namespace tierlift::effects
