// Blend modes and the store rule (docs/design.md "Conventions": quantisation happens at store).
#include <gtest/gtest.h>

#include "tierlift/cpu/draw.h"

namespace tierlift::cpu {
namespace {

const img::Format F32 = img::Format::RGBA32F, U8 = img::Format::RGBA8;

TEST(Blend, EachModeOnFloatTarget) {
  const Vec4 src{0.5f, 0.25f, 2.0f, 0.25f}, dst{0.5f, 0.5f, 1.0f, 1.0f};
  EXPECT_EQ(blend_and_store(BlendMode::Replace, F32, src, dst), src);
  EXPECT_EQ(blend_and_store(BlendMode::OneOne, F32, src, dst), (Vec4{1.0f, 0.75f, 3.0f, 1.25f}));
  // src·a + dst with a = 0.25
  EXPECT_EQ(blend_and_store(BlendMode::SrcAlphaOne, F32, src, dst),
            (Vec4{0.625f, 0.5625f, 1.5f, 1.0625f}));
  // src·a + dst·(1 − a)
  EXPECT_EQ(blend_and_store(BlendMode::SrcAlphaInvSrcAlpha, F32, src, dst),
            (Vec4{0.5f, 0.4375f, 1.25f, 0.8125f}));
}

// RGBA8: source clamped to [0,1] before blending, result rounded to k/255.
TEST(Blend, UnormTargetClampsSourceThenRounds) {
  const Vec4 dst{0.2f, 0, 0, 0};
  Vec4 r = blend_and_store(BlendMode::OneOne, U8, {1.5f, -1.0f, 0.5f, 2.0f}, dst);
  EXPECT_EQ(r[0], 1.0f);            // 1 + 0.2 clamps at store
  EXPECT_EQ(r[1], 0.0f);            // −1 clamps to 0 before blending
  EXPECT_EQ(r[2], 128.0f / 255.0f); // 0.5·255 = 127.5 → 128
  EXPECT_EQ(r[3], 1.0f);
  // SRCALPHA with alpha 2 is clamped to 1 for UNORM: src·1 + dst.
  Vec4 s = blend_and_store(BlendMode::SrcAlphaOne, U8, {0.25f, 0, 0, 2.0f}, {0.25f, 0, 0, 0});
  EXPECT_EQ(s[0], 128.0f / 255.0f); // 0.5 → 127.5 → 128
}

// Round to nearest at the half-LSB boundaries: (k + 0.5)/255 ± a little.
TEST(Store, Rgba8RoundsToNearestAtHalfSteps) {
  for (int k : {0, 1, 127, 254}) {
    float below = (k + 0.5f) / 255.0f - 1e-5f, above = (k + 0.5f) / 255.0f + 1e-5f;
    Vec4 lo = blend_and_store(BlendMode::Replace, U8, {below, 0, 0, 0}, {});
    Vec4 hi = blend_and_store(BlendMode::Replace, U8, {above, 0, 0, 0}, {});
    EXPECT_EQ(lo[0], static_cast<float>(k) / 255.0f) << k;
    EXPECT_EQ(hi[0], static_cast<float>(k + 1) / 255.0f) << k;
  }
}

TEST(Store, Rgba16fAndRgba32f) {
  // 1 + 2^-12 is not a half: rounds to 1 (ties to even); float keeps it.
  const float v = 1.0f + 1.0f / 4096.0f;
  EXPECT_EQ(blend_and_store(BlendMode::Replace, img::Format::RGBA16F, {v, 0, 0, 0}, {})[0], 1.0f);
  EXPECT_EQ(blend_and_store(BlendMode::Replace, F32, {v, 0, 0, 0}, {})[0], v);
}

// Blending reads the stored (quantised) destination: x = 25.3/255 stores round(25.3) = 25;
// a second ONE/ONE draw gives round(25 + 25.3) = 50, where an unquantised destination
// would give round(50.6) = 51.
TEST(Store, BlendReadsQuantisedDestination) {
  Pass p;
  const float x = 25.3f / 255.0f;
  p.constant_inputs.color[0] = {x, x, x, x};
  p.blend = BlendMode::OneOne;
  img::Image im(3, 2, U8);
  ASSERT_TRUE(draw(p, im, 1).ok());
  EXPECT_EQ(im.at(1, 1)[0], 25.0f / 255.0f);
  ASSERT_TRUE(draw(p, im, 1).ok());
  EXPECT_EQ(im.at(1, 1)[0], 50.0f / 255.0f);
}

} // namespace
} // namespace tierlift::cpu
