// Pruning (prune.h) leaves the result unchanged: the glow and the final frame of the pruned
// plan equal those of the whole plan — bit for bit in RGBA8 and RGBA16F, within 1e-6 in
// RGBA32F — on the built-in scene, random scenes, sources in one corner and no sources, on
// every tier; and it does leave out what it says (no blur without sources; RGBA8 tails).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "glow_plan_helpers.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/prune.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/scenes/default_scene.h"

#include "../vulkan/vk_test_util.h"

namespace tierlift::effects {
namespace {

struct Outcome {
  size_t left_out = 0;
};

// Runs the whole and the pruned plan on the CPU device and compares glow and final.
Outcome expect_same(const EffectParams& p, const img::Image& scene, const std::string& what) {
  const PlanResult plan_built = build_glow(p);
  if (!plan_built) {
    ADD_FAILURE() << what << ": " << plan_built.message();
    return {};
  }
  const EffectPlan& plan = *plan_built;
  const PrunedGraph pruned = prune_glow(plan, scene);
  EffectPlan lean = plan;
  lean.graph = pruned.graph;
  CpuPassDevice a, b;
  const EffectRun whole = run_effect(plan, scene, a), part = run_effect(lean, scene, b);
  EXPECT_TRUE(whole.run.ok() && part.run.ok()) << whole.run.message() << part.run.message();
  if (!whole.run.ok() || !part.run.ok()) return {};
  for (const char* tex : {"glow", "final"}) {
    const std::vector<float>& x = whole.images.at(tex).rgba;
    const std::vector<float>& y = part.images.at(tex).rgba;
    EXPECT_EQ(x.size(), y.size());
    size_t differ = 0;
    for (size_t i = 0; i < x.size() && i < y.size(); ++i)
      differ += p.format == img::Format::RGBA32F ? !(std::abs(x[i] - y[i]) <= 1e-6f) : x[i] != y[i];
    EXPECT_EQ(differ, 0u) << what << " " << tier_name(p.tier) << " " << img::format_name(p.format)
                          << " ds" << p.downsample << ": " << tex;
  }
  return {pruned.left_out.size()};
}

EffectParams params(uint32_t w, uint32_t h, Tier t, img::Format f, unsigned ds) {
  EffectParams p;
  p.width = w, p.height = h, p.tier = t, p.format = f, p.downsample = ds;
  return p;
}

const img::Format kFormats[] = {img::Format::RGBA8, img::Format::RGBA16F, img::Format::RGBA32F};

TEST(Prune, BuiltInSceneUnchanged) {
  for (Tier t : all_tiers())
    for (img::Format f : kFormats) {
      const Outcome o =
          expect_same(params(320, 180, t, f, 2), make_default_scene(320, 180), "built-in");
      // RGBA8: the kernel's outermost tap (0.7 · e^-4.5 / 10 ≈ 8e-4 of the source) stores 0.
      // (tier dx9's ps_2_0 passes; ps_1_x passes keep their own precision and all stay)
      if (f == img::Format::RGBA8 && t == Tier::Dx9) {
        EXPECT_GT(o.left_out, 0u) << tier_name(t);
      } else {
        EXPECT_EQ(o.left_out, 0u) << tier_name(t);
      }
    }
}

TEST(Prune, RandomScenesUnchanged) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0, 1);
  for (int n = 0; n < 6; ++n) {
    const uint32_t w = 17 + rng() % 40, h = 9 + rng() % 30;
    img::Image s(w, h);
    const float density = u(rng), scale = n % 2 ? 0.05f : 1.0f; // some scenes dim
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        float* p = s.at(x, y);
        p[0] = u(rng) * scale, p[1] = u(rng) * scale, p[2] = u(rng) * scale;
        p[3] = u(rng) < density ? u(rng) : 0.0f;
      }
    for (Tier t : all_tiers())
      for (img::Format f : kFormats) expect_same(params(w, h, t, f, 1 + n % 4), s, "random");
  }
}

TEST(Prune, SourcesInOneCornerUnchanged) {
  img::Image s = make_default_scene(96, 64);
  for (size_t i = 3; i < s.rgba.size(); i += 4) s.rgba[i] = 0;
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 5; ++x) s.at(x, y)[3] = 1, s.at(x, y)[0] = 0.02f;
  for (Tier t : all_tiers())
    for (img::Format f : kFormats) expect_same(params(96, 64, t, f, 2), s, "corner");
}

// The scissor rule: a corner of sources limits extract, downsample and both blur axes to a
// small part of each texture (the CPU runs above prove the frame unchanged).
TEST(Prune, CornerSourcesLimitTheBlurToACorner) {
  img::Image s = make_default_scene(96, 64);
  for (size_t i = 3; i < s.rgba.size(); i += 4) s.rgba[i] = 0;
  s.at(1, 1)[3] = 1;
  EffectParams p = params(96, 64, Tier::Dx9, img::Format::RGBA32F, 2);
  p.profile.terms = {{1.5, 1.0}}; // a kernel reach of 2 texels: the corner stays small
  const EffectPlan plan = plan_test::expect_built(build_glow(p));
  const PrunedGraph g = prune_glow(plan, s);
  EXPECT_TRUE(g.left_out.empty());
  ASSERT_EQ(g.limited.size(), 4u);
  for (const PassDesc& p : g.graph.passes) {
    if (p.name == "composite") {
      EXPECT_FALSE(p.draw.scissor) << p.name; // the frame is drawn whole
      continue;
    }
    ASSERT_TRUE(p.draw.scissor) << p.name;
    const TextureDesc* t = g.graph.find_texture(p.target);
    const int64_t area = int64_t(p.draw.scissor->x1 - p.draw.scissor->x0) *
                         (p.draw.scissor->y1 - p.draw.scissor->y0);
    EXPECT_EQ(p.draw.scissor->x0, 0);
    EXPECT_EQ(p.draw.scissor->y0, 0);
    EXPECT_LT(area * 2, int64_t(t->width) * t->height) << p.name; // under half of it
  }
}

// One source pixel anywhere (edges and corners included), every tier, format, downsample
// and both half-texel settings: the margins of the scissor rule are wide enough.
TEST(Prune, SingleSourcePixelsUnchanged) {
  std::mt19937 rng(5);
  const uint32_t w = 41, h = 23;
  const std::pair<uint32_t, uint32_t> spots[] = {
      {0, 0}, {w - 1, h - 1}, {20, 11}, {rng() % w, rng() % h}};
  for (const auto& [x, y] : spots) {
    img::Image s(w, h);
    s.at(x, y)[0] = 1, s.at(x, y)[1] = 0.5f, s.at(x, y)[3] = 1;
    for (Tier t : all_tiers())
      for (img::Format f : kFormats)
        for (unsigned ds : {1u, 2u, 3u, 4u}) {
          EffectParams p = params(w, h, t, f, ds);
          p.half_texel = (x + ds) % 2 == 0;
          expect_same(p, s, fmt::format("pixel ({}, {})", x, y));
        }
  }
}

// The scissor honoured by the Vulkan device and the analytic device: the pruned plan's glow
// and frame equal the whole plan's on each (bit for bit in RGBA8 and RGBA16F).
class PruneDevices : public vulkan::test::VulkanTest {};

TEST_F(PruneDevices, LimitedPassesGiveTheSameFrameOnVulkanAndAnalytic) {
  img::Image s = make_default_scene(96, 64);
  for (size_t i = 3; i < s.rgba.size(); i += 4) s.rgba[i] = 0;
  for (uint32_t y = 50; y < 56; ++y)
    for (uint32_t x = 80; x < 90; ++x) s.at(x, y)[3] = 1, s.at(x, y)[1] = 0.7f;
  for (Tier t : all_tiers())
    for (img::Format f : kFormats) {
      const EffectParams p = params(96, 64, t, f, 2);
      const PlanResult plan_built = build_glow(p);
      ASSERT_TRUE(plan_built) << plan_built.message();
      const EffectPlan& plan = *plan_built;
      const PrunedGraph pruned = prune_glow(plan, s);
      ASSERT_EQ(pruned.limited.size(), 4u) << tier_name(t);
      EffectPlan lean = plan;
      lean.graph = pruned.graph;
      auto vk_whole = make_vulkan_pass_device(*dev), vk_lean = make_vulkan_pass_device(*dev);
      auto an_whole = make_analytic_pass_device(), an_lean = make_analytic_pass_device();
      const std::pair<PassDevice*, PassDevice*> pairs[] = {{vk_whole.get(), vk_lean.get()},
                                                           {an_whole.get(), an_lean.get()}};
      for (const auto& [a, b] : pairs) {
        const EffectRun whole = run_effect(plan, s, *a), part = run_effect(lean, s, *b);
        ASSERT_TRUE(whole.run.ok() && part.run.ok()) << whole.run.message() << part.run.message();
        for (const char* tex : {"glow", "final"}) {
          const std::vector<float>& x = whole.images.at(tex).rgba;
          const std::vector<float>& y = part.images.at(tex).rgba;
          ASSERT_EQ(x.size(), y.size());
          size_t differ = 0;
          for (size_t i = 0; i < x.size(); ++i)
            differ += f == img::Format::RGBA32F ? !(std::abs(x[i] - y[i]) <= 1e-6f) : x[i] != y[i];
          EXPECT_EQ(differ, 0u) << a->name() << " " << tier_name(t) << " " << img::format_name(f)
                                << " " << tex;
        }
      }
    }
}

TEST(Prune, NoSourcesRunsNoBlur) {
  img::Image s = make_default_scene(64, 48);
  for (size_t i = 3; i < s.rgba.size(); i += 4) s.rgba[i] = 0;
  for (Tier t : all_tiers())
    for (img::Format f : kFormats) {
      const EffectParams p = params(64, 48, t, f, 2);
      const PrunedGraph g = prune_glow(plan_test::expect_built(build_glow(p)), s);
      ASSERT_EQ(g.graph.passes.size(), 1u);
      EXPECT_EQ(g.graph.passes[0].name, "composite");
      expect_same(p, s, "none");
    }
}

TEST(Prune, NonFiniteScenesAndUnreadPasses) {
  img::Image s = make_default_scene(32, 16);
  s.at(3, 3)[0] = NAN;
  const EffectPlan plan =
      plan_test::expect_built(build_glow(params(32, 16, Tier::Dx9, img::Format::RGBA8, 2)));
  EXPECT_TRUE(prune_glow(plan, s).left_out.empty());
  // A pass whose target nothing reads: left out by the generic rule.
  EffectGraph g = plan.graph;
  PassDesc extra = g.passes.front();
  extra.name = "unread";
  extra.target = std::string(kBlurHTexture);
  g.passes.push_back(extra); // after the last reader of blur_h
  const PrunedGraph r = prune_unread(g, kFinalTexture);
  ASSERT_EQ(r.left_out.size(), 1u);
  EXPECT_EQ(r.left_out[0].what, "unread");
}

// What the tap rule keeps is said, with the reason: every tap of a float target (the
// smallest one's weight × bound against half the format's smallest step) and every ps.1.x
// blur pass of an rgba8 target.
TEST(Prune, KeptTapsAreExplained) {
  const img::Image scene = make_default_scene(320, 180);
  for (img::Format f : {img::Format::RGBA16F, img::Format::RGBA32F}) {
    const PrunedGraph g =
        prune_glow(plan_test::expect_built(build_glow(params(320, 180, Tier::Dx9, f, 4))), scene);
    ASSERT_EQ(g.kept.size(), 1u) << img::format_name(f);
    EXPECT_EQ(g.kept[0].what, "every blur tap");
    EXPECT_NE(g.kept[0].why.find("every tap can change a stored value"), std::string::npos)
        << g.kept[0].why;
    EXPECT_NE(g.kept[0].why.find(f == img::Format::RGBA16F ? "2.98e-08" : "1.18e-38"),
              std::string::npos)
        << g.kept[0].why; // 2^-25 and 2^-126
  }
  const PrunedGraph dx8 = prune_glow(
      plan_test::expect_built(build_glow(params(320, 180, Tier::Dx8, img::Format::RGBA8, 4))),
      scene);
  ASSERT_EQ(dx8.kept.size(), 1u);
  EXPECT_NE(dx8.kept[0].why.find("ps.1.x"), std::string::npos) << dx8.kept[0].why;
  const PrunedGraph dx9 = prune_glow(
      plan_test::expect_built(build_glow(params(320, 180, Tier::Dx9, img::Format::RGBA8, 4))),
      scene);
  EXPECT_TRUE(dx9.kept.empty()); // ps_2_0 passes are judged one by one (left out or kept)
}

} // namespace
} // namespace tierlift::effects
