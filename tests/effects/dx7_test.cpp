// Tier dx7: the texture-stage-state format (parse errors at their position, the lowering),
// the 8-bit weight rounding against hand-computed values (the seed's 0.13 · 255 = 33.15
// example) and the error carry's running-sum bound, and the dx7 glow on the interpreter
// against a separable convolution computed here in double with the bytes the weights became.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "three_way_scenes.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/stage_states.h"
#include "tierlift/effects/glow/weight_quantize.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/ir/opcodes.h"
#include "tierlift/listings/embedded.h"

namespace tierlift::effects {
namespace {

// ---- weight rounding ----

TEST(Dx7Weights, TheSeedsExampleRoundsTo33AndCarriesTheRest) {
  // 0.13 · 255 = 33.15 → 33, carry 0.15; then 33.30 → 33 (0.30), 33.45 → 33 (0.45),
  // 33.60 → 34 (−0.40), 33.75 → 34 (−0.65 → next 32.5 + …).
  const std::vector<double> w(5, 0.13);
  EXPECT_EQ(quantize_weights(w, WeightRounding::Plain), (std::vector<uint8_t>{33, 33, 33, 33, 33}));
  EXPECT_EQ(quantize_weights(w, WeightRounding::ErrorCarry),
            (std::vector<uint8_t>{33, 33, 33, 34, 33}));
  // Five weights of 0.13 are 165.75 steps: plain rounding keeps 165, the carry 166.
}

TEST(Dx7Weights, ClampsToTheColoursRange) {
  EXPECT_EQ(quantize_weights({1.5, -0.2, 0.5}, WeightRounding::Plain),
            (std::vector<uint8_t>{255, 0, 128})); // 127.5 rounds half away from zero
}

TEST(Dx7Weights, ErrorCarryKeepsEveryRunningSumWithinHalfAStep) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 0.2);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> w(1 + trial % 60);
    for (double& x : w) x = u(rng);
    const std::vector<uint8_t> q = quantize_weights(w, WeightRounding::ErrorCarry);
    double ideal = 0, sum = 0;
    for (size_t i = 0; i < w.size(); ++i) {
      ideal += 255 * w[i];
      sum += q[i];
      ASSERT_LE(std::abs(sum - ideal), 0.5 + 1e-9) << "trial " << trial << " tap " << i;
    }
  }
}

TEST(Dx7Weights, SummaryStatesTheBrightnessErrorOfEachRounding) {
  // 0.13 × 5 = 165.75 steps: plain keeps 165 (0.452 % darker, 0.904 % after two axes),
  // the carry 166 (0.151 % brighter).
  const std::vector<double> w(5, 0.13);
  const std::string plain = quantization_summary(w, WeightRounding::Plain);
  EXPECT_NE(plain.find("165/255 per axis against 165.75/255"), std::string::npos) << plain;
  EXPECT_NE(plain.find("0.45 % darker per axis (0.90 % after both axes)"), std::string::npos)
      << plain;
  const std::string carry = quantization_summary(w, WeightRounding::ErrorCarry);
  EXPECT_NE(carry.find("166/255"), std::string::npos) << carry;
  EXPECT_NE(carry.find("0.15 % brighter"), std::string::npos) << carry;
}

TEST(Dx7Weights, NamesRoundTrip) {
  EXPECT_EQ(parse_weight_rounding("plain"), WeightRounding::Plain);
  EXPECT_EQ(parse_weight_rounding("error-carry"), WeightRounding::ErrorCarry);
  EXPECT_EQ(parse_weight_rounding("carry"), std::nullopt);
  EXPECT_EQ(weight_rounding_name(WeightRounding::ErrorCarry), "error-carry");
}

// ---- the .tss format ----

std::string errors_of(const std::string& text) {
  ir::Result<tss::Lowered> l = tss::load_stage_states(text, "bad.tss");
  EXPECT_FALSE(l) << text;
  return l.message();
}

TEST(StageStates, BadInputIsAPositionedError) {
  struct Case {
    const char* text;
    const char* expect;
  } cases[] = {
      {"stage 0: colourop modulate texture diffuse\n",
       "bad.tss:1:10: error: unknown texture-stage state 'colourop'"},
      {"# two\nstage 0: colorop multiply texture diffuse\n",
       "bad.tss:2:18: error: unknown operation 'multiply'"},
      {"stage 0: colorop modulate texture diffuse\nstage 1: colorop add current texture\n"
       "stage 2: colorop add current texture\n",
       "bad.tss:3:7: error: stage 2: this tier blends 2 textures in a pass"},
      {"stage 9: colorop modulate texture diffuse\n",
       "bad.tss:1:7: error: stage 9 is out of range: Direct3D numbers texture stages 0..7"},
      {"stage 0: colorop modulate texture\n",
       "bad.tss:1:34: error: modulate takes 2 arguments, 1 given"},
      {"stage 0: colorop modulate texture diffuse specular\n",
       "bad.tss:1:43: error: modulate takes 2 arguments"},
      {"stage 0: colorop modulate texture diffuse\nstage 0: colorop add texture diffuse\n",
       "bad.tss:2:10: error: stage 0: colorop is set twice (first at line 1)"},
      {"stage 0: alphaop modulatealpha_addcolor current texture\n",
       "bad.tss:1:18: error: modulatealpha_addcolor is a colour operation"},
      {"stage 0: colorop modulate texture shininess\n",
       "bad.tss:1:35: error: unknown argument 'shininess'"},
      {"tfactor 0x1ffffffff\n", "bad.tss:1:9: error: 0x1ffffffff is out of range"},
      {"stage 0: colorop disable\nstage 1: colorop add current texture\n",
       "bad.tss:2:1: error: stage 1 never runs: stage 0 ends the cascade"},
      {"stage 99999999999999999999: colorop add texture diffuse\n",
       "bad.tss:1:7: error: stage 99999999999999999999 is out of range"},
      {"blend one one\n", "bad.tss:1:1: error: 'blend' is not a statement"},
  };
  for (const Case& c : cases) {
    const std::string e = errors_of(c.text);
    EXPECT_NE(e.find(c.expect), std::string::npos) << "got: " << e << "\nwanted: " << c.expect;
    EXPECT_NE(e.find('^'), std::string::npos) << "a caret line: " << e;
  }
}

TEST(StageStates, AcceptsDirect3DSpellingsAndComments) {
  auto l = tss::load_stage_states("// D3D names\nSTAGE 0: D3DTSS_COLOROP D3DTOP_MODULATE "
                                  "D3DTA_TEXTURE, D3DTA_DIFFUSE  # t0 * diffuse\n",
                                  "ok.tss");
  ASSERT_TRUE(l) << l.message();
  EXPECT_EQ(l->texture_stages, 1u);
}

TEST(StageStates, TheBuiltInBlurQuadLowersToTwoTexturesAndOneVertexColour) {
  auto text = listings::find_embedded(kDx7BlurStates);
  ASSERT_TRUE(text);
  auto l = tss::load_stage_states(std::string(*text), "blur_pair.tss");
  ASSERT_TRUE(l) << l.message();
  EXPECT_EQ(l->texture_stages, 2u);
  EXPECT_EQ(l->ps->profile, ir::Profile::ps_1_1);
  EXPECT_EQ(l->vs->profile, ir::Profile::vs_1_1);
  EXPECT_NE(l->ps_text.find("tex t0\ntex t1\n"), std::string::npos) << l->ps_text;
  EXPECT_NE(l->ps_text.find("mad r0.rgb, t1, r0.a, r0"), std::string::npos) << l->ps_text;
  EXPECT_NE(l->vs_text.find("mov oD0, c8"), std::string::npos) << l->vs_text;
  EXPECT_EQ(l->vs_text.find("oD1"), std::string::npos) << "no specular read";
}

// ---- the dx7 glow against independent math ----

// sources = rgb · a (alpha kept); blur along x then y with clamp addressing and the weights
// the bytes carry (byte / 255), in double.
std::vector<double> expected_glow(const img::Image& scene, const std::vector<BlurTap>& taps,
                                  const std::vector<uint8_t>& bytes) {
  const int w = int(scene.width), h = int(scene.height);
  std::vector<double> src(size_t(w) * h * 4), mid(src.size()), out(src.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = scene.at(uint32_t(x), uint32_t(y));
      for (int c = 0; c < 3; ++c) src[(size_t(y) * w + x) * 4 + c] = double(p[c]) * p[3];
      src[(size_t(y) * w + x) * 4 + 3] = p[3];
    }
  auto blur = [&](const std::vector<double>& in, std::vector<double>& o, bool vertical) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) {
          double s = 0;
          for (size_t k = 0; k < taps.size(); ++k) {
            const int xx = std::clamp(x + (vertical ? 0 : taps[k].offset), 0, w - 1);
            const int yy = std::clamp(y + (vertical ? taps[k].offset : 0), 0, h - 1);
            s += bytes[k] / 255.0 * in[(size_t(yy) * w + xx) * 4 + c];
          }
          o[(size_t(y) * w + x) * 4 + c] = std::min(s, 1.0); // a stage saturates at 1
        }
  };
  blur(src, mid, false);
  blur(mid, out, true);
  return out;
}

TEST(Dx7Glow, InterpreterEqualsTheConvolutionWithTheQuantisedWeights) {
  for (WeightRounding r : {WeightRounding::Plain, WeightRounding::ErrorCarry}) {
    SCOPED_TRACE(std::string(weight_rounding_name(r)));
    EffectParams p;
    p.tier = Tier::Dx7;
    p.downsample = 1;
    p.weight_rounding = r;
    p.profile.terms = {{3, 0.8}, {1, 0.2}};
    const img::Image scene =
        test_scenes::make_scene(test_scenes::Scene::RandomAlpha, p.width, p.height);
    PlanResult plan_built = build_glow(p);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    ASSERT_EQ(plan.weight_bytes.size(), plan.taps.size());
    EXPECT_EQ(plan.blur_passes_per_axis, (plan.taps.size() + 1) / 2);
    EXPECT_FALSE(plan.quantization.empty());
    CpuPassDevice cpu(2);
    EffectRun run = run_effect(plan, scene, cpu, false);
    ASSERT_TRUE(run.run.ok()) << run.run.message();
    const img::Image& glow = run.images.at(std::string(kGlowTexture));
    const std::vector<double> want = expected_glow(scene, plan.taps, plan.weight_bytes);
    double worst = 0;
    for (size_t i = 0; i < want.size(); ++i)
      if (i % 4 != 3) worst = std::max(worst, std::abs(double(glow.rgba[i]) - want[i]));
    // RGBA32F target: fp32 sums of ≤ 2·(taps) products of values ≤ 1 stay within 1e-5.
    EXPECT_LE(worst, 1e-5);
  }
}

TEST(Dx7Glow, PlainRoundingOfTheDx7SceneKernelIsDarker) {
  EffectParams p;
  p.tier = Tier::Dx7;
  p.downsample = 2;
  p.profile.terms = {{24, 0.8}, {3, 0.2}}; // listings/scenes/dx7*.json
  p.weight_rounding = WeightRounding::Plain;
  const PlanResult plain_built = build_glow(p);
  p.weight_rounding = WeightRounding::ErrorCarry;
  const PlanResult carry_built = build_glow(p);
  ASSERT_TRUE(plain_built && carry_built);
  const EffectPlan &plain = *plain_built, &carry = *carry_built;
  unsigned sp = 0, sc = 0;
  for (uint8_t b : plain.weight_bytes) sp += b;
  for (uint8_t b : carry.weight_bytes) sc += b;
  EXPECT_EQ(plain.taps.size(), 73u);
  EXPECT_EQ(sp, 248u) << plain.quantization;
  EXPECT_EQ(sc, 255u) << carry.quantization;
}

TEST(Dx7Glow, ABadStageStateFileNamedByTheSceneIsAPositionedError) {
  const std::string path = ::testing::TempDir() + "dx7_bad.tss";
  {
    FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_TRUE(f);
    std::fputs("stage 0: colorop modulate texture diffuse\nstage 2: colorop add texture current\n",
               f);
    std::fclose(f);
  }
  EffectParams p;
  p.tier = Tier::Dx7;
  p.listing_files[std::string(kDx7BlurStates)] = path;
  const PlanResult plan = build_glow(p);
  EXPECT_FALSE(plan);
  EXPECT_NE(plan.message().find(path + ":2:7: error: stage 2"), std::string::npos)
      << plan.message();
  std::remove(path.c_str());
}

} // namespace
} // namespace tierlift::effects
