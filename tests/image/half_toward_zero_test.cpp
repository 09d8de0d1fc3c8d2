// rounding::half_toward_zero: lavapipe's RGBA16F store rule (NUMERICS.md rule 35). Expected
// values by hand from the binary16 layout: 10 fraction bits, steps of 2^(e-10) in [2^e, 2^(e+1)).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/image/image.h"
#include "tierlift/rounding/rounding.h"

namespace {

using tierlift::img::Format;
using tierlift::img::quantize;
using tierlift::rounding::half_toward_zero;

TEST(HalfTowardZero, TruncatesWhereNearestEvenRoundsUp) {
  // In [1, 2) the step is 2^-10. 1 + 0.75·2^-10 lies 3/4 of a step above 1.
  const float x = 1.0f + 0.75f * 0x1p-10f;
  EXPECT_EQ(half_toward_zero(x), 1.0f);
  EXPECT_EQ(quantize(Format::RGBA16F, x), 1.0f + 0x1p-10f);
  EXPECT_EQ(half_toward_zero(-x), -1.0f); // toward zero, not toward −inf
  // 0.3 lies in [0.25, 0.5): step 2^-12; 0.3·4096 = 1228.8 → 1228.
  EXPECT_EQ(half_toward_zero(0.3f), 1228.0f * 0x1p-12f);
}

TEST(HalfTowardZero, ExactHalvesAndSubnormalsStay) {
  for (float v : {0.0f, 1.0f, 0.5f, 2048.0f, 65504.0f, 0x1p-24f, 3.0f * 0x1p-24f})
    EXPECT_EQ(half_toward_zero(v), v) << v;
  EXPECT_EQ(half_toward_zero(0x1p-25f), 0.0f); // below the smallest subnormal half
  EXPECT_EQ(half_toward_zero(1.9f * 0x1p-24f), 0x1p-24f);
}

TEST(HalfTowardZero, NeverOverflowsAndKeepsSpecials) {
  EXPECT_EQ(half_toward_zero(70000.0f), 65504.0f);
  EXPECT_EQ(half_toward_zero(-1e30f), -65504.0f);
  EXPECT_EQ(quantize(Format::RGBA16F, 70000.0f), std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isinf(half_toward_zero(std::numeric_limits<float>::infinity())));
  EXPECT_TRUE(std::isnan(half_toward_zero(std::nanf(""))));
}

} // namespace
