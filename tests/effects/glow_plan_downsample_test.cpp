// The glow generators' downsample passes (both tiers): the box average of each N×N block
// as point reads at texel centres, four a pass, summed by ONE/ONE (glow.h). Expected values
// are worked out by hand, and the read positions checked by independent math.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "glow_plan_helpers.h"
#include "tierlift/effects/glow/glow.h"
#include "tierlift/pass/pass.h"

namespace tierlift::effects {
namespace {

using plan_test::pass_names;

EffectPlan plan_for(unsigned n, Tier tier = Tier::Dx9, uint32_t w = 128, uint32_t h = 64) {
  EffectParams p = plan_test::sized(n, w, h);
  p.tier = tier;
  return plan_test::expect_built(build_glow(p));
}

std::vector<const PassDesc*> downsample_passes(const EffectPlan& plan) {
  std::vector<const PassDesc*> v;
  for (const PassDesc& d : plan.graph.passes)
    if (d.name.rfind("downsample.", 0) == 0) v.push_back(&d);
  return v;
}

// The downsample passes of an N×N box average, checked against the rule by independent
// math: read k of a pass is the helper listing's oTk = uv · c(k+4) + ck; at pixel i of the
// small target the quad uv is i/gw (D3D9 pixel centres), so the read lands at texel
// c(k+4)·i·W/gw + ck·W, which must be N·i + (texel centre of the block: a + ½). Over all
// passes, every texel (a, b) of the N×N block is read exactly once with weight 1/N², and
// the padding reads weigh 0. `stages`: how many stages the sources are bound to.
void expect_box_average(const EffectPlan& plan, unsigned n, uint32_t w, uint32_t h, size_t stages) {
  const std::vector<const PassDesc*> ds = downsample_passes(plan);
  ASSERT_EQ(ds.size(), (n * n + 3) / 4) << n;
  const double su = double(n) * plan.glow_width / w, sv = double(n) * plan.glow_height / h;
  std::vector<int> hits(n * n, 0);
  for (size_t i = 0; i < ds.size(); ++i) {
    const PassDesc& d = *ds[i];
    SCOPED_TRACE(d.name);
    EXPECT_EQ(d.name, "downsample." + std::to_string(i));
    EXPECT_EQ(d.target, kSmallTexture);
    EXPECT_EQ(d.draw.blend, i == 0 ? pass::BlendMode::Replace : pass::BlendMode::OneOne);
    ASSERT_EQ(d.draw.vs_constants.f.size(), 8u);
    ASSERT_EQ(d.draw.ps_constants.f.size(), 4u);
    ASSERT_EQ(d.textures.size(), stages);
    for (size_t t = 0; t < stages; ++t) {
      EXPECT_EQ(d.textures[t].stage, uint32_t(t));
      EXPECT_EQ(d.textures[t].texture, kSourcesTexture);
      EXPECT_EQ(d.binding(d.textures[t]).sampler.filter, pass::Filter::Point);
    }
    for (size_t k = 0; k < 4; ++k) {
      const float weight = d.draw.ps_constants.f[k][0];
      for (int c = 1; c < 4; ++c) EXPECT_EQ(d.draw.ps_constants.f[k][c], weight) << k;
      if (weight == 0) continue; // padding: adds exactly 0 wherever it reads
      EXPECT_FLOAT_EQ(weight, 1.0f / float(n * n)) << k;
      EXPECT_FLOAT_EQ(d.draw.vs_constants.f[k + 4][0], float(su)) << k;
      EXPECT_FLOAT_EQ(d.draw.vs_constants.f[k + 4][1], float(sv)) << k;
      // The position within the block, in texels: a texel centre a + ½ (to fp32 precision).
      const double px = double(d.draw.vs_constants.f[k][0]) * w,
                   py = double(d.draw.vs_constants.f[k][1]) * h;
      const double ax = px - 0.5, ay = py - 0.5;
      EXPECT_NEAR(ax, std::round(ax), 1e-4) << k;
      EXPECT_NEAR(ay, std::round(ay), 1e-4) << k;
      const long a = std::lround(ax), b = std::lround(ay);
      ASSERT_TRUE(a >= 0 && a < long(n) && b >= 0 && b < long(n)) << a << "," << b;
      ++hits[size_t(b) * n + size_t(a)];
      // Pixel 3 of the small target reads texel 3N + a: the scale maps uv 3/gw to 3N/W.
      const double at3 = double(d.draw.vs_constants.f[k + 4][0]) * 3.0 / plan.glow_width * w + px;
      EXPECT_EQ(long(std::floor(at3)), long(3 * n) + a) << k;
    }
  }
  for (unsigned t = 0; t < n * n; ++t) EXPECT_EQ(hits[t], 1) << "texel " << t % n << "," << t / n;
}

TEST(EffectPlan, DownsampleTwo) {
  // σ 4 texels → R = 12, 25 taps, 4 passes per axis; one downsample pass of four reads.
  EffectPlan plan = plan_for(2);
  EXPECT_EQ(plan.taps.size(), 25u);
  EXPECT_EQ(plan.blur_passes_per_axis, 4u);
  std::vector<std::string> want{"extract",  "downsample.0", "blur_h.0", "blur_h.1",
                                "blur_h.2", "blur_h.3",     "blur_v.0", "blur_v.1",
                                "blur_v.2", "blur_v.3",     "composite"};
  EXPECT_EQ(pass_names(plan), want);
  const TextureDesc* small = plan.graph.find_texture(kSmallTexture);
  ASSERT_NE(small, nullptr);
  EXPECT_EQ(small->width, 64u);
  EXPECT_EQ(small->height, 32u);
  // Point reads at the four texel centres of each 2 × 2 block: (½ or 1½)/128, (½ or 1½)/64,
  // x fastest; weight ¼ each; scale 2·64/128 = 1 and 2·32/64 = 1.
  const PassDesc& ds = plan.graph.passes[1];
  const float xs[4] = {0.5f / 128, 1.5f / 128, 0.5f / 128, 1.5f / 128};
  const float ys[4] = {0.5f / 64, 0.5f / 64, 1.5f / 64, 1.5f / 64};
  for (int k = 0; k < 4; ++k) {
    EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][0], xs[k]) << k;
    EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][1], ys[k]) << k;
    EXPECT_EQ(ds.draw.vs_constants.f[k + 4][0], 1.0f) << k;
    EXPECT_EQ(ds.draw.vs_constants.f[k + 4][1], 1.0f) << k;
    EXPECT_EQ(ds.draw.ps_constants.f[k][0], 0.25f) << k;
  }
  EXPECT_EQ(ds.draw.blend, pass::BlendMode::Replace);
  ASSERT_EQ(ds.textures.size(), 1u); // ps_2_0: every read through s0
  EXPECT_EQ(ds.binding(ds.textures[0]).sampler.filter, pass::Filter::Point);
  expect_box_average(plan, 2, 128, 64, 1);
}

TEST(EffectPlan, DownsampleFour) {
  // σ 2 texels → R = 6, 13 taps, 2 passes per axis; 16 reads of weight 1/16 in 4 passes.
  EffectPlan plan = plan_for(4);
  EXPECT_EQ(plan.taps.size(), 13u);
  EXPECT_EQ(plan.graph.passes.size(), 10u); // extract, 4 downsample, 2 + 2 blur, composite
  EXPECT_EQ(plan.glow_width, 32u);
  EXPECT_EQ(plan.glow_height, 16u);
  // Pass i reads row i of the 4 × 4 block: x = (k + ½)/128, y = (i + ½)/64.
  for (int i = 0; i < 4; ++i) {
    const PassDesc& ds = plan.graph.passes[1 + i];
    EXPECT_EQ(ds.name, "downsample." + std::to_string(i));
    EXPECT_EQ(ds.draw.blend, i == 0 ? pass::BlendMode::Replace : pass::BlendMode::OneOne) << i;
    for (int k = 0; k < 4; ++k) {
      EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][0], (k + 0.5f) / 128) << i << " " << k;
      EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][1], (i + 0.5f) / 64) << i << " " << k;
      EXPECT_EQ(ds.draw.vs_constants.f[k + 4][0], 1.0f); // 4·32/128
      EXPECT_EQ(ds.draw.ps_constants.f[k][2], 0.0625f) << i << " " << k;
    }
  }
  EXPECT_EQ(plan.graph.passes[5].name, "blur_h.0");
  expect_box_average(plan, 4, 128, 64, 1);
}

TEST(EffectPlan, DownsampleThreeRoundsUpAndScales) {
  EffectPlan plan = plan_for(3);
  EXPECT_EQ(plan.glow_width, 43u); // ceil(128 / 3)
  EXPECT_EQ(plan.glow_height, 22u);
  // Nine reads, four a pass: 4 + 4 + 1, the last pass padded with three reads of weight 0.
  const std::vector<std::string> names = pass_names(plan);
  EXPECT_EQ(std::vector<std::string>(names.begin() + 1, names.begin() + 5),
            (std::vector<std::string>{"downsample.0", "downsample.1", "downsample.2", "blur_h.0"}));
  const PassDesc &d0 = plan.graph.passes[1], &d2 = plan.graph.passes[3];
  EXPECT_FLOAT_EQ(d0.draw.vs_constants.f[4][0], 129.0f / 128); // 3·43/128
  EXPECT_FLOAT_EQ(d0.draw.vs_constants.f[4][1], 66.0f / 64);   // 3·22/64
  EXPECT_FLOAT_EQ(d0.draw.vs_constants.f[2][0], 2.5f / 128);   // read 2: texel (2, 0)
  EXPECT_FLOAT_EQ(d0.draw.vs_constants.f[3][0], 0.5f / 128);   // read 3: texel (0, 1)
  EXPECT_FLOAT_EQ(d0.draw.vs_constants.f[3][1], 1.5f / 64);
  EXPECT_FLOAT_EQ(d0.draw.ps_constants.f[0][0], 1.0f / 9);
  EXPECT_FLOAT_EQ(d2.draw.vs_constants.f[0][0], 2.5f / 128); // read 8: texel (2, 2)
  EXPECT_FLOAT_EQ(d2.draw.vs_constants.f[0][1], 2.5f / 64);
  EXPECT_FLOAT_EQ(d2.draw.ps_constants.f[0][0], 1.0f / 9);
  for (int k = 1; k < 4; ++k) EXPECT_EQ(d2.draw.ps_constants.f[k][0], 0.0f) << k;
  expect_box_average(plan, 3, 128, 64, 1);
}

TEST(GlowPlanDx8, DownsampleFourUsesFourPassesOfFourReads) {
  EffectPlan plan = plan_for(4, Tier::Dx8);
  ASSERT_FALSE(plan.graph.passes.empty());
  // Pass i reads row i of the 4 × 4 block, t0..t3 on stages 0..3, weight 1/16 each.
  for (int i = 0; i < 4; ++i) {
    const PassDesc& ds = plan.graph.passes[1 + i];
    EXPECT_EQ(ds.name, "downsample." + std::to_string(i));
    EXPECT_TRUE(ir::is_ps11_13(ds.draw.pixel_program->profile)) << i;
    for (int k = 0; k < 4; ++k) {
      EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][0], (k + 0.5f) / 128) << i << " " << k;
      EXPECT_FLOAT_EQ(ds.draw.vs_constants.f[k][1], (i + 0.5f) / 64) << i << " " << k;
      EXPECT_EQ(ds.draw.ps_constants.f[k][0], 0.0625f) << i << " " << k;
    }
  }
  expect_box_average(plan, 4, 128, 64, 4);
}

TEST(GlowPlanDx8, DownsampleTwoAndThreeAreBoxAverages) {
  // One stage per read (t0..t3 read stages 0..3), both on odd sizes.
  for (unsigned n : {2u, 3u}) {
    SCOPED_TRACE(n);
    EffectPlan plan = plan_for(n, Tier::Dx8, 45, 27);
    ASSERT_FALSE(plan.graph.passes.empty());
    expect_box_average(plan, n, 45, 27, 4);
  }
}

} // namespace
} // namespace tierlift::effects
