// The agreement check can fail: an interpreter whose blur weights are off by 0.1 % (every
// blur pass's pixel constants × 1.001) must be caught by the comparison with the analytic
// device in every RGBA8 and RGBA16F setup of three_way_test.cpp (2 tiers × downsample 1, 2, 4
// × half texel on/off × 3 scenes). RGBA8: a 0.1 % shift moves a value of v by 0.255·v steps,
// so it crosses a rounding boundary at a share of the pixels far above the 0.1 % the targets
// allow, unless the comparison excused differences it has not proven to be rounding ties.
// RGBA16F: 0.1 % is about one half-float step at every value, so the stores differ almost
// everywhere. The control — the same setups unperturbed — must pass.
#include <gtest/gtest.h>

#include <cstdio>

#include "three_way_scenes.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/scenes/default_scene.h"

namespace tierlift::effects {
namespace {

using test_scenes::make_scene;
using test_scenes::Scene;

// Every blur pass's pixel constants (its weights) scaled by `factor`.
EffectPlan perturb_blur_weights(EffectPlan plan, float factor) {
  for (PassDesc& d : plan.graph.passes)
    if (d.name.rfind("blur_", 0) == 0)
      for (auto& c : d.draw.ps_constants.f)
        for (float& x : c) x *= factor;
  return plan;
}

void check_format(img::Format format) {
  int setups = 0, caught = 0;
  for (Tier tier : {Tier::Dx9, Tier::Dx8})
    for (unsigned n : {1u, 2u, 4u})
      for (bool half : {true, false})
        for (Scene s : {Scene::RandomBinaryAlpha, Scene::RandomAlpha, Scene::Default}) {
          EffectParams p;
          p.tier = tier;
          p.downsample = n;
          p.format = format;
          p.half_texel = half;
          p.subtexel_bits = 0;
          const img::Image scene = make_scene(s, p.width, p.height);
          const PlanResult plan_built = build_glow(p);
          ASSERT_TRUE(plan_built) << plan_built.message();
          const EffectPlan& plan = *plan_built;
          const std::string name = std::string(tier_name(tier)) + " ds" + std::to_string(n) +
                                   (half ? " half" : " nohalf") + " scene " +
                                   std::to_string(int(s));
          AnalyticPassDevice analytic;
          EffectRun model = run_effect(plan, scene, analytic, true);
          ASSERT_TRUE(model.run.ok()) << model.run.message();
          for (float factor : {1.0f, 1.001f}) {
            CpuPassDevice cpu_dev(2);
            EffectRun run = run_effect(perturb_blur_weights(plan, factor), scene, cpu_dev, true);
            ASSERT_TRUE(run.run.ok()) << run.run.message();
            ir::Result<RunAgreement> agree_compared = compare_runs(
                *run.run, run.images, *model.run, model.images, std::string(kFinalTexture));
            ASSERT_TRUE(agree_compared.ok()) << agree_compared.message();
            const RunAgreement& agree = *agree_compared;
            if (factor == 1.0f) {
              EXPECT_TRUE(agree.all_pass) << name << ": the unperturbed interpreter must agree";
            } else {
              ++setups;
              caught += !agree.all_pass;
              EXPECT_FALSE(agree.all_pass) << name << ": weights off by 0.1 % went unnoticed";
            }
          }
        }
  std::printf("[perturbation] %s: blur weights × 1.001 caught in %d of %d setups\n",
              std::string(img::format_name(format)).c_str(), caught, setups);
}

TEST(ThreeWayPerturbation, Rgba8WeightsOffByOneTenthPercentFailEverySetup) {
  check_format(img::Format::RGBA8);
}

TEST(ThreeWayPerturbation, Rgba16fWeightsOffByOneTenthPercentFailEverySetup) {
  check_format(img::Format::RGBA16F);
}

} // namespace
} // namespace tierlift::effects
