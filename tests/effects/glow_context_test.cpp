// Rendering contexts and the glow fog (glow_context.h) against hand math: a glow render
// whose own rgb × alpha is the glow sources where the scene's alpha says nothing, and D3D's
// linear fog on the sources, f = saturate((end − d)/(end − start)), computed here in double
// for each texel's depth. A one-tap blur at full resolution makes the glow equal to the
// sources, so every texel's contribution to the frame is read straight off `final`. Each
// case runs on the interpreter, on Vulkan and on the analytic device, tiers dx9, dx8, dx7.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <optional>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/prune.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/graph/memory_plan.h"

namespace tierlift::effects {

// How a tier prints in test listings (GetParam): its name, not its bytes. In the enum's own
// namespace, where argument-dependent lookup finds it; static, one copy per test file.
[[maybe_unused]] static void PrintTo(Tier t, std::ostream* os) {
  *os << tier_name(t);
}

namespace {

constexpr uint32_t kW = 8, kH = 3;
constexpr double kStart = 0.2, kEnd = 0.8, kIntensity = 2;
// Depth per column: nearer than start, at start, between, at end, beyond end.
constexpr std::array<double, kW> kDepth{0.0, 0.2, 0.35, 0.5, 0.65, 0.8, 0.9, 1.0};
constexpr std::array<double, 3> kFog{0.1, 0.2, 0.3};

// One tap of weight 1 at full resolution: glow = sources, texel for texel.
EffectParams one_tap(Tier tier) {
  EffectParams p;
  p.tier = tier;
  p.width = kW, p.height = kH;
  p.downsample = 1;
  p.profile.max_taps = 1;
  p.intensity = kIntensity;
  p.subtexel_bits = 0;
  return p;
}

// rgb varies with the row, alpha 1, ½, 0 by row (row 2 does not glow at all).
img::Image source_image() {
  img::Image im(kW, kH);
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      float* p = im.at(x, y);
      p[0] = 0.9f, p[1] = 0.6f - 0.1f * float(y), p[2] = 0.25f, p[3] = 1.0f - 0.5f * float(y);
    }
  return im;
}

struct Ways {
  EffectPlan plan;
  std::vector<std::pair<std::string, EffectRun>> runs;
};

class GlowContext3 : public vulkan::test::VulkanTest, public ::testing::WithParamInterface<Tier> {
protected:
  // p's plan on the three ways over `scene`; nothing (the failure recorded) when p does not
  // build.
  std::optional<Ways> run_all(const EffectParams& p, const img::Image& scene) {
    PlanResult plan_built = build_glow(p);
    if (!plan_built) {
      ADD_FAILURE() << plan_built.message();
      return std::nullopt;
    }
    Ways w{std::move(*plan_built), {}};
    const EffectPlan& plan = w.plan;
    CpuPassDevice cpu_dev(1);
    AnalyticPassDevice analytic;
    auto vk = make_vulkan_pass_device(*dev);
    w.runs.emplace_back("cpu", run_effect(plan, scene, cpu_dev));
    w.runs.emplace_back("vulkan", run_effect(plan, scene, *vk));
    w.runs.emplace_back("analytic", run_effect(plan, scene, analytic));
    for (const auto& [name, r] : w.runs) EXPECT_TRUE(r.run.ok()) << name << ": " << r.run.message();
    EXPECT_TRUE(dev->messages().empty()) << dev->messages().front();
    return w;
  }
};

// Every way's `glow` equals expected(x, y) within 2e-6 per channel (one tap of weight 1:
// the glow is the sources). On tier dx9 the frame is scene + intensity × glow as well (the
// ps.1.x tiers clamp the frame to their register range, here 1 on dx7).
// The bound: the devices compute in fp32 what expected() computes in double. The depth and
// the constants c0 = −1/(end − start), c1 = end/(end − start) (÷4 on ps.1.x, ×4 back exactly)
// are each rounded once (relative 2^-24); f = saturate(c0·d + c1) then errs by at most
// (2·|c0·d| + |c1| + |c0·d + c1|)·2^-24 ≤ (3.34 + 1.34 + 1.34)·6e-8 < 3.7e-7 (kStart, kEnd
// above; d ≤ 1), which the lrp scales by |sources − fog| ≤ 1; rgb × alpha, the lrp's own
// operations and the one-tap blur (weight 1, exact) add at most 4 roundings of values ≤ 1,
// 2.4e-7: under 6.1e-7 in all, so 2e-6 holds with room. The frame adds intensity 2 × that
// plus one rounding of a value ≤ 3: under 1.4e-6 against 4e-6.
template <class Expected>
void expect_glow(const Ways& w, const img::Image& scene, Tier tier, const Expected& expected) {
  for (const auto& [name, r] : w.runs) {
    if (!r.run.ok()) continue;
    const img::Image& glow = r.images.at(std::string(kGlowTexture));
    const img::Image& fin = r.images.at(std::string(kFinalTexture));
    for (uint32_t y = 0; y < kH; ++y)
      for (uint32_t x = 0; x < kW; ++x) {
        const std::array<double, 3> g = expected(x, y);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(glow.at(x, y)[c], g[c], 2e-6)
              << name << " x " << x << " y " << y << " channel " << c;
          if (tier == Tier::Dx9) {
            EXPECT_NEAR(fin.at(x, y)[c], scene.at(x, y)[c] + kIntensity * g[c], 4e-6)
                << name << " final x " << x << " y " << y << " channel " << c;
          }
        }
      }
  }
}

TEST_P(GlowContext3, FogFadesEachSourceByTheLinearFogFraction) {
  EffectParams p = one_tap(GetParam());
  p.context.fog.on = true;
  p.context.fog.start = kStart, p.context.fog.end = kEnd;
  p.context.fog.color = kFog;
  auto depth = std::make_shared<img::Image>(kW, kH);
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) depth->at(x, y)[0] = float(kDepth[x]); // red is the depth
  p.context.fog.depth = depth;
  const img::Image scene = source_image();
  const std::optional<Ways> w = run_all(p, scene);
  ASSERT_TRUE(w);
  expect_glow(*w, scene, p.tier, [&](uint32_t x, uint32_t y) {
    // By hand: d ≤ start keeps the source, d ≥ end leaves the fog colour, in between the
    // fraction (end − d)/(end − start) of the source.
    const double d = kDepth[x];
    const double f = d <= kStart ? 1 : d >= kEnd ? 0 : (kEnd - d) / (kEnd - kStart);
    const float* s = scene.at(x, y);
    std::array<double, 3> g{};
    for (int c = 0; c < 3; ++c) g[c] = f * double(s[c]) * double(s[3]) + (1 - f) * kFog[c];
    return g;
  });
  // The closed form's ends, spelled out: beyond end only the fog colour glows; near, a
  // texel of alpha 0 does not glow at all.
  const img::Image& glow = w->runs[0].second.images.at(std::string(kGlowTexture));
  EXPECT_NEAR(glow.at(7, 0)[2], kFog[2], 2e-6);
  EXPECT_NEAR(glow.at(6, 1)[1], kFog[1], 2e-6);
  EXPECT_NEAR(glow.at(0, 2)[2], 0.0, 2e-6);
}

TEST_P(GlowContext3, BuiltInFloorFogsTheTopRows) {
  EffectParams p = one_tap(GetParam());
  p.context.fog.on = true;
  p.context.fog.start = 0.25, p.context.fog.end = 0.75; // black fog
  const img::Image scene = source_image();
  const std::optional<Ways> w = run_all(p, scene);
  ASSERT_TRUE(w);
  expect_glow(*w, scene, p.tier, [&](uint32_t x, uint32_t y) {
    const double d = 1 - (y + 0.5) / kH; // rows 5/6, 1/2, 1/6 of the way up
    const double f = std::clamp((0.75 - d) / 0.5, 0.0, 1.0);
    const float* s = scene.at(x, y);
    return std::array<double, 3>{f * s[0] * s[3], f * s[1] * s[3], f * s[2] * s[3]};
  });
}

TEST_P(GlowContext3, GlowImageGlowsWhereTheSceneAlphaIsZero) {
  EffectParams p = one_tap(GetParam());
  img::Image scene = source_image();
  for (size_t i = 3; i < scene.rgba.size(); i += 4) scene.rgba[i] = 0; // nothing glows here
  auto glow = std::make_shared<img::Image>(kW, kH); // zero: no glow but at two texels
  glow->at(2, 1)[0] = 1, glow->at(2, 1)[1] = 0.5f, glow->at(2, 1)[3] = 1;
  glow->at(6, 0)[2] = 0.8f, glow->at(6, 0)[3] = 0.25f;
  p.context.glow_image = glow;
  const std::optional<Ways> w = run_all(p, scene);
  ASSERT_TRUE(w);
  expect_glow(*w, scene, p.tier, [&](uint32_t x, uint32_t y) {
    const float* g = glow->at(x, y);
    return std::array<double, 3>{g[0] * g[3], g[1] * g[3], g[2] * g[3]};
  });
  // Pruning must not take the scene's zero alpha for "no sources": the frame is unchanged.
  const PrunedGraph pruned = prune_glow(w->plan, scene);
  EXPECT_TRUE(pruned.left_out.empty() && pruned.limited.empty());
  const img::Image& glow_out = w->runs[0].second.images.at(std::string(kGlowTexture));
  EXPECT_NEAR(glow_out.at(2, 1)[0], 1.0, 2e-6);
  EXPECT_NEAR(glow_out.at(6, 0)[2], 0.2, 2e-6);
}

INSTANTIATE_TEST_SUITE_P(Tiers, GlowContext3, ::testing::Values(Tier::Dx9, Tier::Dx8, Tier::Dx7),
                         [](const ::testing::TestParamInfo<Tier>& info) {
                           return std::string(tier_name(info.param));
                         });

TEST(GlowContext, MemoryPlanCountsTheCarriedInputs) {
  EffectParams plain = one_tap(Tier::Dx9), fogged = plain;
  fogged.context.fog.on = true;
  const PlanResult a_built = build_glow(plain), b_built = build_glow(fogged);
  ASSERT_TRUE(a_built && b_built) << a_built.message() << b_built.message();
  const EffectPlan &a = *a_built, &b = *b_built;
  const uint64_t texture = uint64_t{kW} * kH * 16; // one RGBA32F texture of the scene's size
  // The depth texture four times: the image the graph carries, the device's own, the one
  // the run hands back, and begin_run's copy of the inputs (scene and depth), which is the
  // CPU device's largest transient (a pass draws in place and copies nothing).
  EXPECT_EQ(plan_memory(b.graph, {"cpu"}, false, 0).peak,
            plan_memory(a.graph, {"cpu"}, false, 0).peak + 4 * texture);
}

TEST(GlowContext, FogConstantsAndTheirPs1xLimit) {
  GlowFog fog;
  fog.start = 0.2, fog.end = 0.8;
  const auto c = fog_constants(fog, 4);
  EXPECT_FLOAT_EQ(c[0][0], float(-1 / 0.6 / 4));
  EXPECT_FLOAT_EQ(c[1][0], float(0.8 / 0.6 / 4));
  EXPECT_EQ(fog_ps1x_limit(fog), "");
  fog.start = 0.7; // 0.1 deep: a slope of 2.5 per unit after _x4 does not fit
  EXPECT_NE(fog_ps1x_limit(fog).find("end − start >= 0.25"), std::string::npos);
  EffectParams p;
  p.tier = Tier::Dx8;
  p.context.fog = fog;
  p.context.fog.on = true;
  EXPECT_NE(build_glow(p).message().find("tier dx8"), std::string::npos);
  p.context.fog.start = 0.8; // start == end
  EXPECT_NE(build_glow(p).message().find("start < end"), std::string::npos);
}

} // namespace
} // namespace tierlift::effects
