// codegen::choose_unorm8_decode: the cheapest decode that turns a device's RGBA8 values into
// k/255.0f for all 256 levels, checked on value sets computed here: exact values, the two
// ways lavapipe is known to convert, values an ulp off where no cheaper decode helps, and
// values too far off for any. That the chosen decode's SPIR-V computes what decode_on_host
// does is checked on the device (tests/vulkan/resident_point_fetch_test.cpp, every level).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tierlift/codegen/unorm8_decode.h"

using namespace tierlift;
using codegen::Unorm8Decode;

namespace {

// One fp32 operation each (no contraction, no excess precision).
float mul(float a, float b) {
  volatile float r = a * b;
  return r;
}

std::vector<float> levels(float (*convert)(int k)) {
  std::vector<float> v(256);
  for (int k = 0; k < 256; ++k) v[static_cast<size_t>(k)] = convert(k);
  return v;
}

float exact(int k) {
  return static_cast<float>(k / 255.0);
}
// lavapipe's two known conversions: k times fl(1/255), and k/256 (exact) times fl(256/255).
float times_reciprocal(int k) {
  return mul(static_cast<float>(k), 1.0f / 255.0f);
}
float via_256(int k) {
  return mul(static_cast<float>(k) / 256.0f, 256.0f / 255.0f);
}

TEST(Unorm8Decode, ExactValuesNeedNone) {
  const std::vector<float> v = levels(exact);
  EXPECT_EQ(codegen::choose_unorm8_decode(v), Unorm8Decode::None);
}

TEST(Unorm8Decode, LavapipesValuesTakeTwoMultiplies) {
  for (auto convert : {times_reciprocal, via_256}) {
    const std::vector<float> v = levels(convert);
    int off = 0;
    for (int k = 0; k < 256; ++k) off += v[static_cast<size_t>(k)] != exact(k);
    EXPECT_EQ(off, 126); // what lavapipe's float copy was measured to get wrong
    EXPECT_EQ(codegen::choose_unorm8_decode(v), Unorm8Decode::TwoMultiply);
    for (int k = 0; k < 256; ++k)
      ASSERT_EQ(codegen::decode_on_host(Unorm8Decode::TwoMultiply, v[static_cast<size_t>(k)]),
                exact(k))
          << "level " << k;
  }
}

TEST(Unorm8Decode, OtherValuesAnUlpOffTakeTheGeneralDecode) {
  // Exact but for level 3, one ulp up: the two multiplies do not map exact values onto
  // themselves, so only the general decode is left.
  std::vector<float> v = levels(exact);
  v[3] = std::nextafter(v[3], 1.0f);
  EXPECT_EQ(codegen::choose_unorm8_decode(v), Unorm8Decode::RoundAndRebuild);
  // Several reads of each level (four channels): one bad read decides.
  std::vector<float> four;
  for (int c = 0; c < 4; ++c) {
    const std::vector<float> l = levels(c == 2 ? times_reciprocal : via_256);
    four.insert(four.end(), l.begin(), l.end());
  }
  EXPECT_EQ(codegen::choose_unorm8_decode(four), Unorm8Decode::TwoMultiply);
  four[2 * 256 + 7] = std::nextafter(four[2 * 256 + 7], 0.0f);
  EXPECT_EQ(codegen::choose_unorm8_decode(four), Unorm8Decode::RoundAndRebuild);
}

TEST(Unorm8Decode, ValuesTooFarOffHaveNoDecode) {
  // Level 200 read as 201/255: a device that returns another level entirely.
  std::vector<float> v = levels(exact);
  v[200] = exact(201);
  EXPECT_EQ(codegen::choose_unorm8_decode(v), std::nullopt);
  // Not a whole number of level sets.
  EXPECT_EQ(codegen::choose_unorm8_decode(std::vector<float>(255, 0.0f)), std::nullopt);
  EXPECT_EQ(codegen::choose_unorm8_decode(std::vector<float>{}), std::nullopt);
}

} // namespace
