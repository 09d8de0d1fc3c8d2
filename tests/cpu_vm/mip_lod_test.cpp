// The LOD and mip-blend rules (tierlift/pass/mip_lod.h, NUMERICS.md M1-M3) against values
// worked out by hand: a 4×4 texture's three levels, lods on and between levels, the biases
// and MAXMIPLEVEL, each MIPFILTER.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/image/image.h"
#include "tierlift/pass/mip_chain.h"
#include "tierlift/pass/mip_lod.h"
#include "tierlift/rounding/rounding.h"

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

// ---- Mip chains (mip_chain.h, NUMERICS.md M6) and lavapipe's level rule (M1-M2) ----------

namespace {

using tierlift::pass::LodInput;
using tierlift::pass::select_levels;

// A 5×3 image whose texel (i, j) is i + 10·j in every channel.
std::shared_ptr<const tierlift::img::Image> ramp_5x3() {
  auto im = std::make_shared<tierlift::img::Image>(5, 3);
  for (uint32_t j = 0; j < 3; ++j)
    for (uint32_t i = 0; i < 5; ++i)
      for (int c = 0; c < 4; ++c) im->at(i, j)[c] = float(i + 10 * j);
  return im;
}

TEST(MipChain, BoxFilterDropsTheOddRowAndColumn) {
  using tierlift::pass::generate_mips;
  EXPECT_EQ(tierlift::pass::full_chain_length(5, 3), 3u); // 5×3, 2×1, 1×1
  EXPECT_EQ(tierlift::pass::full_chain_length(64, 64), 7u);
  EXPECT_EQ(tierlift::pass::full_chain_length(1, 1), 1u);
  const auto levels = generate_mips(ramp_5x3(), 0);
  ASSERT_EQ(levels.size(), 3u);
  ASSERT_EQ(levels[1]->width, 2u);
  ASSERT_EQ(levels[1]->height, 1u);
  // Texels (0..1, 0..1) and (2..3, 0..1); column 4 and row 2 are dropped.
  EXPECT_EQ(levels[1]->at(0, 0)[0], (0.0f + 1 + 10 + 11) / 4);
  EXPECT_EQ(levels[1]->at(1, 0)[0], (2.0f + 3 + 12 + 13) / 4);
  // 2×1 → 1×1: the single row is read twice.
  ASSERT_EQ(levels[2]->width, 1u);
  EXPECT_EQ(levels[2]->at(0, 0)[3], (5.5f + 7.5f) / 2);
  EXPECT_EQ(generate_mips(ramp_5x3(), 2).size(), 2u);
  EXPECT_EQ(generate_mips(ramp_5x3(), 9).size(), 3u); // at most the full chain
}

TEST(MipChain, BindingChecksEachLevelsSize) {
  using tierlift::pass::mipmapped_binding;
  auto base = ramp_5x3();
  auto good = std::make_shared<tierlift::img::Image>(2, 1);
  auto bad = std::make_shared<tierlift::img::Image>(3, 1);
  auto ok = mipmapped_binding({base, good});
  ASSERT_TRUE(ok.ok()) << ok.message();
  EXPECT_EQ(ok->levels.size(), 2u);
  EXPECT_EQ(ok->image, base);
  auto wrong = mipmapped_binding({base, bad});
  ASSERT_FALSE(wrong.ok());
  EXPECT_NE(wrong.message().find("level 1 must be 2x1"), std::string::npos) << wrong.message();
  auto one = std::make_shared<tierlift::img::Image>(1, 1);
  EXPECT_FALSE(mipmapped_binding({base, good, one, one}).ok());  // 4 levels > 3
  EXPECT_TRUE(mipmapped_binding({base}).value().levels.empty()); // one level: the image alone
}

TEST(MipLod, LlvmpipeFastLog2AndNearestLevel) {
  using namespace tierlift::rounding;
  EXPECT_EQ(fast_log2_llvmpipe(1.0f), 0.0f);
  EXPECT_EQ(fast_log2_llvmpipe(16.0f), 4.0f);
  EXPECT_EQ(fast_log2_llvmpipe(36.0f), 5.125f); // 1.125·2^5: (5 − 1) + 1.125
  EXPECT_EQ(fast_log2_llvmpipe(0.0f), -127.0f);
  EXPECT_EQ(lod_from_rho_llvmpipe(6.0f), 2.5625f);
  EXPECT_EQ(nearest_level_llvmpipe(0.5f), 0);
  EXPECT_EQ(nearest_level_llvmpipe(1.5f), 2);
  EXPECT_EQ(nearest_level_llvmpipe(2.5f), 2);
  EXPECT_EQ(nearest_level_llvmpipe(2.51f), 3);
  EXPECT_EQ(nearest_level_from_rho_llvmpipe(5.6f), 2); // log2 5.6 = 2.49
  EXPECT_EQ(nearest_level_from_rho_llvmpipe(5.7f), 3); // 2.51
  // ρ = max of the axes' larger gradient times their size, not the vector's length.
  EXPECT_EQ(mip_rho_llvmpipe(3.0f / 64, 4.0f / 64, 0, 0, 64, 64), 4.0f);
}

TEST(MipLod, SelectLevelsExactAndLlvmpipe) {
  LodInput in;
  in.dudx = 6.0f / 64;
  in.dvdy = 6.0f / 64; // ρ = 6 texels on a 64×64 level 0
  const MipState linear = state(MipFilter::Linear);
  const LevelChoice lp = select_levels(in, linear, 7, 64, 64, true);
  expect_levels(lp, 2, 3, 0.5625f); // ½·fast_log2(36) = 2.5625
  const LevelChoice ex = select_levels(in, linear, 7, 64, 64, false);
  EXPECT_EQ(ex.fine, 2u);
  EXPECT_FLOAT_EQ(ex.fraction, float(std::log2(6.0) - 2));
  // Explicit lod, MIPMAPLODBIAS, MAXMIPLEVEL from below, the last level's end.
  LodInput l;
  l.explicit_lod = true;
  l.lod = 0.25f;
  expect_levels(select_levels(l, state(MipFilter::Linear, 0.5f), 7, 64, 64, true), 0, 1, 0.75f);
  expect_levels(select_levels(l, state(MipFilter::Linear, 0, 3), 7, 64, 64, true), 3, 4, 0.0f);
  l.lod = 9.0f;
  expect_levels(select_levels(l, linear, 7, 64, 64, true), 6, 6, 0.0f);
  // NONE: MAXMIPLEVEL whatever the lod; POINT: ties to even.
  expect_levels(select_levels(l, state(MipFilter::None, 0, 4), 7, 64, 64, true), 4, 4, 0.0f);
  l.lod = 2.5f;
  expect_levels(select_levels(l, state(MipFilter::Point), 7, 64, 64, true), 2, 2, 0.0f);
}

} // namespace
