// The sRGB transfer functions of rounding.h (NUMERICS.md S1, S3) against IEC 61966-2-1's closed
// form evaluated here in long double, independently of the tables: every decode level, every
// encode threshold and the floats on either side of it, and the encoded value through both
// RGBA8 store rules.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/rounding/rounding.h"

namespace {

namespace rounding = tierlift::rounding;

long double decode(long double c) {
  return c <= 0.04045L ? c / 12.92L : std::pow((c + 0.055L) / 1.055L, 2.4L);
}
long double encode(long double l) {
  return l <= 0.0031308L ? l * 12.92L : 1.055L * std::pow(l, 1.0L / 2.4L) - 0.055L;
}
// The nearest byte to 255·encode(l), l clamped to [0, 1], NaN → 0.
int encode_byte(float l) {
  if (!(l > 0)) return 0;
  if (l >= 1) return 255;
  return static_cast<int>(std::floor(255.0L * encode(l) + 0.5L));
}

// Each level is the closed form at k/255 rounded once to float (S1's documented bound: half an
// ulp of the float): the nearest float to the long double value.
TEST(SrgbRule, DecodeOfAll256LevelsIsTheClosedFormRounded) {
  const std::array<float, 256>& levels = rounding::srgb_decode_levels();
  for (int k = 0; k < 256; ++k) {
    const long double exact = decode(k / 255.0L);
    EXPECT_EQ(levels[k], static_cast<float>(exact)) << k;
    const float ulp = std::nextafter(levels[k], 2.0f) - levels[k];
    EXPECT_LE(std::fabs(static_cast<long double>(levels[k]) - exact), ulp / 2.0L) << k;
  }
  EXPECT_EQ(levels[0], 0.0f);
  EXPECT_EQ(levels[255], 1.0f);
  EXPECT_FLOAT_EQ(levels[128], 0.2158605f); // ((128/255 + 0.055)/1.055)^2.4
}

// Threshold k is the first float whose nearest byte is k: it encodes to k, the float below it
// to k − 1.
TEST(SrgbRule, EncodeThresholdsSplitTheBytes) {
  const std::array<float, 256>& t = rounding::srgb_encode_thresholds();
  for (int k = 1; k < 256; ++k) {
    EXPECT_EQ(encode_byte(t[k]), k) << k;
    EXPECT_EQ(encode_byte(std::nextafter(t[k], -1.0f)), k - 1) << k;
    EXPECT_EQ(rounding::srgb_encode_byte(t[k]), k) << k;
    EXPECT_EQ(rounding::srgb_encode_byte(std::nextafter(t[k], -1.0f)), k - 1) << k;
  }
}

TEST(SrgbRule, EncodeByteIsTheNearestByteOfTheClosedForm) {
  for (int i = 0; i <= 100000; ++i) {
    const float l = static_cast<float>(i) / 100000.0f;
    ASSERT_EQ(rounding::srgb_encode_byte(l), encode_byte(l)) << l;
  }
  const float inf = std::numeric_limits<float>::infinity();
  for (float v :
       {-inf, -1.0f, -0.0f, 0.0f, 1e-40f, 1.0f, 2.0f, inf, std::numeric_limits<float>::quiet_NaN()})
    EXPECT_EQ(rounding::srgb_encode_byte(v), encode_byte(v)) << v;
  EXPECT_EQ(rounding::srgb_encode_byte(0.5f), 188); // 255·0.735357 = 187.52
  EXPECT_EQ(rounding::srgb_encode_byte(0.2158605f), 128);
}

// The encoded colour reaches the target as the byte under both RGBA8 store rules, and decoding
// the byte and encoding it again gives the byte back.
TEST(SrgbRule, EncodedValueStoresItsByteAndRoundTrips) {
  for (int k = 0; k < 256; ++k) {
    const float v = static_cast<float>(k) * rounding::kSrgbByteScale;
    EXPECT_EQ(rounding::unorm8_llvmpipe(v), k) << k;
    EXPECT_EQ(rounding::unorm8_nearest(v), static_cast<float>(k) / 255.0f) << k;
    EXPECT_EQ(rounding::srgb_encode_byte(rounding::srgb_decode_levels()[k]), k) << k;
  }
}

} // namespace
