// NUMERICS.md rule 37: what the Llvmpipe sampler reads at coordinates llvmpipe cannot address
// (±inf, NaN, u·N overflowing) under WRAP, MIRROR and BORDER. The expected texels follow from
// the rule by hand: llvmpipe's float-to-int conversion gives INT_MIN there and its bilinear
// weight x − floor(x) is NaN. Measured on lavapipe (Mesa 22.3) with `tierlift run --backend
// both` on 8 × 8 and 13 × 7 RGBA32F textures.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNan = std::numeric_limits<float>::quiet_NaN();

// Texel (x, y) holds (x, y, 100, 1).
std::shared_ptr<const img::Image> numbered(uint32_t w, uint32_t h) {
  auto im = std::make_shared<img::Image>(w, h, img::Format::RGBA32F);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      float* p = im->at(x, y);
      p[0] = static_cast<float>(x);
      p[1] = static_cast<float>(y);
      p[2] = 100;
      p[3] = 1;
    }
  return im;
}

SamplerState sampler(Filter f, AddressMode m) {
  SamplerState s;
  s.filter = f;
  s.address_u = s.address_v = m;
  s.border_color = {0.25f, 0.5f, 0.75f, 1.0f};
  return s;
}

Vec4 read(uint32_t w, uint32_t h, Filter f, AddressMode m, float u, float v) {
  return sample_texture_llvmpipe(*numbered(w, h), sampler(f, m), u, v, 0);
}

void expect_all_nan(const Vec4& r) {
  for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isnan(r[c])) << "channel " << c << ": " << r[c];
}

// Wrap at a power-of-two size: POINT reads texel INT_MIN & 7 = 0, LINEAR a NaN weight; 3e38·8
// overflows to inf, so it counts as unaddressable too.
TEST(UnaddressableCoords, WrapPowerOfTwo) {
  for (float u : {kInf, -kInf, kNan, 3e38f}) {
    const Vec4 p = read(8, 8, Filter::Point, AddressMode::Wrap, u, 0.5f);
    EXPECT_EQ(p[0], 0.0f) << u;
    EXPECT_EQ(p[1], 4.0f) << u; // v = 0.5 is row 4
    expect_all_nan(read(8, 8, Filter::Linear, AddressMode::Wrap, u, 0.5f));
  }
}

// Wrap at 13 × 7: llvmpipe takes fract(u) first (NaN for a non-finite u) and clamps it to
// just below 1, so POINT reads the last texel; LINEAR a NaN weight. A finite 3e38 has
// fraction 0: an ordinary coordinate, not this rule.
TEST(UnaddressableCoords, WrapOtherSizes) {
  for (float u : {kInf, -kInf, kNan}) {
    EXPECT_EQ(read(13, 7, Filter::Point, AddressMode::Wrap, u, 0.5f)[0], 12.0f) << u;
    EXPECT_EQ(read(13, 7, Filter::Point, AddressMode::Wrap, 0.5f, u)[1], 6.0f) << u;
    expect_all_nan(read(13, 7, Filter::Linear, AddressMode::Wrap, u, 0.5f));
  }
}

// Mirror: the mirrored coordinate 2·(u/2 − round(u/2)) is NaN, which llvmpipe sends to 0: texel
// 0 for POINT and LINEAR (both taps texel 0), at every size.
TEST(UnaddressableCoords, MirrorReadsTexelZero) {
  for (float u : {kInf, -kInf, kNan})
    for (Filter f : {Filter::Point, Filter::Linear}) {
      const Vec4 r = read(13, 7, f, AddressMode::Mirror, u, 0.5f);
      EXPECT_EQ(r[0], 0.0f) << u;
      EXPECT_EQ(r[1], 3.0f) << u; // v = 0.5: row 3 (POINT), rows 3 and 3 (LINEAR)
    }
}

// Border: POINT reads the border colour (NaN included, which the ordinary rule sends to texel
// 0), LINEAR a NaN weight.
TEST(UnaddressableCoords, Border) {
  for (float u : {kInf, -kInf, kNan, 3e38f}) {
    const Vec4 p = read(8, 8, Filter::Point, AddressMode::Border, u, 0.5f);
    EXPECT_EQ(p[0], 0.25f) << u;
    EXPECT_EQ(p[3], 1.0f) << u;
    expect_all_nan(read(8, 8, Filter::Linear, AddressMode::Border, u, 0.5f));
  }
}

// The ordinary rule still holds for finite coordinates and for CLAMP.
TEST(UnaddressableCoords, FiniteAndClampUnchanged) {
  EXPECT_EQ(read(8, 8, Filter::Point, AddressMode::Wrap, 1.25f, 0.5f)[0], 2.0f);
  EXPECT_EQ(read(8, 8, Filter::Linear, AddressMode::Clamp, kInf, 0.5f)[0], 7.0f);
  EXPECT_EQ(read(8, 8, Filter::Point, AddressMode::Clamp, -kInf, 0.5f)[0], 0.0f);
}

} // namespace
} // namespace tierlift::cpu
