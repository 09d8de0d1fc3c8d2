// The glow generators' pass lists (dx9 and dx8): counts, sizes, constants, taps, blend
// modes, listings, intensity and bad parameters (the downsample passes in detail:
// glow_plan_downsample_test.cpp). Expected values are worked out by hand
// from the rules in glow.h and blur_profile.h.
#include <gtest/gtest.h>

#include <cmath>

#include "glow_plan_helpers.h"
#include "tierlift/effects/glow/glow.h"
#include "tierlift/pass/pass.h"

namespace tierlift::effects {
namespace {

BlurProfile one_gaussian(double sigma, double weight) {
  BlurProfile p;
  p.terms = {{sigma, weight}};
  return p;
}

using plan_test::pass_names;

EffectPlan plan_for(unsigned n, bool half = true, uint32_t w = 128, uint32_t h = 64) {
  EffectParams p = plan_test::sized(n, w, h);
  p.half_texel = half;
  return plan_test::expect_built(build_glow_dx9(p));
}

TEST(EffectPlan, DownsampleOne) {
  // σ 8 px → R = 24, 49 taps, 7 passes per axis; no downsample pass.
  EffectPlan plan = plan_for(1);
  EXPECT_EQ(plan.taps.size(), 49u);
  EXPECT_EQ(plan.blur_passes_per_axis, 7u);
  EXPECT_EQ(plan.graph.passes.size(), 16u);
  EXPECT_EQ(plan.glow_width, 128u);
  EXPECT_EQ(plan.glow_height, 64u);
  EXPECT_EQ(plan.graph.find_texture(kSmallTexture), nullptr);
  EXPECT_EQ(plan.graph.passes[1].textures[0].texture, kSourcesTexture);
}

// Every downsample pass of a plan: point reads of the sources into the small target, four
// a pass, the first replacing and the others adding (ONE/ONE).
TEST(EffectPlan, BlurOffsetsCarryTheHalfTexel) {
  EffectPlan plan = plan_for(2);
  const PassDesc& h0 = plan.graph.passes[2];
  EXPECT_EQ(h0.draw.blend, pass::BlendMode::Replace);
  EXPECT_FLOAT_EQ(h0.draw.vs_constants.f[0][0], -11.5f / 64); // tap −12 + ½ on a 64-wide texture
  EXPECT_FLOAT_EQ(h0.draw.vs_constants.f[0][1], 0.5f / 32);
  EXPECT_FLOAT_EQ(h0.draw.vs_constants.f[7][0], -4.5f / 64);
  const PassDesc& h3 = plan.graph.passes[5];
  EXPECT_EQ(h3.draw.blend, pass::BlendMode::OneOne);
  EXPECT_FLOAT_EQ(h3.draw.vs_constants.f[0][0], 12.5f / 64); // the 25th tap, then padding
  for (int k = 1; k < 8; ++k) EXPECT_EQ(h3.draw.ps_constants.f[k][0], 0.0f);
  const PassDesc& v0 = plan.graph.passes[6];
  EXPECT_FLOAT_EQ(v0.draw.vs_constants.f[0][0], 0.5f / 64);
  EXPECT_FLOAT_EQ(v0.draw.vs_constants.f[0][1], -11.5f / 32);
  EXPECT_EQ(v0.textures[0].texture, kBlurHTexture);
  EXPECT_EQ(v0.target, kGlowTexture);
  // Every tap on a texel centre: point filtering (bilinear there is the texel itself).
  for (const PassDesc* d : {&h0, &h3, &v0}) {
    ASSERT_EQ(d->textures.size(), 1u);
    EXPECT_EQ(d->binding(d->textures[0]).sampler.filter, pass::Filter::Point) << d->name;
  }
}

TEST(EffectPlan, WithoutHalfTexelOffsetsAreWholeTexels) {
  EffectPlan plan = plan_for(2, false);
  EXPECT_FLOAT_EQ(plan.graph.passes[2].draw.vs_constants.f[0][0], -12.0f / 64);
  EXPECT_EQ(plan.graph.passes[2].draw.vs_constants.f[0][1], 0.0f);
  EXPECT_FLOAT_EQ(plan.graph.passes[6].draw.vs_constants.f[0][1], -12.0f / 32);
  // Taps on texel corners, read bilinearly: the article's failure case, as on D3D9.
  for (size_t i = 2; i < 10; ++i)
    EXPECT_EQ(plan.graph.passes[i].binding(plan.graph.passes[i].textures.at(0)).sampler.filter,
              pass::Filter::Linear)
        << plan.graph.passes[i].name;
  // The helper passes read where they mean to, half texel or not: point reads.
  EXPECT_EQ(plan.graph.passes[1].binding(plan.graph.passes[1].textures.at(0)).sampler.filter,
            pass::Filter::Point);
}

TEST(EffectPlan, TapsAreSymmetricNormalisedAndUseThePrintedListings) {
  EffectPlan plan = plan_for(2);
  double sum = 0;
  for (size_t i = 0; i < plan.taps.size(); ++i) {
    sum += plan.taps[i].weight;
    EXPECT_EQ(plan.taps[i].offset, int(i) - 12);
    EXPECT_DOUBLE_EQ(plan.taps[i].weight, plan.taps[plan.taps.size() - 1 - i].weight);
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  // Listing 1 is vs_2_0 with eight oT#; Listing 2 is ps_2_0.
  EXPECT_EQ(plan.graph.passes[2].draw.vertex_program->profile, ir::Profile::vs_2_0);
  EXPECT_EQ(plan.graph.passes[2].draw.pixel_program->profile, ir::Profile::ps_2_0);
}

TEST(BlurProfile, SingleGaussianByHand) {
  // σ = 1: R = 3, weights e^(−k²/2) / (1 + 2(e^−½ + e^−2 + e^−4.5)).
  ir::Result<std::vector<BlurTap>> sampled = sample_blur_profile(one_gaussian(1.0, 1.0), 1);
  ASSERT_TRUE(sampled) << sampled.message();
  const std::vector<BlurTap>& taps = *sampled;
  ASSERT_EQ(taps.size(), 7u);
  const double norm = 1 + 2 * (0.6065306597126334 + 0.1353352832366127 + 0.0111089965382423);
  EXPECT_NEAR(taps[3].weight, 1 / norm, 1e-12);
  EXPECT_NEAR(taps[0].weight, 0.0111089965382423 / norm, 1e-12);
}

TEST(BlurProfile, BadProfilesAreErrors) {
  ir::Result<std::vector<BlurTap>> zero_sigma = sample_blur_profile(one_gaussian(0.0, 1.0), 1);
  EXPECT_FALSE(zero_sigma);
  EXPECT_FALSE(zero_sigma.message().empty());
  EXPECT_FALSE(sample_blur_profile(one_gaussian(1.0, 0.0), 1));
  EXPECT_FALSE(sample_blur_profile(one_gaussian(NAN, 1.0), 1));
  EXPECT_FALSE(sample_blur_profile(one_gaussian(5000.0, 1.0), 1));
  EffectParams p;
  p.downsample = 5;
  EXPECT_FALSE(build_glow_dx9(p));
}

// ---- tier dx8 --------------------------------------------------------------------------

EffectParams dx8_params(unsigned n, uint32_t w = 128, uint32_t h = 64) {
  EffectParams p = plan_test::sized(n, w, h);
  p.tier = Tier::Dx8;
  return p;
}

// σ = 2 px at downsample 2 is σ = 1 texel: R = 3, taps −3..3 with weights e^(−k²/2)/norm
// (the numbers of BlurProfile.SingleGaussianByHand), two dx8 passes per axis.
constexpr double kE05 = 0.6065306597126334, kE2 = 0.1353352832366127, kE45 = 0.0111089965382423;
constexpr double kNorm = 1 + 2 * (kE05 + kE2 + kE45);

TEST(GlowPlanDx8, PassCountsAreCeilOfTapsOverFour) {
  // Default profile: 49 taps at N = 1 → 13 passes an axis; 25 at N = 2 → 7; 13 at N = 4 → 4.
  // Downsample passes: none at N = 1, ceil(N²/4) else (one, four); plus extract, composite.
  struct Want {
    unsigned n, per_axis, downsample_passes;
  };
  for (const Want& c : {Want{1, 13, 0}, Want{2, 7, 1}, Want{4, 4, 4}}) {
    PlanResult plan_built = build_glow(dx8_params(c.n));
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    EXPECT_EQ(plan.blur_passes_per_axis, c.per_axis) << c.n;
    EXPECT_EQ(plan.graph.passes.size(), 2 * c.per_axis + 2 + c.downsample_passes) << c.n;
  }
  const EffectPlan plan = plan_test::expect_built(build_glow(dx8_params(2)));
  std::vector<std::string> want{"extract", "downsample.0"};
  for (const char* axis : {"blur_h", "blur_v"})
    for (int i = 0; i < 7; ++i) want.push_back(std::string(axis) + "." + std::to_string(i));
  want.push_back("composite");
  EXPECT_EQ(pass_names(plan), want);
}

TEST(GlowPlanDx8, BlurConstantsFollowTheArticlesRule) {
  EffectParams p = dx8_params(2, 45, 27); // glow 23 × 14
  p.profile = one_gaussian(2.0, 1.0);
  PlanResult plan_built = build_glow_dx8(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  ASSERT_EQ(plan.taps.size(), 7u);
  EXPECT_EQ(plan.glow_width, 23u);
  EXPECT_EQ(plan.glow_height, 14u);
  EXPECT_EQ(plan.blur_passes_per_axis, 2u);
  ASSERT_EQ(plan.graph.passes.size(), 7u);
  const PassDesc &h0 = plan.graph.passes[2], &h1 = plan.graph.passes[3];
  const PassDesc &v0 = plan.graph.passes[4], &v1 = plan.graph.passes[5];
  EXPECT_EQ(h0.name, "blur_h.0");
  EXPECT_EQ(v1.name, "blur_v.1");
  // Listing 3: c_k = ((k + ½)/W, ½/H) for the taps −3..0, then 1..3 and one padding tap.
  const float hu0[4] = {-2.5f / 23, -1.5f / 23, -0.5f / 23, 0.5f / 23};
  const float hu1[4] = {1.5f / 23, 2.5f / 23, 3.5f / 23, 0.5f / 23};
  const double w0[4] = {kE45, kE2, kE05, 1}, w1[4] = {kE05, kE2, kE45, 0};
  ASSERT_EQ(h0.draw.vs_constants.f.size(), 4u);
  ASSERT_EQ(h0.draw.ps_constants.f.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_FLOAT_EQ(h0.draw.vs_constants.f[k][0], hu0[k]) << k;
    EXPECT_FLOAT_EQ(h0.draw.vs_constants.f[k][1], 0.5f / 14) << k;
    EXPECT_FLOAT_EQ(h1.draw.vs_constants.f[k][0], hu1[k]) << k;
    EXPECT_FLOAT_EQ(v0.draw.vs_constants.f[k][0], 0.5f / 23) << k;
    EXPECT_FLOAT_EQ(v0.draw.vs_constants.f[k][1], hu0[k] * 23 / 14) << k;
    // Listing 4: c_k = the tap's weight in every channel (0 for padding). The plan stores
    // each weight as a float: |fl32(x) − x| ≤ 2⁻²⁴·x ≤ 6e-8 for x ≤ 1, inside 1e-7.
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(h0.draw.ps_constants.f[k][c], w0[k] / kNorm, 1e-7) << k;
      EXPECT_NEAR(h1.draw.ps_constants.f[k][c], w1[k] / kNorm, 1e-7) << k;
      EXPECT_EQ(v1.draw.ps_constants.f[k][c], h1.draw.ps_constants.f[k][c]) << k;
    }
  }
  // The first pass of an axis replaces, the others add (ONE/ONE).
  EXPECT_EQ(h0.draw.blend, pass::BlendMode::Replace);
  EXPECT_EQ(h1.draw.blend, pass::BlendMode::OneOne);
  EXPECT_EQ(v0.draw.blend, pass::BlendMode::Replace);
  EXPECT_EQ(v1.draw.blend, pass::BlendMode::OneOne);
  // tex t0..t3 read texture stages 0..3: the source is bound to all four; with the half
  // texel every tap is on a texel centre, so point filtering.
  ASSERT_EQ(h0.textures.size(), 4u);
  for (uint32_t k = 0; k < 4; ++k) {
    EXPECT_EQ(h0.textures[k].stage, k);
    EXPECT_EQ(h0.textures[k].texture, kSmallTexture);
    EXPECT_EQ(h0.binding(h0.textures[k]).sampler.filter, pass::Filter::Point);
    EXPECT_EQ(v1.binding(v1.textures[k]).sampler.filter, pass::Filter::Point);
    EXPECT_EQ(v0.textures[k].texture, kBlurHTexture);
  }
  EXPECT_EQ(v1.target, kGlowTexture);
}

TEST(GlowPlanDx8, WithoutHalfTexelOffsetsAreWholeTexels) {
  EffectParams p = dx8_params(2, 45, 27);
  p.profile = one_gaussian(2.0, 1.0);
  p.half_texel = false;
  PlanResult plan_built = build_glow_dx8(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  EXPECT_FLOAT_EQ(plan.graph.passes[2].draw.vs_constants.f[0][0], -3.0f / 23);
  EXPECT_EQ(plan.graph.passes[2].draw.vs_constants.f[0][1], 0.0f);
  EXPECT_EQ(plan.graph.passes[2].draw.vs_constants.f[3][0], 0.0f);
  EXPECT_FLOAT_EQ(plan.graph.passes[4].draw.vs_constants.f[0][1], -3.0f / 14);
  // Taps on texel corners: bilinear on all four stages, as on D3D8/9 hardware.
  for (size_t i = 2; i < 6; ++i)
    for (const TextureBind& t : plan.graph.passes[i].textures)
      EXPECT_EQ(plan.graph.passes[i].binding(t).sampler.filter, pass::Filter::Linear)
          << plan.graph.passes[i].name;
}

TEST(GlowPlanDx8, HelperPassesAreD3D8Listings) {
  PlanResult plan_built = build_glow_dx8(dx8_params(2, 45, 27));
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  for (const PassDesc& d : plan.graph.passes) {
    EXPECT_EQ(d.draw.vertex_program->profile, ir::Profile::vs_1_1) << d.name;
    EXPECT_TRUE(ir::is_ps11_13(d.draw.pixel_program->profile)) << d.name;
  }
  const PassDesc &ex = plan.graph.passes[0], &ds = plan.graph.passes[1];
  const PassDesc& co = plan.graph.passes.back();
  EXPECT_EQ(ex.analytic, AnalyticForm::MaskByAlpha);
  EXPECT_EQ(ex.draw.pixel_program->profile, ir::Profile::ps_1_1);
  EXPECT_EQ(plan.graph.passes[2].draw.pixel_program->profile, ir::Profile::ps_1_3); // Listing 4
  EXPECT_EQ(ds.analytic, AnalyticForm::Linear);
  // Extract: one point read at texel centres of the 45 × 27 scene.
  EXPECT_FLOAT_EQ(ex.draw.vs_constants.f[0][0], 0.5f / 45);
  EXPECT_FLOAT_EQ(ex.draw.vs_constants.f[4][1], 1.0f);
  ASSERT_EQ(ex.textures.size(), 1u);
  EXPECT_EQ(ex.binding(ex.textures[0]).sampler.filter, pass::Filter::Point);
  // Downsample by 2 into 23 × 14, one pass: point reads at the four texel centres of each
  // 2 × 2 block, weight ¼ each, the quad uv scaled by 2·23/45 and 2·14/27. Four stages bound.
  EXPECT_EQ(ds.name, "downsample.0");
  EXPECT_EQ(plan.graph.passes[2].name, "blur_h.0");
  const float xs[4] = {0.5f / 45, 1.5f / 45, 0.5f / 45, 1.5f / 45};
  const float ys[4] = {0.5f / 27, 0.5f / 27, 1.5f / 27, 1.5f / 27};
  for (int k = 0; k < 4; ++k) {
    EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][0], xs[k]) << k;
    EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][1], ys[k]) << k;
    EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k + 4][0], 46.0f / 45) << k;
    EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k + 4][1], 28.0f / 27) << k;
    EXPECT_EQ(ds.draw.ps_constants.f[k][0], 0.25f) << k;
  }
  EXPECT_EQ(ds.draw.blend, pass::BlendMode::Replace);
  ASSERT_EQ(ds.textures.size(), 4u);
  EXPECT_EQ(ds.textures[3].stage, 3u);
  EXPECT_EQ(ds.textures[3].texture, kSourcesTexture);
  EXPECT_EQ(ds.binding(ds.textures[3]).sampler.filter, pass::Filter::Point);
  // Composite: scene at texel centres; glow at (i + ½)/2 texels of a 46 × 28 cover.
  EXPECT_FLOAT_EQ(co.draw.vs_constants.f[1][0], 0.5f / 46);
  EXPECT_FLOAT_EQ(co.draw.vs_constants.f[5][0], 45.0f / 46);
  EXPECT_FLOAT_EQ(co.draw.vs_constants.f[5][1], 27.0f / 28);
  ASSERT_EQ(co.textures.size(), 2u);
  EXPECT_EQ(co.textures[1].stage, 1u);
  EXPECT_EQ(co.textures[1].texture, kGlowTexture);
}

// ---- intensity and bad parameters (both tiers) -----------------------------------------

float composite_c0(const EffectPlan& plan) {
  return plan.graph.passes.back().draw.ps_constants.f.at(0)[0];
}

TEST(GlowIntensity, Dx9PutsIntensityInC0) {
  EffectParams p;
  p.width = 45;
  p.height = 27;
  for (double intensity : {0.0, 1.0, 2.5, 17.0}) {
    p.intensity = intensity;
    PlanResult plan_built = build_glow_dx9(p);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    EXPECT_EQ(composite_c0(plan), float(intensity));
    EXPECT_EQ(plan.graph.passes.back().draw.pixel_program->profile, ir::Profile::ps_2_0);
  }
}

TEST(GlowIntensity, Dx8UpToOneInC0AboveOneAQuarterWithX4) {
  EffectParams p = dx8_params(2, 45, 27);
  for (double intensity : {0.0, 0.5, 1.0}) {
    p.intensity = intensity;
    PlanResult plan_built = build_glow_dx8(p);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    EXPECT_EQ(composite_c0(plan), float(intensity));
    EXPECT_EQ(plan.graph.passes.back().draw.pixel_program->code.size(), 4u); // tex, tex, mad, +mov
  }
  for (double intensity : {1.5, 4.0}) {
    p.intensity = intensity;
    PlanResult plan_built = build_glow_dx8(p);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    EXPECT_EQ(composite_c0(plan), float(intensity / 4));
    const ir::Instruction& mul = plan.graph.passes.back().draw.pixel_program->code.at(2);
    EXPECT_EQ(mul.op, ir::Opcode::Mul);
    EXPECT_EQ(mul.mods.shift, 2); // _x4
  }
}

TEST(GlowIntensity, BadValuesAreErrorsNamingIntensity) {
  for (Tier tier : {Tier::Dx9, Tier::Dx8})
    for (double bad : {-0.5, double(NAN), double(INFINITY)}) {
      EffectParams p = dx8_params(2, 45, 27);
      p.tier = tier;
      p.intensity = bad;
      const PlanResult plan = build_glow(p);
      EXPECT_FALSE(plan) << tier_name(tier) << " " << bad;
      EXPECT_EQ(plan.message().rfind("intensity ", 0), 0u) << plan.message();
    }
  EffectParams p = dx8_params(2, 45, 27);
  p.intensity = 4.5;
  const PlanResult plan = build_glow(p);
  EXPECT_FALSE(plan);
  EXPECT_EQ(plan.message().rfind("intensity 4.5: tier dx8", 0), 0u) << plan.message();
  p.tier = Tier::Dx9;
  EXPECT_TRUE(build_glow(p)) << "dx9 has no such limit";
}

TEST(GlowPlanDx8, BadParametersNameTheField) {
  for (unsigned n : {0u, 5u, 9u}) {
    const PlanResult plan = build_glow_dx8(dx8_params(n));
    EXPECT_FALSE(plan);
    EXPECT_EQ(plan.message(), "downsample " + std::to_string(n) + ": expected 1..4");
  }
  const PlanResult zero = build_glow_dx8(dx8_params(2, 0, 27));
  EXPECT_EQ(zero.message().rfind("scene size 0x27", 0), 0u) << zero.message();
  EffectParams p = dx8_params(2);
  p.profile = one_gaussian(-1.0, 1.0);
  EXPECT_NE(build_glow_dx8(p).message().find("sigma -1"), std::string::npos);
  p = dx8_params(2);
  p.listing_files["gpugems21/listing4_blur4_weighted_sum.psh"] = "/nonexistent/l4.psh";
  EXPECT_NE(build_glow_dx8(p).message().find("/nonexistent/l4.psh"), std::string::npos);
}

TEST(GlowPlanDx8, TapWeightsAboveOneAreClampedWithAWarning) {
  // σ = 0.1 px, weight 2: R = ceil(0.3) = 1, the centre tap ≈ 2 (the others ≈ 2·e^−50).
  EffectParams p = dx8_params(1, 45, 27);
  p.profile = one_gaussian(0.1, 2.0);
  PlanResult plan_built = build_glow_dx8(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  ASSERT_EQ(plan.warnings.size(), 1u);
  EXPECT_NE(plan.warnings[0].find("1 tap weight(s) above 1 (up to 2)"), std::string::npos)
      << plan.warnings[0];
  p.tier = Tier::Dx9;
  EXPECT_TRUE(build_glow(p)->warnings.empty()) << "ps.2.0 constants are floats";
}

TEST(GlowTier, NamesRoundTrip) {
  EXPECT_EQ(tier_name(Tier::Dx8), "dx8");
  EXPECT_EQ(parse_tier("dx8"), Tier::Dx8);
  EXPECT_EQ(parse_tier("dx9"), Tier::Dx9);
  EXPECT_EQ(parse_tier("dx7"), Tier::Dx7);
  EXPECT_EQ(tier_name(Tier::Dx7), "dx7");
  EXPECT_EQ(parse_tier("dx6"), std::nullopt);
}

} // namespace
} // namespace tierlift::effects

namespace tierlift::effects {
namespace {

// Tier dx9c: one loop per blur pass, i0 = (taps, 1, 2, 0), tap k's offset in c(2k+1) and its
// weight in c(2k+2), the kernel stated to the analytic model with the same floats; a ramped
// weight scale is refused (the stated kernel has one set of weights).
TEST(EffectPlan, Dx9cLoopsOverItsTapsWithOffsetsAndWeightsInConstants) {
  EffectParams p;
  p.tier = Tier::Dx9c;
  p.width = 64;
  p.height = 32;
  p.downsample = 1;
  p.profile = BlurProfile{{{1.0, 1.0}}, std::nullopt, 0}; // σ 1: taps −3..3
  PlanResult plan = build_glow(p);
  ASSERT_TRUE(plan) << plan.message();
  ASSERT_EQ(plan->taps.size(), 7u);
  EXPECT_EQ(plan->blur_passes_per_axis, 1u);
  const PassDesc* h = nullptr;
  for (const PassDesc& d : plan->graph.passes)
    if (d.name == "blur_h.0") h = &d;
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->draw.pixel_program->profile, ir::Profile::ps_3_0);
  EXPECT_EQ(h->analytic, AnalyticForm::Kernel);
  EXPECT_EQ(h->draw.ps_constants.i[0], (std::array<int32_t, 4>{7, 1, 2, 0}));
  ASSERT_EQ(h->draw.ps_constants.f.size(), 15u); // c0, then 7 × (offset, weight)
  ASSERT_EQ(h->kernel.size(), 7u);
  for (size_t k = 0; k < 7; ++k) {
    // Tap k: offset (offset_k + ½)/64 along x, ½/32 along y (the half texel).
    const float du = float((plan->taps[k].offset + 0.5) / 64), dv = float(0.5 / 32);
    EXPECT_EQ(h->draw.ps_constants.f[2 * k + 1][0], du) << k;
    EXPECT_EQ(h->draw.ps_constants.f[2 * k + 1][1], dv) << k;
    EXPECT_EQ(h->draw.ps_constants.f[2 * k + 2][0], float(plan->taps[k].weight)) << k;
    EXPECT_EQ(h->kernel[k].offset[0], double(du)) << k;
    EXPECT_EQ(h->kernel[k].weight[0], double(float(plan->taps[k].weight))) << k;
  }
  p.weight_scale_ramp.points = {{1, 1.0}, {10, 2.0}};
  PlanResult ramped = build_glow(p);
  ASSERT_FALSE(ramped);
  EXPECT_NE(ramped.message().find("weight scale ramp: tier dx9c"), std::string::npos)
      << ramped.message();
}

} // namespace
} // namespace tierlift::effects
