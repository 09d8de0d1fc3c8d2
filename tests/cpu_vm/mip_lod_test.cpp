// The LOD and mip-blend rules (tierlift/pass/mip_lod.h, NUMERICS.md M1-M3) against values
// worked out by hand: a 4×4 texture's three levels, lods on and between levels, the biases
// and MAXMIPLEVEL, each MIPFILTER.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/pass/mip_lod.h"

namespace {

using tierlift::pass::choose_levels;
using tierlift::pass::LevelChoice;
using tierlift::pass::MipFilter;
using tierlift::pass::MipState;

MipState state(MipFilter f, float bias = 0, uint32_t max_level = 0) {
  MipState s;
  s.filter = f;
  s.lod_bias = bias;
  s.max_mip_level = max_level;
  return s;
}

void expect_levels(const LevelChoice& c, uint32_t fine, uint32_t coarse, float fraction) {
  EXPECT_EQ(c.fine, fine);
  EXPECT_EQ(c.coarse, coarse);
  EXPECT_EQ(c.fraction, fraction);
}

// M1: a 4×4 texture drawn at 1:1 has footprint 1 texel (lod 0); minified 2× lod 1; the
// larger axis decides; magnified 4× lod −2.
TEST(MipLod, LodFromGradientsIsLog2OfTheLargerFootprint) {
  using tierlift::pass::lod_from_gradients;
  EXPECT_EQ(lod_from_gradients(0.25f, 0, 0, 0.25f, 4, 4), 0.0f);
  EXPECT_EQ(lod_from_gradients(0.5f, 0, 0, 0.5f, 4, 4), 1.0f);
  EXPECT_EQ(lod_from_gradients(0.25f, 0, 0, 1.0f, 4, 4), 2.0f); // dv/dy·H = 4
  EXPECT_EQ(lod_from_gradients(0.0625f, 0, 0, 0.0625f, 4, 4), -2.0f);
  // A diagonal step of (3, 4) texels: |.| = 5, lod log2(5).
  EXPECT_FLOAT_EQ(lod_from_gradients(0.75f, 1.0f, 0, 0, 4, 4), std::log2(5.0f));
  EXPECT_EQ(lod_from_gradients(0, 0, 0, 0, 4, 4), -std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(lod_from_gradients(INFINITY, 0, 0, 0, 4, 4)));
}

// M2 on a 4×4 texture (levels 0, 1, 2).
TEST(MipLod, NoneReadsTheMostDetailedLevelAllowed) {
  for (float lod : {-3.0f, 0.0f, 1.5f, 7.0f})
    expect_levels(choose_levels(lod, 0, state(MipFilter::None), 3), 0, 0, 0);
  expect_levels(choose_levels(0.0f, 0, state(MipFilter::None, 0, 1), 3), 1, 1, 0);
  expect_levels(choose_levels(0.0f, 0, state(MipFilter::None, 0, 9), 3), 2, 2,
                0); // MAXMIPLEVEL past the chain
}

TEST(MipLod, PointTakesTheNearestLevelHalvesGoCoarser) {
  const MipState s = state(MipFilter::Point);
  expect_levels(choose_levels(0.49f, 0, s, 3), 0, 0, 0);
  expect_levels(choose_levels(0.5f, 0, s, 3), 1, 1, 0);
  expect_levels(choose_levels(1.49f, 0, s, 3), 1, 1, 0);
  expect_levels(choose_levels(1.5f, 0, s, 3), 2, 2, 0);
  expect_levels(choose_levels(-5.0f, 0, s, 3), 0, 0, 0); // clamped to the finest
  expect_levels(choose_levels(9.0f, 0, s, 3), 2, 2, 0);  // and to the last
}

TEST(MipLod, LinearBlendsBetweenNeighbouringLevels) {
  const MipState s = state(MipFilter::Linear);
  expect_levels(choose_levels(0.25f, 0, s, 3), 0, 1, 0.25f);
  expect_levels(choose_levels(1.75f, 0, s, 3), 1, 2, 0.75f);
  expect_levels(choose_levels(2.0f, 0, s, 3), 2, 2, 0.0f);
  expect_levels(choose_levels(5.5f, 0, s, 3), 2, 2, 0.0f);
  expect_levels(choose_levels(-0.5f, 0, s, 3), 0, 1, 0.0f);
}

// MIPMAPLODBIAS and texldb's bias add to the lod; MAXMIPLEVEL raises the floor of the clamp.
TEST(MipLod, BiasesAddAndMaxMipLevelClampsFromBelow) {
  expect_levels(choose_levels(0.0f, 0.25f, state(MipFilter::Linear, 1.0f), 3), 1, 2, 0.25f);
  expect_levels(choose_levels(1.0f, -1.0f, state(MipFilter::Point), 3), 0, 0, 0);
  expect_levels(choose_levels(0.25f, 0, state(MipFilter::Linear, 0, 1), 3), 1, 2, 0.0f);
  expect_levels(choose_levels(1.5f, 0, state(MipFilter::Linear, 0, 1), 3), 1, 2, 0.5f);
  EXPECT_TRUE(choose_levels(0.0f, 0, state(MipFilter::Linear), 3).magnified);
  EXPECT_FALSE(choose_levels(0.0f, 0.125f, state(MipFilter::Linear), 3).magnified);
  EXPECT_FALSE(choose_levels(-1.0f, 0, state(MipFilter::Linear, 1.5f), 3).magnified);
}

TEST(MipLod, NanLodReadsTheMostDetailedLevelMagnified) {
  const LevelChoice c = choose_levels(std::nanf(""), 0, state(MipFilter::Linear, 0, 1), 3);
  expect_levels(c, 1, 1, 0);
  EXPECT_TRUE(c.magnified);
}

// M3: at lod 0.25 a read is 0.75·L0 + 0.25·L1: levels of constant colour 1 and 0.5 give 0.875.
TEST(MipLod, LinearMipBlendIsTheFractionTowardTheCoarserLevel) {
  using tierlift::pass::mip_blend_exact;
  EXPECT_EQ(mip_blend_exact(0.25f, 1.0f, 0.5f), 0.875f);
  EXPECT_EQ(mip_blend_exact(0.0f, 0.3f, 0.9f), 0.3f);
  EXPECT_EQ(mip_blend_exact(1.0f, 0.3f, 0.9f), 0.9f);
  // One rounding: (2/3)·0.1f + (1/3)·0.7f in double, then to float.
  const float f = 1.0f / 3.0f;
  EXPECT_EQ(mip_blend_exact(f, 0.1f, 0.7f),
            static_cast<float>((1.0 - double(f)) * double(0.1f) + double(f) * double(0.7f)));
}

} // namespace
