// analytic::half_toward_zero_model against values worked out by hand from the IEEE 754 binary16
// definition (10 fraction bits; halves in [2^k, 2^(k+1)) are 2^(k−10) apart, 2^-24 below
// 2^-14; largest finite 65504), the RGBA16F store of the analytic model.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/analytic/blur_model.h"

namespace analytic = tierlift::analytic;

TEST(HalfTowardZeroModel, NormalValuesDropTheBitsBelowTheTenthFractionBit) {
  EXPECT_EQ(analytic::half_toward_zero_model(1.0), 1.0f);
  // 1 + 2^-10 + 2^-12: the 2^-12 is below the spacing 2^-10 at 1.
  EXPECT_EQ(analytic::half_toward_zero_model(1.0 + 0x1p-10 + 0x1p-12), 1.0f + 0x1p-10f);
  // Just below 2: 1 + 1023/1024 is the largest half there.
  EXPECT_EQ(analytic::half_toward_zero_model(2.0 - 0x1p-30), 2.0f - 0x1p-10f);
  // 0.1 = 1.6·2^-4: spacing 2^-14, ⌊0.1·2^14⌋ = ⌊1638.4⌋ = 1638.
  EXPECT_EQ(analytic::half_toward_zero_model(0.1), 1638.0f * 0x1p-14f);
  // Toward zero on the negative side too: −(1 + 2^-11) → −1.
  EXPECT_EQ(analytic::half_toward_zero_model(-(1.0 + 0x1p-11)), -1.0f);
  EXPECT_EQ(analytic::half_toward_zero_model(-0.1), -1638.0f * 0x1p-14f);
}

TEST(HalfTowardZeroModel, SubnormalsAreMultiplesOfTwoToTheMinus24) {
  EXPECT_EQ(analytic::half_toward_zero_model(1.5 * 0x1p-24), 0x1p-24f);
  EXPECT_EQ(analytic::half_toward_zero_model(0x1p-25), 0.0f);
  // 2^-14 − 2^-30 lies below the smallest normal: ⌊(2^-14 − 2^-30)·2^24⌋ = 1023.
  EXPECT_EQ(analytic::half_toward_zero_model(0x1p-14 - 0x1p-30), 1023.0f * 0x1p-24f);
  EXPECT_EQ(analytic::half_toward_zero_model(0x1p-14), 0x1p-14f);
}

TEST(HalfTowardZeroModel, LargeValuesStopAtTheLargestHalf) {
  // Spacing 32 in [32768, 65536): 65519 → 65504, and beyond the range the largest half.
  EXPECT_EQ(analytic::half_toward_zero_model(65519.0), 65504.0f);
  EXPECT_EQ(analytic::half_toward_zero_model(65535.0), 65504.0f);
  EXPECT_EQ(analytic::half_toward_zero_model(1e9), 65504.0f);
  EXPECT_EQ(analytic::half_toward_zero_model(-1e9), -65504.0f);
  EXPECT_EQ(analytic::half_toward_zero_model(40000.0 + 31.0), 40000.0f); // 40000 = 1250·32
}

TEST(HalfTowardZeroModel, SpecialValuesStay) {
  EXPECT_TRUE(std::isnan(analytic::half_toward_zero_model(std::nan(""))));
  EXPECT_EQ(analytic::half_toward_zero_model(INFINITY), INFINITY);
  EXPECT_EQ(analytic::half_toward_zero_model(-INFINITY), -INFINITY);
  EXPECT_TRUE(std::signbit(analytic::half_toward_zero_model(-0.0)));
  EXPECT_TRUE(std::signbit(analytic::half_toward_zero_model(-0x1p-26))); // −0, toward zero
}
