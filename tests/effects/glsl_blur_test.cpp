// The GLSL blur of seed 004 (effects/glsl_blur.h) checked three ways: the GLSL (glslang →
// SPIR-V on lavapipe) against its ps_2_0 twin on Vulkan and on the interpreter (RGBA32F
// ≤ 1e-5), and against the impulse response worked out by hand: one bright texel blurred by
// the 9-tap kernel along x then y is the outer product of the seed's weights.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/glsl_blur.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

// The seed's weights, typed in again from the article (not read from the code under test).
constexpr double kW[9] = {0.05, 0.09, 0.12, 0.15, 0.16, 0.15, 0.12, 0.09, 0.05};
constexpr uint32_t kSize = 512; // blurSize 1/512: one texel per step

EffectParams params_512() {
  EffectParams p;
  p.width = p.height = kSize;
  p.format = img::Format::RGBA32F;
  return p;
}

img::Image impulse(uint32_t x0, uint32_t y0) {
  img::Image im(kSize, kSize, img::Format::RGBA32F);
  im.at(x0, y0)[0] = 1.0f;
  im.at(x0, y0)[1] = 0.5f;
  im.at(x0, y0)[3] = 1.0f;
  return im;
}

// A reproducible scene of random values in [0, 2).
img::Image random_scene() {
  img::Image im(kSize, kSize, img::Format::RGBA32F);
  uint32_t state = 2024u;
  for (float& v : im.rgba) {
    state = state * 1664525u + 1013904223u;
    v = float(state >> 8) / float(1u << 23);
  }
  return im;
}

// The default blur run on `device` over impulse(x0, y0): final(x, y) = w[x − x0 + 4] ·
// w[y − y0 + 4] × the texel, zero outside the 9×9 footprint, within `tol`.
void expect_impulse_response(PassDevice& device, uint32_t x0, uint32_t y0, double tol,
                             const std::string& way) {
  PlanResult plan_built = build_glsl_blur(params_512(), GlslBlurParams{});
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectRun r = run_effect(*plan_built, impulse(x0, y0), device);
  ASSERT_TRUE(r.run.ok()) << way << ": " << r.run.message();
  const img::Image& out = r.images.at("final");
  double worst = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      const int dx = int(x) - int(x0), dy = int(y) - int(y0);
      const double k = std::abs(dx) <= 4 && std::abs(dy) <= 4 ? kW[dx + 4] * kW[dy + 4] : 0.0;
      const double want[4] = {k, 0.5 * k, 0, k};
      for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(out.at(x, y)[c] - want[c]));
    }
  EXPECT_LE(worst, tol) << way;
}

TEST(GlslBlur, GraphHasTwoGlslPassesWithTwinsAndKernels) {
  PlanResult plan_built = build_glsl_blur(params_512(), GlslBlurParams{});
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  ASSERT_EQ(plan.graph.passes.size(), 2u);
  for (const PassDesc& p : plan.graph.passes) {
    EXPECT_TRUE(p.draw.pixel_spirv && !p.draw.pixel_spirv->empty()) << p.name;
    EXPECT_EQ(p.draw.pixel_program->profile, ir::Profile::ps_2_0) << p.name;
    ASSERT_EQ(p.kernel.size(), 9u);
    double sum = 0;
    for (const KernelTap& t : p.kernel) sum += t.weight[0];
    EXPECT_NEAR(sum, 0.98, 1e-12);
  }
}

TEST(GlslBlur, WeightsSummingTo098AreReported) {
  const std::vector<std::string> w = glsl_blur_warnings(GlslBlurParams{});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "kernel weights sum to 0.98: the blur is 3.96 % darker than its source "
                  "(0.9604 after both axes)");
}

TEST(GlslBlur, AnalyticImpulseResponseIsTheOuterProductOfTheWeights) {
  auto dev = make_analytic_pass_device();
  // Double sums of nine products, stored as float: within float's half ulp of 0.16².
  expect_impulse_response(*dev, 200, 300, 1e-8, "analytic");
}

TEST(GlslBlur, CpuRunsTheTwinWithTheSameImpulseResponse) {
  CpuPassDevice cpu(2);
  // fp32: each output is a product of two fp32 weights (within 2^-24 relative each) summed
  // with zeros, so within 1e-7 of the exact product. The footprint touches the edges.
  expect_impulse_response(cpu, 4, 507, 1e-7, "cpu");
}

using GlslBlurVulkan = vulkan::test::VulkanTest;

TEST_F(GlslBlurVulkan, GlslImpulseResponseOnLavapipe) {
  auto vk = make_vulkan_pass_device(*dev);
  expect_impulse_response(*vk, 256, 256, 1e-7, "vulkan (GLSL)");
}

// The three ways on a random scene: GLSL on Vulkan, the twin on the interpreter, the kernel
// in double; and the twin on Vulkan against the GLSL on Vulkan.
TEST_F(GlslBlurVulkan, GlslTwinAndKernelAgreeWithin1e5) {
  PlanResult plan_built = build_glsl_blur(params_512(), GlslBlurParams{});
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  EffectPlan twin_plan = plan;
  for (PassDesc& p : twin_plan.graph.passes) p.draw.pixel_spirv.reset(); // ps_2_0 through codegen
  const img::Image scene = random_scene();
  auto vk = make_vulkan_pass_device(*dev);
  CpuPassDevice cpu(2);
  auto analytic = make_analytic_pass_device();
  EffectRun glsl_vk = run_effect(plan, scene, *vk, true);
  EffectRun twin_vk = run_effect(twin_plan, scene, *vk, true);
  EffectRun twin_cpu = run_effect(plan, scene, cpu, true);
  EffectRun math = run_effect(plan, scene, *analytic, true);
  for (const EffectRun* r : {&glsl_vk, &twin_vk, &twin_cpu, &math})
    ASSERT_TRUE(r->run.ok()) << r->run.message();
  const std::pair<const EffectRun*, const char*> others[] = {
      {&twin_vk, "ps_2_0 twin on vulkan"}, {&twin_cpu, "ps_2_0 twin on cpu"}, {&math, "analytic"}};
  for (const auto& [other, label] : others) {
    ir::Result<RunAgreement> a_compared =
        compare_runs(*glsl_vk.run, glsl_vk.images, *other->run, other->images, "final");
    ASSERT_TRUE(a_compared.ok()) << a_compared.message();
    const RunAgreement& a = *a_compared;
    for (const PassAgreement& row : a.passes) {
      EXPECT_TRUE(row.verdict.pass) << label << ", " << row.pass << ": " << row.verdict.summary;
      EXPECT_LE(row.comparison.max_abs_all, 1e-5) << label << ", " << row.pass;
      vulkan::test::report(std::string("glsl-blur GLSL vs ") + label + " " + row.pass,
                           row.comparison);
    }
  }
}

TEST(GlslBlur, BadGlslFileIsPositionedAndNamed) {
  const auto dir = std::filesystem::temp_directory_path() / "tierlift_glsl_blur_bad";
  std::filesystem::create_directories(dir);
  const auto file = dir / "bad.frag";
  std::ofstream(file) << "varying vec2 vTexCoord;\nvoid main(void)\n{\n  gl_FragColor = "
                         "texture2D(RTScene, vTexCoord);\n}\n";
  GlslBlurParams g;
  g.horizontal = file.string();
  const PlanResult plan = build_glsl_blur(params_512(), g);
  std::filesystem::remove_all(dir);
  ASSERT_FALSE(plan);
  // "  gl_FragColor = texture2D(" is 27 characters: RTScene starts at column 28 of line 4.
  EXPECT_EQ(
      plan.message().rfind(file.string() + ":4:28: error: 'RTScene': undeclared identifier", 0), 0u)
      << plan.message();
}

TEST(GlslBlur, SceneNamesTheEffect) {
  ir::Result<Scene> s =
      load_scene_file(std::string(TIERLIFT_SOURCE_DIR) + "/listings/scenes/glsl-blur.json");
  ASSERT_TRUE(s) << s.message();
  EXPECT_EQ(s->effect, EffectKind::GlslBlur);
  EXPECT_EQ(s->params.width, kSize);
  ASSERT_EQ(s->warnings.size(), 1u);
  EXPECT_NE(s->warnings[0].find("sum to 0.98"), std::string::npos);
  PlanResult plan_built = build_scene_effect(*s);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  EXPECT_EQ(plan.graph.passes.size(), 2u);
}

TEST(GlslBlur, GlslKeyBelongsToTheGlslEffect) {
  ir::Result<Scene> s = parse_scene("{\"glsl\": {}}", "x.json", "");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.message().rfind(
                "x.json:1:2: error: /glsl: \"glsl\" configures \"effect\": \"glsl-blur\"", 0),
            0u)
      << s.message();
  s = parse_scene("{\"effect\": \"glsl-blur\", \"glsl\": {\"weights\": [1, 2]}}", "y.json", "");
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("/glsl/weights"), std::string::npos) << s.message();
}

} // namespace
} // namespace tierlift::effects
