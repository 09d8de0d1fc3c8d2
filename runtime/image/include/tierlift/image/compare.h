// Comparing two images and judging the difference against docs/design.md's agreement targets.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"

namespace tierlift::img {

struct Comparison {
  uint32_t width = 0, height = 0;
  std::array<double, 4> max_abs{}; // per channel R, G, B, A
  std::array<double, 4> rmse{};    // per channel
  double max_abs_all = 0;          // over all channels
  double rmse_all = 0;             // over all channels
  uint64_t pixels = 0;
  uint64_t identical_pixels = 0;     // all four channels equal (NaN equals NaN)
  double identical_share = 1;        // identical_pixels / pixels (1 for empty images)
  uint32_t worst_x = 0, worst_y = 0; // where max_abs_all occurs
  int worst_channel = 0;
  double full_scale = 1;            // max(1, largest finite |value| in either image)
  bool non_finite_mismatch = false; // NaN or ±inf in one image and not the other
};

// |a − b| of one channel value as compare() counts it: 0 for equal values (NaN equals NaN),
// +inf when either is NaN or infinite and they are not equal.
double channel_difference(float a, float b);

// Differences a − b. Sizes must match; otherwise a failure that says why. A value that is
// NaN or infinite in one image but not equal in the other counts as an infinite difference.
ir::Result<Comparison> compare(const Image& a, const Image& b);

// Agreement targets per target format (docs/design.md "Three ways, one answer"):
//   RGBA32F: max abs ≤ 1e-5 × full scale.
//   RGBA16F: max abs ≤ 2^-10 × full scale (one half-float step at the top of the scale;
//            docs/design.md sets no figure, this is ours).
//   RGBA8:   max abs ≤ 1 LSB (1/255) and ≥ 99.9 % of pixels identical.
struct Tolerance {
  double max_abs_relative = 1e-5; // × full scale
  double min_identical_share = 0; // 0 = not checked
};
Tolerance agreement_tolerance(Format target);

struct Verdict {
  bool pass = false;
  std::string summary; // one line: figures and the rule applied
};
Verdict judge(const Comparison& c, Format target);
Verdict judge(const Comparison& c, const Tolerance& t);

// "max abs 1.2e-07 (R at 3,4), rmse 3.0e-08, identical 99.95 %"
std::string describe(const Comparison& c);

} // namespace tierlift::img
