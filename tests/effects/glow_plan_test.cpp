// The dx9 glow generator's pass list: counts, sizes, constants, taps. Expected values are
// worked out by hand from the rules in glow.h and blur_profile.h.
#include <gtest/gtest.h>

#include <cmath>

#include "tierlift/effects/glow.h"

namespace tierlift::effects {
namespace {

GlowPlan plan_for(unsigned n, bool half = true, uint32_t w = 128, uint32_t h = 64) {
  GlowParams p;
  p.width = w;
  p.height = h;
  p.downsample = n;
  p.half_texel = half;
  GlowPlan plan = build_glow_dx9(p);
  EXPECT_TRUE(plan) << plan.error;
  return plan;
}

std::vector<std::string> pass_names(const GlowPlan& plan) {
  std::vector<std::string> v;
  for (const PassDesc& d : plan.graph.passes) v.push_back(d.name);
  return v;
}

TEST(GlowPlan, DownsampleOne) {
  // σ 8 px → R = 24, 49 taps, 7 passes per axis; no downsample pass.
  GlowPlan plan = plan_for(1);
  EXPECT_EQ(plan.taps.size(), 49u);
  EXPECT_EQ(plan.blur_passes_per_axis, 7u);
  EXPECT_EQ(plan.graph.passes.size(), 16u);
  EXPECT_EQ(plan.glow_width, 128u);
  EXPECT_EQ(plan.glow_height, 64u);
  EXPECT_EQ(plan.graph.find_texture(kSmallTexture), nullptr);
  EXPECT_EQ(plan.graph.passes[1].textures[0].texture, kSourcesTexture);
}

TEST(GlowPlan, DownsampleTwo) {
  // σ 4 texels → R = 12, 25 taps, 4 passes per axis.
  GlowPlan plan = plan_for(2);
  EXPECT_EQ(plan.taps.size(), 25u);
  EXPECT_EQ(plan.blur_passes_per_axis, 4u);
  std::vector<std::string> want{"extract",  "downsample", "blur_h.0", "blur_h.1",
                                "blur_h.2", "blur_h.3",   "blur_v.0", "blur_v.1",
                                "blur_v.2", "blur_v.3",   "composite"};
  EXPECT_EQ(pass_names(plan), want);
  const TextureDesc* small = plan.graph.find_texture(kSmallTexture);
  ASSERT_NE(small, nullptr);
  EXPECT_EQ(small->width, 64u);
  EXPECT_EQ(small->height, 32u);
  // One bilinear read at the midpoint of texels 0 and 1 of each block: 1/128, 1/64.
  const PassDesc& ds = plan.graph.passes[1];
  EXPECT_FLOAT_EQ(ds.vs_constants[0][0], 1.0f / 128);
  EXPECT_FLOAT_EQ(ds.vs_constants[0][1], 1.0f / 64);
  EXPECT_FLOAT_EQ(ds.vs_constants[4][0], 1.0f); // scale 2·64/128
  EXPECT_FLOAT_EQ(ds.ps_constants[0][0], 1.0f);
  EXPECT_FLOAT_EQ(ds.ps_constants[1][0], 0.0f);
}

TEST(GlowPlan, DownsampleFour) {
  // σ 2 texels → R = 6, 13 taps, 2 passes per axis; four reads of weight ¼.
  GlowPlan plan = plan_for(4);
  EXPECT_EQ(plan.taps.size(), 13u);
  EXPECT_EQ(plan.graph.passes.size(), 7u);
  EXPECT_EQ(plan.glow_width, 32u);
  EXPECT_EQ(plan.glow_height, 16u);
  const PassDesc& ds = plan.graph.passes[1];
  const float xs[4] = {1.0f / 128, 3.0f / 128, 1.0f / 128, 3.0f / 128};
  const float ys[4] = {1.0f / 64, 1.0f / 64, 3.0f / 64, 3.0f / 64};
  for (int k = 0; k < 4; ++k) {
    EXPECT_FLOAT_EQ(ds.vs_constants[k][0], xs[k]) << k;
    EXPECT_FLOAT_EQ(ds.vs_constants[k][1], ys[k]) << k;
    EXPECT_FLOAT_EQ(ds.ps_constants[k][2], 0.25f) << k;
  }
}

TEST(GlowPlan, DownsampleThreeRoundsUpAndScales) {
  GlowPlan plan = plan_for(3);
  EXPECT_EQ(plan.glow_width, 43u); // ceil(128 / 3)
  EXPECT_EQ(plan.glow_height, 22u);
  const PassDesc& ds = plan.graph.passes[1];
  EXPECT_FLOAT_EQ(ds.vs_constants[4][0], 129.0f / 128);
  EXPECT_FLOAT_EQ(ds.ps_constants[0][0], 4.0f / 9); // (2/3)²
  EXPECT_FLOAT_EQ(ds.ps_constants[3][0], 1.0f / 9); // (1/3)²
}

TEST(GlowPlan, BlurOffsetsCarryTheHalfTexel) {
  GlowPlan plan = plan_for(2);
  const PassDesc& h0 = plan.graph.passes[2];
  EXPECT_EQ(h0.blend, cpu::BlendMode::Replace);
  EXPECT_FLOAT_EQ(h0.vs_constants[0][0], -11.5f / 64); // tap −12 + ½ on a 64-wide texture
  EXPECT_FLOAT_EQ(h0.vs_constants[0][1], 0.5f / 32);
  EXPECT_FLOAT_EQ(h0.vs_constants[7][0], -4.5f / 64);
  const PassDesc& h3 = plan.graph.passes[5];
  EXPECT_EQ(h3.blend, cpu::BlendMode::OneOne);
  EXPECT_FLOAT_EQ(h3.vs_constants[0][0], 12.5f / 64); // the 25th tap, then padding
  for (int k = 1; k < 8; ++k) EXPECT_EQ(h3.ps_constants[k][0], 0.0f);
  const PassDesc& v0 = plan.graph.passes[6];
  EXPECT_FLOAT_EQ(v0.vs_constants[0][0], 0.5f / 64);
  EXPECT_FLOAT_EQ(v0.vs_constants[0][1], -11.5f / 32);
  EXPECT_EQ(v0.textures[0].texture, kBlurHTexture);
  EXPECT_EQ(v0.target, kGlowTexture);
}

TEST(GlowPlan, WithoutHalfTexelOffsetsAreWholeTexels) {
  GlowPlan plan = plan_for(2, false);
  EXPECT_FLOAT_EQ(plan.graph.passes[2].vs_constants[0][0], -12.0f / 64);
  EXPECT_EQ(plan.graph.passes[2].vs_constants[0][1], 0.0f);
  EXPECT_FLOAT_EQ(plan.graph.passes[6].vs_constants[0][1], -12.0f / 32);
}

TEST(GlowPlan, TapsAreSymmetricNormalisedAndUseThePrintedListings) {
  GlowPlan plan = plan_for(2);
  double sum = 0;
  for (size_t i = 0; i < plan.taps.size(); ++i) {
    sum += plan.taps[i].weight;
    EXPECT_EQ(plan.taps[i].offset, int(i) - 12);
    EXPECT_DOUBLE_EQ(plan.taps[i].weight, plan.taps[plan.taps.size() - 1 - i].weight);
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  // Listing 1 is vs_2_0 with eight oT#; Listing 2 is ps_2_0.
  EXPECT_EQ(plan.graph.passes[2].vs->profile, ir::Profile::vs_2_0);
  EXPECT_EQ(plan.graph.passes[2].ps->profile, ir::Profile::ps_2_0);
}

TEST(BlurProfile, SingleGaussianByHand) {
  // σ = 1: R = 3, weights e^(−k²/2) / (1 + 2(e^−½ + e^−2 + e^−4.5)).
  std::string err;
  auto taps = sample_blur_profile(BlurProfile{{{1.0, 1.0}}}, 1, &err);
  ASSERT_EQ(taps.size(), 7u) << err;
  const double norm = 1 + 2 * (0.6065306597126334 + 0.1353352832366127 + 0.0111089965382423);
  EXPECT_NEAR(taps[3].weight, 1 / norm, 1e-12);
  EXPECT_NEAR(taps[0].weight, 0.0111089965382423 / norm, 1e-12);
}

TEST(BlurProfile, BadProfilesAreErrors) {
  std::string err;
  EXPECT_TRUE(sample_blur_profile(BlurProfile{{{0.0, 1.0}}}, 1, &err).empty());
  EXPECT_FALSE(err.empty());
  EXPECT_TRUE(sample_blur_profile(BlurProfile{{{1.0, 0.0}}}, 1, &err).empty());
  EXPECT_TRUE(sample_blur_profile(BlurProfile{{{NAN, 1.0}}}, 1, &err).empty());
  EXPECT_TRUE(sample_blur_profile(BlurProfile{{{5000.0, 1.0}}}, 1, &err).empty());
  GlowParams p;
  p.downsample = 5;
  EXPECT_FALSE(build_glow_dx9(p));
}

} // namespace
} // namespace tierlift::effects
