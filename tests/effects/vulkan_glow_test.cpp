// CPU vs Vulkan on the glow graph: every pass and the final frame within docs/design.md's
// agreement targets, with the validation layer on (its messages fail the test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/scenes/default_scene.h"

namespace tierlift::effects {
namespace {

struct Case {
  img::Format format;
  unsigned downsample;
  bool half_texel;
  Tier tier = Tier::Dx9;
  uint32_t width = 128, height = 64;
  bool random_scene = false; // else the default scene at that size
  double intensity = 1;
};

// A reproducible scene of random colours (multiples of 1/255; in RGBA32F a quarter of the
// pixels reach up to 2, which the ps.1.x tier reads clamped to 1) with alpha 0 or 1.
img::Image random_scene(uint32_t w, uint32_t h, img::Format f) {
  img::Image im(w, h, f);
  uint32_t state = 12345u + w * 7919u + h;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  };
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const float range = f == img::Format::RGBA32F && next() % 4 == 0 ? 2.0f : 1.0f;
      for (int c = 0; c < 3; ++c) im.at(x, y)[c] = range * float(next() % 256) / 255.0f;
      im.at(x, y)[3] = next() % 3 == 0 ? 1.0f : 0.0f;
    }
  return im;
}

class GlowVulkan : public vulkan::test::VulkanTest, public ::testing::WithParamInterface<Case> {};

using GlowVulkanDevice = vulkan::test::VulkanTest;

TEST_P(GlowVulkan, EveryPassAgrees) {
  const Case c = GetParam();
  EffectParams p;
  p.tier = c.tier;
  p.width = c.width;
  p.height = c.height;
  p.downsample = c.downsample;
  p.format = c.format;
  p.half_texel = c.half_texel;
  p.intensity = c.intensity;
  p.subtexel_bits = 0; // lavapipe weights float textures exactly (see cmd_glow.cpp)
  PlanResult plan_built = build_glow(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  const img::Image scene = c.random_scene ? random_scene(c.width, c.height, c.format)
                                          : make_default_scene(c.width, c.height, c.format);
  CpuPassDevice cpu_dev(2);
  auto vk_dev = make_vulkan_pass_device(*dev);
  EffectRun a = run_effect(plan, scene, cpu_dev, true);
  EffectRun b = run_effect(plan, scene, *vk_dev, true);
  ASSERT_TRUE(a.run.ok()) << a.run.message();
  ASSERT_TRUE(b.run.ok()) << b.run.message();
  ir::Result<RunAgreement> agree_compared =
      compare_runs(*a.run, a.images, *b.run, b.images, std::string(kFinalTexture));
  ASSERT_TRUE(agree_compared.ok()) << agree_compared.message();
  const RunAgreement& agree = *agree_compared;
  ASSERT_EQ(agree.passes.size(), plan.graph.passes.size() + 1);
  const std::string label = std::string("glow ") + std::string(tier_name(c.tier)) + " " +
                            std::string(img::format_name(c.format)) + " " +
                            std::to_string(c.width) + "x" + std::to_string(c.height) + "/" +
                            std::to_string(c.downsample) + " ";
  for (const PassAgreement& row : agree.passes) {
    EXPECT_TRUE(row.verdict.pass) << row.pass << ": " << row.verdict.summary;
    vulkan::test::report(label + row.pass, row.comparison);
  }
  EXPECT_TRUE(agree.all_pass);
  // The glow really is there: the final frame differs from the scene.
  EXPECT_NE(a.images.at(std::string(kFinalTexture)).rgba, a.images.at("scene").rgba);
}

// Readable parameters: "dx9 rgba32f 128x64 ds2 half-texel default-scene intensity 1".
void PrintTo(const Case& c, std::ostream* os) {
  *os << tier_name(c.tier) << " " << img::format_name(c.format) << " " << c.width << "x" << c.height
      << " ds" << c.downsample << (c.half_texel ? " half-texel" : " corners")
      << (c.random_scene ? " random-scene" : " default-scene");
}
std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  const Case& c = info.param;
  return fmt::format("{}_{}_ds{}_{}", tier_name(c.tier), img::format_name(c.format), c.downsample,
                     info.index);
}

INSTANTIATE_TEST_SUITE_P(Glow, GlowVulkan,
                         ::testing::Values(Case{img::Format::RGBA32F, 2, true},
                                           Case{img::Format::RGBA32F, 1, true},
                                           Case{img::Format::RGBA32F, 2, false},
                                           Case{img::Format::RGBA32F, 4, true},
                                           Case{img::Format::RGBA8, 3, true}),
                         case_name);

// Tier dx8 (Listings 3 + 4, ps.1.x helpers) on small odd sizes, both formats, N = 1, 2, 4.
constexpr Case dx8(img::Format f, unsigned n, bool random, bool half = true, double i = 1) {
  return Case{f, n, half, Tier::Dx8, 45, 27, random, i};
}
INSTANTIATE_TEST_SUITE_P(
    GlowDx8, GlowVulkan,
    ::testing::Values(dx8(img::Format::RGBA32F, 1, false), dx8(img::Format::RGBA32F, 2, false),
                      dx8(img::Format::RGBA32F, 4, false), dx8(img::Format::RGBA8, 1, false),
                      dx8(img::Format::RGBA8, 2, false), dx8(img::Format::RGBA8, 4, false),
                      dx8(img::Format::RGBA32F, 2, true), dx8(img::Format::RGBA8, 2, true),
                      dx8(img::Format::RGBA32F, 3, true, false),
                      dx8(img::Format::RGBA32F, 2, false, true, 2.5),
                      dx8(img::Format::RGBA8, 4, true, true, 0.5)),
    case_name);

// Bilinear read of `im` at texel-space position (gx, gy) (texel k centred at k + 0.5),
// clamp addressing, exact weights, in double.
double bilinear(const img::Image& im, double gx, double gy, int c) {
  auto at = [&](int64_t x, int64_t y) {
    x = std::clamp<int64_t>(x, 0, im.width - 1);
    y = std::clamp<int64_t>(y, 0, im.height - 1);
    return double(im.at(uint32_t(x), uint32_t(y))[c]);
  };
  const double fx = gx - 0.5, fy = gy - 0.5;
  const auto x0 = int64_t(std::floor(fx)), y0 = int64_t(std::floor(fy));
  const double a = fx - double(x0), b = fy - double(y0);
  return (1 - b) * ((1 - a) * at(x0, y0) + a * at(x0 + 1, y0)) +
         b * ((1 - a) * at(x0, y0 + 1) + a * at(x0 + 1, y0 + 1));
}

// RGBA8, downsample 2: the composite reads the 8-bit glow at bilinear fractions ¼ and ¾,
// so scene + glow often lands exactly halfway between two 8-bit steps (3a + b ≡ 2 mod 4),
// where D3D9 and Vulkan allow either rounding. The CPU device stores RGBA8 as lavapipe does
// (fl32(value·255) rounded to even, rounding::unorm8_llvmpipe) and weights bilinear reads as it
// does, so every pass and the final frame agree bit for bit, ties included. The test counts
// the ties (by exact math in double) to show they are there to be rounded.
TEST_F(GlowVulkanDevice, CompositeAgreesExactlyOnRoundingTies) {
  EffectParams p;
  p.width = 128;
  p.height = 64;
  p.downsample = 2;
  p.format = img::Format::RGBA8;
  PlanResult plan_built = build_glow_dx9(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  const img::Image scene = make_default_scene(128, 64, p.format);
  CpuPassDevice cpu_dev(2);
  auto vk_dev = make_vulkan_pass_device(*dev);
  EffectRun a = run_effect(plan, scene, cpu_dev, true);
  EffectRun b = run_effect(plan, scene, *vk_dev, true);
  ASSERT_TRUE(a.run.ok() && b.run.ok()) << a.run.message() << b.run.message();
  ASSERT_EQ(a.run->passes.size(), b.run->passes.size());
  for (size_t i = 0; i < a.run->passes.size(); ++i)
    EXPECT_EQ(a.run->passes[i].result.rgba, b.run->passes[i].result.rgba) << a.run->passes[i].pass;
  const std::string glow(kGlowTexture), fin(kFinalTexture);
  ASSERT_EQ(a.images.at(glow).rgba, b.images.at(glow).rgba);
  const img::Image &fa = a.images.at(fin), &fb = b.images.at(fin);
  uint64_t ties = 0, differ = 0;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 128; ++x)
      for (int c = 0; c < 3; ++c) {
        const double exact = double(scene.at(x, y)[c]) +
                             bilinear(a.images.at(glow), (x + 0.5) / 2, (y + 0.5) / 2, c);
        const double steps = exact * 255;
        if (exact < 1 && std::abs(steps - std::floor(steps) - 0.5) < 1e-4) ++ties;
        if (fa.at(x, y)[c] != fb.at(x, y)[c]) ++differ;
      }
  EXPECT_EQ(fa.rgba, fb.rgba);
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(ties, 0u); // the ties are there: both devices rounded every one the same way
  std::printf("[glow-rgba8] composite: %llu exact rounding ties, all stored alike\n",
              static_cast<unsigned long long>(ties));
}

// With alpha 0 everywhere the Vulkan device too must return the scene exactly.
TEST_F(GlowVulkanDevice, NothingGlowsGivesTheSceneBack) {
  for (img::Format f : {img::Format::RGBA32F, img::Format::RGBA8}) {
    EffectParams p;
    p.width = 128;
    p.height = 64;
    p.format = f;
    PlanResult plan_built = build_glow_dx9(p);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    img::Image scene = make_default_scene(128, 64, f);
    for (size_t i = 3; i < scene.rgba.size(); i += 4) scene.rgba[i] = 0.0f;
    auto vk_dev = make_vulkan_pass_device(*dev);
    EffectRun g = run_effect(plan, scene, *vk_dev);
    ASSERT_TRUE(g.run.ok()) << g.run.message();
    EXPECT_EQ(g.images.at(std::string(kFinalTexture)).rgba, scene.rgba);
  }
}

} // namespace
} // namespace tierlift::effects
