// After-image feedback and ramped parameters over frames (glow.h, run_effect_frames), on the
// CPU and Vulkan devices, against closed forms computed here in double:
//   Sources: s_N = x·(1 − g^N)/(1 − g) → x/(1 − g)
//   Glow:    y_∞ = B(I − gB)⁻¹x, B the separable blur with clamp-to-edge addressing, solved
//            here by its own Neumann series, independent of the devices
//   RGBA8:   s_n = round(X + g·s_(n−1)) in steps climbs to min(255, ⌈(X − ½)/(1 − g)⌉) and
//            stalls there, short of X/(1 − g)
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/glow/glow_run.h"

namespace tierlift::effects {
namespace {

constexpr uint32_t kW = 16, kH = 12;

// A few glowing texels (alpha 1) of values k/255 on a dark ground (alpha 0): the glow
// sources x are the glowing texels' rgb, 0 elsewhere.
img::Image test_scene(img::Format format) {
  img::Image im(kW, kH, format);
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      float* p = im.at(x, y);
      p[0] = p[1] = p[2] = 10.0f / 255;
      p[3] = 0;
    }
  auto put = [&](uint32_t x, uint32_t y, int r, int g, int b) {
    float* p = im.at(x, y);
    p[0] = float(r) / 255, p[1] = float(g) / 255, p[2] = float(b) / 255, p[3] = 1;
  };
  put(3, 3, 20, 50, 3);
  put(4, 3, 3, 20, 50);
  put(12, 8, 50, 3, 20);
  put(0, 11, 20, 20, 20); // at a corner: the clamp-to-edge reads
  return im;
}

// The glow sources x (rgb × alpha) in double.
std::vector<double> sources(const img::Image& scene) {
  std::vector<double> x(size_t(kW) * kH * 3);
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t i = 0; i < kW; ++i)
      for (int c = 0; c < 3; ++c)
        x[(size_t(y) * kW + i) * 3 + c] = double(scene.at(i, y)[c]) * scene.at(i, y)[3];
  return x;
}

// B: the blur along x, then along y, with the plan's taps and clamp-to-edge addressing.
std::vector<double> blur(const std::vector<double>& in, const std::vector<BlurTap>& taps) {
  auto pass = [&](const std::vector<double>& src, bool vertical) {
    std::vector<double> out(src.size(), 0.0);
    for (uint32_t y = 0; y < kH; ++y)
      for (uint32_t x = 0; x < kW; ++x)
        for (const BlurTap& t : taps) {
          const auto o = static_cast<int64_t>(std::lround(t.offset));
          const int64_t sx = vertical ? x : std::clamp<int64_t>(x + o, 0, kW - 1);
          const int64_t sy = vertical ? std::clamp<int64_t>(y + o, 0, kH - 1) : y;
          for (int c = 0; c < 3; ++c)
            out[(size_t(y) * kW + x) * 3 + c] +=
                t.weight * src[(size_t(sy) * kW + size_t(sx)) * 3 + c];
        }
    return out;
  };
  return pass(pass(in, false), true);
}

EffectParams params(Afterimage mode, double g, img::Format format) {
  EffectParams p;
  p.width = kW;
  p.height = kH;
  p.downsample = 1;
  p.format = format;
  p.afterimage = mode;
  p.afterimage_gain = g;
  p.profile.terms = {{1.0, 1.0}}; // σ 1: a small kernel
  return p;
}

// Runs `frames` frames and returns `texture` after the last one.
img::Image last_frame(PassDevice& device, const EffectPlan& plan, const img::Image& scene,
                      unsigned frames, const std::string& texture) {
  img::Image last;
  const EffectFrames run = run_effect_frames(plan, scene, device, frames, {texture},
                                             [&](unsigned f, const ImageMap& images) {
                                               if (f + 1 == frames) last = images.at(texture);
                                               return ir::ok_status();
                                             });
  EXPECT_TRUE(run.run.ok()) << run.run.message();
  return last;
}

void expect_near_all(const img::Image& got, const std::vector<double>& want, double tol,
                     const std::string& what) {
  ASSERT_EQ(got.width, kW);
  double worst = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c)
        worst =
            std::max(worst, std::abs(double(got.at(x, y)[c]) - want[(size_t(y) * kW + x) * 3 + c]));
  EXPECT_LE(worst, tol) << what;
}

void sources_series(PassDevice& device) {
  const double g = 0.5;
  const unsigned n = 8;
  const img::Image scene = test_scene(img::Format::RGBA32F);
  const PlanResult plan_built = build_glow(params(Afterimage::Sources, g, img::Format::RGBA32F));
  ASSERT_TRUE(plan_built) << plan_built.message();
  const EffectPlan& plan = *plan_built;
  const img::Image fed = last_frame(device, plan, scene, n, std::string(kFedTexture));
  std::vector<double> want = sources(scene);
  for (double& v : want) v *= (1 - std::pow(g, n)) / (1 - g);
  // fp32: each frame one mad of values ≤ 2·x; 8 frames stay far inside 1e-5 of full scale.
  expect_near_all(fed, want, 1e-5, device.name() + ": s_N = x(1 − g^N)/(1 − g)");
}

void glow_steady_state(PassDevice& device) {
  const double g = 0.5;
  const unsigned n = 40; // g^40 ≈ 1e-12: the series has converged far below fp32's step
  const img::Image scene = test_scene(img::Format::RGBA32F);
  const PlanResult plan_built = build_glow(params(Afterimage::Glow, g, img::Format::RGBA32F));
  ASSERT_TRUE(plan_built) << plan_built.message();
  const EffectPlan& plan = *plan_built;
  // y = B(I − gB)⁻¹x: z = (I − gB)⁻¹x by z ← x + g·B z until it stops changing.
  const std::vector<double> x = sources(scene);
  std::vector<double> z = x;
  for (int it = 0; it < 200; ++it) {
    std::vector<double> bz = blur(z, plan.taps);
    for (size_t i = 0; i < z.size(); ++i) z[i] = x[i] + g * bz[i];
  }
  const std::vector<double> want = blur(z, plan.taps);
  const img::Image glow = last_frame(device, plan, scene, n, std::string(kGlowTexture));
  expect_near_all(glow, want, 1e-5, device.name() + ": y = B(I − gB)⁻¹x");
}

// RGBA8: each fed level climbs to ⌈(X − ½)/(1 − g)⌉ (at most 255) and stalls there.
void rgba8_stall(PassDevice& device, Tier tier) {
  const double g = 0.8;
  const img::Image scene = test_scene(img::Format::RGBA8);
  EffectParams p = params(Afterimage::Sources, g, img::Format::RGBA8);
  p.tier = tier;
  const PlanResult plan_built = build_glow(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  const EffectPlan& plan = *plan_built;
  const img::Image fed = last_frame(device, plan, scene, 40, std::string(kFedTexture));
  int checked = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        const double xs = std::round(double(scene.at(x, y)[c]) * scene.at(x, y)[3] * 255);
        const double stall = std::min(255.0, std::ceil((xs - 0.5) / (1 - g)));
        const double level = std::round(double(fed.at(x, y)[c]) * 255);
        EXPECT_EQ(level, xs == 0 ? 0 : stall) << device.name() << " at " << x << "," << y;
        if (xs == 20) {
          EXPECT_EQ(level, 98) << "20/(1 − 0.8) = 100 in exact arithmetic";
        }
        checked += xs > 0;
      }
  EXPECT_EQ(checked, 12);
}

// Intensity ramped [[1, 0], [5, 2]]: final = scene + intensity(f)·glow with intensity
// 0, 0.5, 1, 1.5, 2 over frames 1..5 (and the glow the same every frame).
void ramped_intensity(PassDevice& device) {
  const img::Image scene = test_scene(img::Format::RGBA32F);
  EffectParams p = params(Afterimage::Off, 0, img::Format::RGBA32F);
  p.intensity_ramp.points = {{1, 0.0}, {5, 2.0}};
  p.intensity = 0;
  const PlanResult plan_built = build_glow(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  const EffectPlan& plan = *plan_built;
  const double want[] = {0, 0.5, 1, 1.5, 2};
  unsigned seen = 0;
  const std::string final_name(kFinalTexture), glow_name(kGlowTexture);
  const EffectFrames run = run_effect_frames(
      plan, scene, device, 7, {final_name, glow_name}, [&](unsigned f, const ImageMap& images) {
        const img::Image& fin = images.at(final_name);
        const img::Image& glow = images.at(glow_name);
        const double k = want[std::min(f, 4u)]; // held after the last keyframe
        double worst = 0;
        // downsample 1: the composite's bilinear read of the glow lands on texel centres.
        for (uint32_t y = 0; y < kH; ++y)
          for (uint32_t x = 0; x < kW; ++x)
            for (int c = 0; c < 3; ++c)
              worst = std::max(worst, std::abs(double(fin.at(x, y)[c]) - scene.at(x, y)[c] -
                                               k * glow.at(x, y)[c]));
        EXPECT_LE(worst, 1e-6) << device.name() << " frame " << f + 1;
        ++seen;
        return ir::ok_status();
      });
  ASSERT_TRUE(run.run.ok()) << run.run.message();
  EXPECT_EQ(seen, 7u);
}

TEST(Afterimage, SourcesGeometricSeriesOnTheCpu) {
  CpuPassDevice cpu(2);
  sources_series(cpu);
}
TEST(Afterimage, GlowSteadyStateOnTheCpu) {
  CpuPassDevice cpu(2);
  glow_steady_state(cpu);
}
TEST(Afterimage, Rgba8StallOnTheCpu) {
  CpuPassDevice cpu(2);
  rgba8_stall(cpu, Tier::Dx9);
  rgba8_stall(cpu, Tier::Dx8);
  rgba8_stall(cpu, Tier::Dx7); // the dx8 mix listing; the blur is the stage states'
}
TEST(Ramping, IntensityKeyframesOnTheCpu) {
  CpuPassDevice cpu(2);
  ramped_intensity(cpu);
}

using AfterimageVulkan = vulkan::test::VulkanTest; // validation on: any message fails

TEST_F(AfterimageVulkan, SourcesGeometricSeries) {
  auto vk = make_vulkan_pass_device(*dev);
  sources_series(*vk);
}
TEST_F(AfterimageVulkan, GlowSteadyState) {
  auto vk = make_vulkan_pass_device(*dev);
  glow_steady_state(*vk);
}
TEST_F(AfterimageVulkan, Rgba8Stall) {
  auto vk = make_vulkan_pass_device(*dev);
  rgba8_stall(*vk, Tier::Dx9);
  rgba8_stall(*vk, Tier::Dx8);
  rgba8_stall(*vk, Tier::Dx7);
}
TEST_F(AfterimageVulkan, IntensityKeyframes) {
  auto vk = make_vulkan_pass_device(*dev);
  ramped_intensity(*vk);
}

// The stall of a fading trail: the largest L with round(k·L) = L, found by trying every
// level, against rgba8_stall_level's formula.
TEST(Afterimage, Rgba8StallLevelMatchesASearch) {
  for (double k : {0.3, 0.5, 0.6, 0.75, 0.8, 0.9, 0.95, 0.97, 0.99, 0.999}) {
    int found = 0;
    for (int l = 1; l <= 255; ++l)
      if (std::abs(k * l - l) < 0.5) found = l; // rounds back to L (ties excluded)
    EXPECT_EQ(rgba8_stall_level(k), found) << k;
  }
  EXPECT_EQ(rgba8_stall_level(0.9), 4); // 4 → 3.6 → 4; 5 → 4.5 is a tie
}

TEST(Afterimage, WarningsNameRunawayAndStall) {
  EffectParams p = params(Afterimage::Glow, 1.5, img::Format::RGBA8);
  PlanResult plan_built = build_glow(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  std::vector<std::string> w = afterimage_warnings(p, plan.taps);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("runs away (to a white screen)"), std::string::npos) << w[0];
  p.afterimage = Afterimage::Sources;
  p.afterimage_gain = 0.9;
  w = afterimage_warnings(p, plan.taps);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("at or below 4/255 never fades"), std::string::npos) << w[0];
  p.format = img::Format::RGBA16F;
  EXPECT_TRUE(afterimage_warnings(p, plan.taps).empty());
}

TEST(Ramping, KeyframesAreLinearBetweenAndHeldOutside) {
  Keyframes k;
  k.points = {{3, 1.0}, {7, 3.0}, {8, 0.0}};
  EXPECT_EQ(k.at(1, 9), 1.0);
  EXPECT_EQ(k.at(3, 9), 1.0);
  EXPECT_EQ(k.at(5, 9), 2.0);
  EXPECT_EQ(k.at(7, 9), 3.0);
  EXPECT_EQ(k.at(8, 9), 0.0);
  EXPECT_EQ(k.at(100, 9), 0.0);
  EXPECT_EQ(k.max(9), 3.0);
  EXPECT_EQ(k.span(), 8u);
  EXPECT_EQ(Keyframes{}.at(4, 9), 9.0);
}

} // namespace
} // namespace tierlift::effects
