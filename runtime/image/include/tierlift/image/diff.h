// Two images compared for a person (`tierlift diff`): the figures of img::compare (max abs,
// RMSE, identical share), the share of pixels off by more than a threshold, the worst pixels
// with both values, a heat map, and a verdict against limits the caller gives.
//
// A pixel's difference is the largest of its four channel differences (img::channel_difference:
// NaN equals NaN, a non-finite value against anything else is an infinite difference).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/image/compare.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"

namespace tierlift::img {

struct DiffOptions {
  // A pixel is "off" when its difference exceeds off_steps / 255 (one 8-bit step by default).
  // The comparison allows the float noise of two stored k/255 values (relative 1e-4, as
  // img::judge does), so a difference of exactly off_steps steps is not off.
  double off_steps = 1;
  size_t worst_count = 5; // how many of the worst pixels to list
};

struct PixelDifference {
  uint32_t x = 0, y = 0;
  std::array<float, 4> a{}, b{}; // RGBA of each image
  double difference = 0;         // largest channel difference
  int channel = 0;               // where it is (0..3 = R, G, B, A)
};

struct Diff {
  Comparison comparison; // max abs, RMSE, identical share (img::compare)
  double off_steps = 1;  // DiffOptions::off_steps used
  uint64_t off_pixels = 0;
  double off_share = 0; // off_pixels / pixels (0 for an empty image)
  // The worst pixels, largest difference first; equal differences in row-major order.
  // Pixels without a difference are never listed.
  std::vector<PixelDifference> worst;
};

// Sizes must match; otherwise a failure (rule "size") that gives both sizes.
ir::Result<Diff> diff_images(const Image& a, const Image& b, const DiffOptions& options = {});

// Limits a diff must stay within; unset limits are not checked.
struct DiffLimits {
  std::optional<double> max_abs;       // largest channel difference allowed
  std::optional<double> max_off_share; // share of off pixels allowed, 0..1
};
// pass, and one line naming each limit and whether it held.
Verdict judge_diff(const Diff& d, const DiffLimits& limits);

// The heat map of a − b: each pixel's difference d as a colour, opaque RGBA8. 0 is black, and
// d / scale runs black → red → yellow → white (reached at scale); a non-finite difference is
// magenta. `scale` ≤ 0 takes the largest finite difference (the worst pixel is white).
Image heat_map(const Image& a, const Image& b, double scale = 0);

} // namespace tierlift::img
