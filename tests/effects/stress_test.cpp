// The stress catalogue (tierlift/effects/report/stress.h): each case checked here against closed
// forms computed in the test (not read from the row), on the three ways; the verdict can fail.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/report/stress.h"
#include "tierlift/effects/scenes/scene.h"

namespace {

using namespace tierlift;
using effects::StressRow;

class Stress : public vulkan::test::VulkanTest {
protected:
  effects::StressOptions options() {
    effects::StressOptions o;
    vulkan::Device* d = dev;
    o.make_device = [d](const std::string& way) -> std::unique_ptr<effects::PassDevice> {
      if (way == "cpu") return std::make_unique<effects::CpuPassDevice>(1);
      if (way == "vulkan") return effects::make_vulkan_pass_device(*d);
      return effects::make_analytic_pass_device();
    };
    return o;
  }
  std::vector<StressRow> run(const std::string& id) {
    ir::Result<std::vector<StressRow>> ran = effects::run_stress_case(id, options());
    EXPECT_TRUE(ran) << ran.message();
    std::vector<StressRow> rows = ran ? std::move(ran).value() : std::vector<StressRow>{};
    EXPECT_FALSE(rows.empty());
    for (const StressRow& r : rows) {
      EXPECT_EQ(r.measured.size(), 3u) << r.id;
      EXPECT_EQ(r.verdict, "PASS") << r.id << ": " << r.error << " " << r.note;
    }
    return rows;
  }
  static const StressRow& row(const std::vector<StressRow>& rows, const std::string& id) {
    for (const StressRow& r : rows)
      if (r.id == id) return r;
    ADD_FAILURE() << "no row " << id;
    return rows.front();
  }
};

double value_of(const StressRow& r, const std::string& way) {
  for (const auto& m : r.measured)
    if (m.way == way) return m.value;
  return std::numeric_limits<double>::quiet_NaN();
}

TEST(StressJudge, AWrongExpectedValueFails) {
  StressRow r;
  r.measured = {{"cpu", 0.5, {}}, {"vulkan", 0.5, {}}, {"analytic", 0.5, {}}};
  r.expected = 0.5;
  effects::judge_stress_row(r);
  EXPECT_EQ(r.verdict, "PASS");
  r.expected = 0.6; // deliberately wrong
  effects::judge_stress_row(r);
  EXPECT_EQ(r.verdict, "FAIL");
  r.tolerance = 0.1 + 1e-12;
  effects::judge_stress_row(r);
  EXPECT_EQ(r.verdict, "PASS");
  r.error = "vulkan: lost";
  effects::judge_stress_row(r);
  EXPECT_EQ(r.verdict, "ERROR");
}

TEST(StressJudge, NaNMatchesNaNAndMasksMustAgree) {
  StressRow r;
  r.expected = std::numeric_limits<double>::quiet_NaN();
  r.measured = {{"cpu", std::nan(""), {}}, {"vulkan", std::nan(""), {}}};
  effects::judge_stress_row(r);
  EXPECT_EQ(r.verdict, "PASS");
  r.measured[1].value = std::numeric_limits<double>::infinity();
  effects::judge_stress_row(r);
  EXPECT_EQ(r.verdict, "FAIL");
  // Equal counts in different places: the ways do not agree.
  StressRow m;
  m.expected = 1;
  m.measured = {{"cpu", 1, {1, 0}}, {"vulkan", 1, {0, 1}}};
  effects::judge_stress_row(m);
  EXPECT_FALSE(m.ways_agree);
  EXPECT_EQ(m.verdict, "FAIL");
  // A documented difference (lavapipe's denormal flush) passes only for its way.
  StressRow d;
  d.expected = 1e-39;
  d.also_expected["vulkan"] = 0;
  d.measured = {{"cpu", 1e-39, {}}, {"vulkan", 0, {}}};
  effects::judge_stress_row(d);
  EXPECT_EQ(d.verdict, "PASS");
  d.measured[0].value = 0;
  effects::judge_stress_row(d);
  EXPECT_EQ(d.verdict, "FAIL");
}

TEST(StressJudge, CatalogueCoversTheIssuesRegimes) {
  const std::vector<std::string> ids = effects::stress_case_ids();
  for (const char* want : {"hdr.6e4.rgba16f", "hdr.6e4.rgba32f", "hdr.overflow.rgba16f",
                           "non-finite", "denormal.rgba32f", "sigma.tiny", "sigma.limit.rgba8",
                           "sigma.limit.rgba16f", "downsample.sizes", "intensity.1000.rgba8",
                           "weights", "feedback.g0.5.rgba8", "feedback.g1.01.rgba32f"})
    EXPECT_NE(std::find(ids.begin(), ids.end(), want), ids.end()) << want;
}

TEST_F(Stress, HdrCentreIsVTimesTheCentreTapSquared) {
  const double w0 = 1 / (1 + 2 * std::exp(-0.5) + 2 * std::exp(-2.0) + 2 * std::exp(-4.5));
  for (const char* id : {"hdr.6e4.rgba32f", "hdr.6e4.rgba16f"}) {
    const StressRow r = run(id).front();
    EXPECT_NEAR(r.expected, 6e4 * w0 * w0, 1e-9 * r.expected) << id;
    // Two half stores toward zero lose at most 2^-10 each.
    for (const auto& m : r.measured) EXPECT_NEAR(m.value, 6e4 * w0 * w0, 6e4 * w0 * w0 * 2.2e-3);
  }
}

TEST_F(Stress, OverflowStoresInfAndSpreadsOverTheFootprint) {
  const std::vector<StressRow> rows = run("hdr.overflow.rgba16f");
  for (const auto& m : rows.at(0).measured)
    EXPECT_EQ(m.value, std::numeric_limits<double>::infinity());
  for (const auto& m : row(rows, "hdr.overflow.rgba16f.spread").measured)
    EXPECT_EQ(m.value, 7 * 7) << m.way; // σ 1: R = ceil(3) = 3
}

TEST_F(Stress, NonFiniteTexelsSpreadOverTheFootprintOnly) {
  for (const StressRow& r : run("non-finite")) {
    EXPECT_TRUE(r.ways_agree) << r.id;
    for (const auto& m : r.measured) EXPECT_EQ(m.value, 49) << r.id << " " << m.way;
  }
}

TEST_F(Stress, Denormals) {
  // lavapipe flushes fp32 denormals, and the interpreter with it; the analytic model keeps them.
  const StressRow f32 = run("denormal.rgba32f").front();
  EXPECT_EQ(value_of(f32, "cpu"), 0);
  EXPECT_EQ(value_of(f32, "vulkan"), 0);
  EXPECT_EQ(value_of(f32, "analytic"), double(1e-39f));
  const StressRow f16 = run("denormal.rgba16f").front();
  for (const auto& m : f16.measured) EXPECT_EQ(m.value, 168 * std::ldexp(1.0, -24)) << m.way;
}

TEST_F(Stress, SigmaAtBothEnds) {
  EXPECT_EQ(run("sigma.tiny").front().expected, 0);
  // 2049 taps of exp(−k²/2·4096²), |k| ≤ 1024, 8 a pass; the scene 0.25 stores as 64/255 in
  // RGBA8, so a pass adds 64·Σ(its weights) ≈ 0.2525 of a step: every ONE/ONE store rounds
  // it away, and the glow of 0.25 is 0.
  double sum = 0;
  for (int k = -1024; k <= 1024; ++k) sum += std::exp(-double(k) * k / (2.0 * 4096 * 4096));
  EXPECT_LT(64 * 8 / sum, 0.5);
  const StressRow r8 = run("sigma.limit.rgba8").front();
  EXPECT_EQ(r8.expected, 0);
  for (const auto& m : r8.measured) EXPECT_EQ(m.value, 0) << m.way;
  // RGBA16F: 514 stores toward zero, each losing less than a step of 2^-12 below 0.25.
  const StressRow r16 = run("sigma.limit.rgba16f").front();
  for (const auto& m : r16.measured) {
    EXPECT_LE(m.value, 0.25);
    EXPECT_GE(m.value, 0.25 - 514 * std::ldexp(1.0, -12));
  }
}

TEST_F(Stress, DownsampleEdgesAndSaturation) {
  const std::vector<StressRow> d = run("downsample.sizes");
  EXPECT_EQ(row(d, "downsample.1x1.d4").expected, 0.75);
  EXPECT_NEAR(row(d, "downsample.1x7.d3.mid").expected, (3 + 4 + 5) / 18.0, 1e-12);
  EXPECT_EQ(row(d, "downsample.1x7.d3.edge").expected, 1.0);
  EXPECT_EQ(row(d, "downsample.7x5.d2.corner").expected, 1.0);
  // Named: a range-for over a temporary's member would read the vector after it is freed.
  const std::vector<StressRow> sat8 = run("intensity.1000.rgba8");
  for (const auto& m : sat8.front().measured) EXPECT_EQ(m.value, 1.0);
  // RGBA16F: 0.25 + 1000·0.25 = 250.25, a half float; the stores round toward zero, so a
  // glow a hair below 0.25 gives the half below, 250.125 (steps of 2^-3 there).
  const std::vector<StressRow> sat16 = run("intensity.1000.rgba16f");
  for (const auto& m : sat16.front().measured) {
    EXPECT_LE(m.value, 250.25);
    EXPECT_GE(m.value, 250.125);
  }
}

TEST_F(Stress, WeightsThatMissTheirTotal) {
  const std::vector<StressRow> w = run("weights");
  for (const auto& m : row(w, "weights.glsl-0.98").measured)
    EXPECT_NEAR(m.value, 0.98 * 0.98, 1e-5);
  // σ 2, nine taps, each rounded to k/255: the sum of those, squared.
  double g[9], sum = 0, q = 0;
  for (int k = -4; k <= 4; ++k) sum += g[k + 4] = std::exp(-k * k / 8.0);
  for (double x : g) q += std::round(x / sum * 255) / 255;
  for (const auto& m : row(w, "weights.dx7-8bit").measured) EXPECT_NEAR(m.value, q * q, 1e-5);
}

TEST_F(Stress, FeedbackSteadyStateDecayAndStall) {
  const double s = 2.0 / 255;
  // g = 0.5, RGBA32F: s/(1 − g) after 24 frames (0.5^24 of the way left), 1/e in 2 frames.
  const std::vector<StressRow> f = run("feedback.g0.5.rgba32f");
  for (const auto& m : row(f, "feedback.g0.5.rgba32f.steady").measured)
    EXPECT_NEAR(m.value, 2 * s, 1e-6);
  for (const auto& m : row(f, "feedback.g0.5.rgba32f.decay").measured) EXPECT_EQ(m.value, 2);
  // g = 0.9, RGBA8: the decay stops where round(0.9·k) = k: k ≤ 4 (k = 5 gives 4.5, a tie
  // that fp32's 0.9f·5 = 4.4999998 resolves downwards).
  const std::vector<StressRow> r8 = run("feedback.g0.9.rgba8");
  for (const auto& m : row(r8, "feedback.g0.9.rgba8.stall").measured) EXPECT_EQ(m.value, 4);
  // g = 1.01 grows: after 200 frames about s·(1.01^200 − 1)/0.01 = 5.7, far from steady.
  const std::vector<StressRow> up = run("feedback.g1.01.rgba32f");
  for (const auto& m : up.front().measured)
    EXPECT_NEAR(m.value, s * (std::pow(1.01, 200) - 1) / 0.01, 1e-3);
}

} // namespace

namespace {

bool mentions(const std::vector<std::string>& lines, const std::string& what) {
  for (const std::string& l : lines)
    if (l.find(what) != std::string::npos) return true;
  return false;
}

TEST(StressWarnings, GlowWarnsOfTheRgba8Regimes) {
  effects::EffectParams p; // the default scene: 4 blur passes an axis, intensity 1, rgba32f
  EXPECT_FALSE(mentions(effects::glow_warnings(p), "rgba8"));
  p.format = img::Format::RGBA8;
  EXPECT_FALSE(mentions(effects::glow_warnings(p), "rgba8")) << "4 passes, intensity 1";
  p.profile.terms = {{4096, 1}};
  p.profile.max_taps = 2049; // 2049 taps: 257 passes an axis
  EXPECT_TRUE(mentions(effects::glow_warnings(p), "rgba8 with 257 blur passes per axis"));
  p.profile = effects::default_blur_profile();
  p.intensity = 1000;
  EXPECT_TRUE(mentions(effects::glow_warnings(p), "intensity 1000 in rgba8"));
  p.format = img::Format::RGBA16F;
  EXPECT_FALSE(mentions(effects::glow_warnings(p), "saturates"));
}

} // namespace
