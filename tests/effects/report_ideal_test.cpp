// The report's error against the ideal glow, checked against an independent computation: a
// direct 2D convolution in double written here (every source pixel times a kernel whose cell
// weights are integrated numerically from the Gaussian density, not with erf), and the
// report's figures for a run compared with figures computed here from that run's images.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/report/ideal_glow.h"
#include "tierlift/effects/report/report_sweep.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

// ∫_{d−½}^{d+½} N(x; 0, σ) dx by Simpson's rule on 2000 intervals.
double cell(double d, double sigma) {
  constexpr int kN = 2000;
  const double a = d - 0.5, h = 1.0 / kN;
  auto f = [sigma](double x) {
    return std::exp(-x * x / (2 * sigma * sigma)) / (sigma * std::sqrt(2 * std::numbers::pi));
  };
  double s = f(a) + f(a + 1);
  for (int i = 1; i < kN; ++i) s += f(a + i * h) * (i % 2 ? 4 : 2);
  return s * h / 3;
}

double kernel(int d, const BlurProfile& p) {
  double k = 0;
  for (const Gaussian& g : p.terms) k += g.weight * cell(d, g.sigma);
  return k;
}

// A small scene: dark ground, a few glowing pixels and a half-transparent strip.
img::Image small_scene() {
  img::Image s(23, 17);
  for (uint32_t y = 0; y < s.height; ++y)
    for (uint32_t x = 0; x < s.width; ++x) {
      float* p = s.at(x, y);
      p[0] = 0.05f, p[1] = 0.04f, p[2] = 0.06f, p[3] = 0;
    }
  auto put = [&](uint32_t x, uint32_t y, float r, float g, float b, float a) {
    float* p = s.at(x, y);
    p[0] = r, p[1] = g, p[2] = b, p[3] = a;
  };
  put(3, 4, 1, 0.2f, 0.8f, 1);
  put(15, 10, 0.25f, 0.9f, 1, 1);
  for (uint32_t x = 6; x < 19; ++x) put(x, 13, 1, 0.75f, 0.1f, 0.5f);
  return s;
}

BlurProfile profile() {
  BlurProfile p;
  p.terms = {{2.5, 0.6}, {0.8, 0.4}};
  return p;
}

// Σ over every source pixel of src · K(i − x) · K(j − y): the ideal glow, directly.
RgbImage direct_ideal(const img::Image& scene, const BlurProfile& p) {
  RgbImage out{scene.width, scene.height,
               std::vector<double>(size_t{scene.width} * scene.height * 3)};
  // K(d) for every distance the image has, integrated once.
  const int reach = int(std::max(scene.width, scene.height));
  std::vector<double> k1(size_t(2 * reach + 1));
  for (int d = -reach; d <= reach; ++d) k1[size_t(d + reach)] = kernel(d, p);
  auto kernel = [&](int d, const BlurProfile&) { return k1[size_t(d + reach)]; };
  for (uint32_t j = 0; j < scene.height; ++j)
    for (uint32_t i = 0; i < scene.width; ++i)
      for (uint32_t y = 0; y < scene.height; ++y)
        for (uint32_t x = 0; x < scene.width; ++x) {
          const float* s = scene.at(x, y);
          const double k = kernel(int(i) - int(x), p) * kernel(int(j) - int(y), p);
          for (int c = 0; c < 3; ++c) out.at(i, j)[c] += double(s[c]) * s[3] * k;
        }
  return out;
}

TEST(ReportIdeal, IdealGlowEqualsADirectConvolution) {
  const img::Image scene = small_scene();
  const RgbImage mine = ideal_glow(glow_sources(scene), profile());
  const RgbImage direct = direct_ideal(scene, profile());
  ASSERT_EQ(mine.rgb.size(), direct.rgb.size());
  double worst = 0;
  for (size_t i = 0; i < mine.rgb.size(); ++i)
    worst = std::max(worst, std::abs(mine.rgb[i] - direct.rgb[i]));
  // Simpson on 2000 intervals is exact to ~1e-14 for these σ; the 8σ cut drops < 1.3e-15.
  EXPECT_LT(worst, 1e-12);
}

TEST(ReportIdeal, SinglePixelClosedForm) {
  img::Image s(41, 41);
  float* c = s.at(20, 20);
  c[0] = c[1] = c[2] = c[3] = 1;
  BlurProfile p;
  p.terms = {{3.0, 1.0}};
  const RgbImage g = ideal_glow(glow_sources(s), p);
  // The centre: (Φ(½/σ) − Φ(−½/σ))² = erf(½/(σ√2))².
  const double e = std::erf(0.5 / (3.0 * std::sqrt(2.0)));
  EXPECT_NEAR(g.at(20, 20)[0], e * e, 1e-15);
}

// The report's error figures for a configuration equal those computed here from a run of
// the same configuration against the direct ideal (downsample 1: the glow texture is read at
// texel centres, so the glow compared is the texture itself).
TEST(ReportIdeal, SweepErrorsEqualAnIndependentComputation) {
  Scene scene = default_scene();
  scene.params.width = 23;
  scene.params.height = 17;
  scene.params.profile = profile();
  scene.params.intensity = 1.5;
  const img::Image image = small_scene();
  for (img::Format format : {img::Format::RGBA32F, img::Format::RGBA8}) {
    scene.params.downsample = 1;
    scene.params.format = format;
    SweepSettings s;
    s.tiers = {Tier::Dx9};
    s.downsamples = {1};
    s.taps = {1.0};
    s.formats = {format};
    s.half_texels = {true};
    s.frames = 1;
    s.timed = {"cpu"};
    const ir::Result<SweepResult> swept = run_sweep(scene, image, s, nullptr);
    ASSERT_TRUE(swept.ok()) << swept.message();
    const SweepResult& r = *swept;
    ASSERT_EQ(r.configs.size(), 1u); // the scene's own choice is the sweep's only point
    const ConfigResult& c = r.configs[0];
    ASSERT_TRUE(c.skipped.empty()) << c.skipped;
    EXPECT_TRUE(c.all_agree);

    CpuPassDevice cpu;
    const PlanResult plan = build_glow(scene.params);
    ASSERT_TRUE(plan) << plan.message();
    const EffectRun run = run_effect(*plan, image, cpu);
    ASSERT_TRUE(run.run.ok()) << run.run.message();
    const RgbImage ideal = direct_ideal(image, scene.params.profile);
    const img::Image& glow = run.images.at("glow");
    const img::Image& final = run.images.at("final");
    double gmax = 0, gsq = 0, fmax = 0, fsq = 0;
    size_t goff = 0, foff = 0;
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x) {
        double gw = 0, fw = 0;
        for (int k = 0; k < 3; ++k) {
          const double gi = ideal.at(x, y)[k];
          // The final frame is compared as displayed: both sides clamped to [0, 1].
          const double fi = std::clamp(image.at(x, y)[k] + scene.params.intensity * gi, 0.0, 1.0);
          const double fa = std::clamp(double(final.at(x, y)[k]), 0.0, 1.0);
          const double gd = std::abs(glow.at(x, y)[k] - gi), fd = std::abs(fa - fi);
          gw = std::max(gw, gd), fw = std::max(fw, fd);
          gsq += gd * gd, fsq += fd * fd;
        }
        gmax = std::max(gmax, gw), fmax = std::max(fmax, fw);
        goff += gw > 1.0 / 255, foff += fw > 1.0 / 255;
      }
    const double n = double(image.width) * image.height;
    EXPECT_NEAR(c.glow.max_abs, gmax, 1e-12);
    EXPECT_NEAR(c.glow.rmse, std::sqrt(gsq / (3 * n)), 1e-12);
    EXPECT_DOUBLE_EQ(c.glow.share_off, double(goff) / n);
    EXPECT_NEAR(c.final.max_abs, fmax, 1e-12);
    EXPECT_NEAR(c.final.rmse, std::sqrt(fsq / (3 * n)), 1e-12);
    EXPECT_DOUBLE_EQ(c.final.share_off, double(foff) / n);
    // RGBA32F at full resolution with every tap: only the discrete kernel (the profile
    // sampled at texel centres and normalised over ±3σ) differs from the ideal, and the
    // glow sources are in [0, 1]: that difference is a few percent of the peak at most.
    if (format == img::Format::RGBA32F) {
      EXPECT_LT(c.glow.max_abs, 0.05);
    }
    EXPECT_GT(c.glow.max_abs, 0); // the discrete kernel is not the continuous one
  }
}

TEST(ReportIdeal, SweepListsTheScenesChoiceFirstAndRefusesAnEmptySweep) {
  const Scene scene = default_scene();
  SweepSettings s = quick_sweep();
  const std::vector<SweepConfig> c = sweep_configs(s, scene.params);
  ASSERT_FALSE(c.empty());
  EXPECT_EQ(c[0].tier, scene.params.tier);
  EXPECT_EQ(c[0].downsample, scene.params.downsample);
  EXPECT_EQ(c[0].format, scene.params.format);
  for (size_t i = 0; i < c.size(); ++i)
    for (size_t j = i + 1; j < c.size(); ++j) EXPECT_FALSE(c[i] == c[j]) << i << " " << j;
  s.formats.clear();
  EXPECT_TRUE(sweep_configs(s, scene.params).empty());
  EXPECT_FALSE(
      run_sweep(scene, img::Image(scene.params.width, scene.params.height), s, nullptr).ok());
  // Every tier the glow has is in both sweeps.
  EXPECT_EQ(quick_sweep().tiers, all_tiers());
  EXPECT_EQ(full_sweep().tiers, all_tiers());
  EXPECT_GE(all_tiers().size(), 2u);
}

TEST(ReportIdeal, ParetoFrontKeepsOnlyUndominatedPoints) {
  auto point = [](double ms, double rmse) {
    ConfigResult c;
    c.times = {{"vulkan", 0, ms, ms, ms, 1}};
    c.final.rmse = rmse;
    return c;
  };
  const std::vector<ConfigResult> cs = {point(1, 0.5), point(2, 0.1), point(3, 0.2), point(4, 0.01),
                                        point(0.5, 0.9)};
  EXPECT_EQ(pareto_front(cs), (std::vector<size_t>{4, 0, 1, 3}));
}

TEST(ReportIdeal, ParetoFrontCountsNearlyEqualErrorsAsEqual) {
  auto point = [](double ms, double rmse) {
    ConfigResult c;
    c.times = {{"vulkan", 0, ms, ms, ms, 1}};
    c.final.rmse = rmse;
    return c;
  };
  // Twice as slow for 2e-12 less error (relative 2e-10): the slower one is dominated.
  EXPECT_EQ(pareto_front({point(1, 0.01), point(2, 0.01 - 2e-12)}), (std::vector<size_t>{0}));
  // Near 0 the absolute tolerance (1e-9) decides: 1e-12 against 0 is a tie.
  EXPECT_EQ(pareto_front({point(1, 1e-12), point(2, 0)}), (std::vector<size_t>{0}));
  // 1e-5 less error on 0.01 (relative 1e-3) is a real gain: both stay.
  EXPECT_EQ(pareto_front({point(1, 0.01), point(2, 0.01 - 1e-5)}), (std::vector<size_t>{0, 1}));
  // Equal time and errors within the tolerance: a tie, both kept.
  EXPECT_EQ(pareto_front({point(1, 0.01), point(1, 0.01 + 1e-12)}), (std::vector<size_t>{0, 1}));
  EXPECT_TRUE(same_error(0.5, 0.5 + 4e-7));
  EXPECT_FALSE(same_error(0.5, 0.5 + 6e-7));
}

} // namespace
} // namespace tierlift::effects
