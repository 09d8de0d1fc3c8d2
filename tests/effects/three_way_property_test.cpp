// Property: every legal scene agrees three ways. Random scenes the scene schema accepts —
// blur profiles of one to three Gaussians (σ from 0.05 px up) with or without the sawtooth,
// downsample 1–4, tier dx9 or dx8, every target format, the half texel on or off, odd sizes,
// intensity within the tier's range — each run on the interpreter, on lavapipe and by the
// analytic device, every pair held to docs/design.md's targets on every pass. A fixed seed and a
// bounded count keep it reproducible and within CI time; a failure names the scene.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <sstream>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"

namespace tierlift::effects {
namespace {

constexpr int kScenes = 64; // about 0.2 s each here: bounded for CI

struct RandomScene {
  EffectParams params;
  img::Image image;
  std::string description;
};

RandomScene draw_scene(std::mt19937& rng) {
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<>(lo, hi)(rng);
  };
  auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(rng); };
  RandomScene s;
  EffectParams& p = s.params;
  p.tier = pick(0, 1) ? Tier::Dx9 : Tier::Dx8;
  p.downsample = unsigned(pick(1, 4));
  const img::Format formats[] = {img::Format::RGBA8, img::Format::RGBA16F, img::Format::RGBA32F};
  p.format = formats[pick(0, 2)];
  p.half_texel = pick(0, 1) == 1;
  p.width = uint32_t(2 * pick(6, 40) + 1); // odd sizes, 13..81
  p.height = uint32_t(2 * pick(5, 25) + 1);
  p.subtexel_bits = 0;
  p.intensity = uniform(0, p.tier == Tier::Dx8 ? 4.0 : 6.0);
  BlurProfile profile;
  const int gaussians = pick(0, 3);
  const bool saw = gaussians == 0 || pick(0, 2) == 0;
  for (int g = 0; g < gaussians; ++g) {
    // σ log-uniform in [0.05, 12] px: many below 1 (spikes narrower than a texel).
    const double sigma = 0.05 * std::pow(240.0, uniform(0, 1));
    profile.terms.push_back({sigma, uniform(0.05, 1)});
  }
  if (saw) profile.sawtooth = Sawtooth{uniform(1, 12), uniform(0, 24), uniform(0.05, 1)};
  p.profile = profile;
  std::ostringstream d;
  d << tier_name(p.tier) << " " << p.width << "x" << p.height << " ds" << p.downsample << " "
    << img::format_name(p.format) << (p.half_texel ? " half" : " nohalf") << " intensity "
    << p.intensity;
  for (const Gaussian& g : profile.terms) d << " gauss(" << g.sigma << ", " << g.weight << ")";
  if (profile.sawtooth)
    d << " saw(" << profile.sawtooth->period << ", " << profile.sawtooth->radius << ", "
      << profile.sawtooth->weight << ")";
  s.description = d.str();
  // rgb random multiples of 1/255; alpha 0, 1 or a random multiple of 1/255.
  s.image = img::Image(p.width, p.height);
  std::uniform_int_distribution<int> byte(0, 255);
  const int alpha_kind = pick(0, 1);
  for (size_t i = 0; i < s.image.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) s.image.rgba[i + c] = float(byte(rng)) / 255.0f;
    s.image.rgba[i + 3] = alpha_kind ? float(pick(0, 1)) : float(byte(rng)) / 255.0f;
  }
  return s;
}

class ThreeWayProperty : public vulkan::test::VulkanTest {};

TEST_F(ThreeWayProperty, EveryLegalRandomSceneAgreesThreeWays) {
  std::mt19937 rng(20261123u);
  int checked = 0;
  for (int n = 0; n < kScenes; ++n) {
    RandomScene s = draw_scene(rng);
    SCOPED_TRACE(s.description);
    PlanResult plan_built = build_glow(s.params);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built; // every drawn scene is legal
    CpuPassDevice cpu_dev(2);
    AnalyticPassDevice analytic;
    auto vk_dev = make_vulkan_pass_device(*dev);
    struct Way {
      const char* name;
      EffectRun run;
    };
    std::vector<Way> ways;
    ways.push_back({"cpu", run_effect(plan, s.image, cpu_dev, true)});
    ways.push_back({"vulkan", run_effect(plan, s.image, *vk_dev, true)});
    ways.push_back({"analytic", run_effect(plan, s.image, analytic, true)});
    for (const Way& w : ways) ASSERT_TRUE(w.run.run.ok()) << w.name << ": " << w.run.run.message();
    for (size_t a = 0; a < ways.size(); ++a)
      for (size_t b = a + 1; b < ways.size(); ++b) {
        ir::Result<RunAgreement> agree_compared =
            compare_runs(*ways[a].run.run, ways[a].run.images, *ways[b].run.run, ways[b].run.images,
                         std::string(kFinalTexture));
        ASSERT_TRUE(agree_compared.ok()) << agree_compared.message();
        const RunAgreement& agree = *agree_compared;
        for (const PassAgreement& row : agree.passes)
          EXPECT_TRUE(row.verdict.pass) << ways[a].name << " vs " << ways[b].name << ", "
                                        << row.pass << ": " << row.verdict.summary;
      }
    ++checked;
  }
  std::printf("[three-way property] %d random legal scenes, every pair within the targets\n",
              checked);
}

} // namespace
} // namespace tierlift::effects
