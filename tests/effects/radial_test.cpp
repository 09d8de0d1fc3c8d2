// Radial-blur beams (effects/radial.h): the beams of a single bright pixel against the
// radial kernel's closed form, computed here from the article's rule alone (copy i reads
// u' = c + (u − c)(1 − 2·i·step), weight (1/8)(N − i)/N, a bilinear read of one lit texel is
// the product of the tent weights max(0, 1 − |u'·W − ½ − x₀|) per axis); the three ways
// agreeing on every pass; the star moving with the frame; and bad "radial" fields in scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../vulkan/vk_test_util.h"
#include "three_way_scenes.h"
#include "three_ways.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/radial.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {

// How a tier prints in test listings (GetParam): its name, not its bytes. In the enum's own
// namespace, where argument-dependent lookup finds it; static, one copy per test file.
[[maybe_unused]] static void PrintTo(Tier t, std::ostream* os) {
  *os << tier_name(t);
}

namespace {

using test_ways::ThreeDevices;

constexpr uint32_t kW = 41, kH = 33;
constexpr uint32_t kX0 = 29, kY0 = 11; // the lit texel
constexpr float kLit[4] = {1.0f, 0.5f, 0.25f, 1.0f};

img::Image single_pixel() {
  img::Image im(kW, kH);
  for (int c = 0; c < 4; ++c) im.rgba[(size_t(kY0) * kW + kX0) * 4 + c] = kLit[c];
  return im;
}

// The beams' red channel at pixel (x, y) by the closed form (lit value 1 in red).
double closed_form(double cx, double cy, unsigned n, double step, uint32_t x, uint32_t y) {
  double sum = 0;
  for (unsigned i = 1; i <= n; ++i) {
    const double s = 1 - 2.0 * i * step;
    const double u = cx + ((x + 0.5) / kW - cx) * s, v = cy + ((y + 0.5) / kH - cy) * s;
    const double wx = std::max(0.0, 1 - std::abs(u * kW - 0.5 - kX0));
    const double wy = std::max(0.0, 1 - std::abs(v * kH - 0.5 - kY0));
    sum += (1.0 / 8.0) * double(n - i) / n * wx * wy;
  }
  return sum;
}

RadialParams still_params() {
  RadialParams r;
  r.centre = {0.3, 0.6};
  r.steps = 20; // three ps.2.0 passes (8 + 8 + 4), five ps.1.x passes
  r.step = 0.0125;
  r.strength = 0.75;
  r.amplitude = 0; // the star is the scene image unmoved
  return r;
}

EffectParams glow_params(Tier tier, img::Format format = img::Format::RGBA32F) {
  EffectParams g;
  g.tier = tier;
  g.width = kW;
  g.height = kH;
  g.format = format;
  g.subtexel_bits = 0; // lavapipe weights float textures exactly
  return g;
}

// The animated tests' run: kFrames frames from radial.frame = kFirst, the star moving with
// amplitude kA at rate kRate (half a time unit a frame: it moves by texels between frames).
constexpr unsigned kFrames = 3, kFirst = 5;
constexpr double kA = 3, kRate = 2;

RadialParams moving_params() {
  RadialParams r = still_params();
  r.amplitude = kA;
  r.rate = kRate;
  r.frame = kFirst;
  r.frames = kFrames;
  return r;
}

// The star texture of each frame of `graph` run on `device` over `scene` (none after a failed
// run, which fails the test).
std::vector<img::Image> star_frames(const EffectGraph& graph, const img::Image& scene,
                                    PassDevice& device) {
  ImageMap images{{std::string(kSceneTexture), scene}};
  std::vector<img::Image> frames;
  ir::Result<FrameTimes> run =
      run_frames(graph, device, images, kFrames, [&](unsigned, PassDevice& d) -> ir::Status {
        ir::Result<img::Image> star = d.read_texture(std::string(kStarTexture));
        if (!star) return std::move(star).failure();
        frames.push_back(std::move(*star));
        return ir::ok_status();
      });
  EXPECT_TRUE(run.ok()) << device.name() << ": " << run.message();
  return frames;
}

class RadialWays : public vulkan::test::VulkanTest, public ::testing::WithParamInterface<Tier> {};

TEST_P(RadialWays, SingleBrightPixelMatchesTheClosedForm) {
  const RadialParams r = still_params();
  PlanResult plan_built = build_radial(glow_params(GetParam()), r);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  ThreeDevices ways(*dev);
  const img::Image scene = single_pixel();
  double worst = 0, peak = 0;
  for (PassDevice* d : ways.all()) {
    EffectRun run = run_effect(plan, scene, *d, false);
    ASSERT_TRUE(run.run.ok()) << run.run.message();
    const img::Image& beams = run.images.at(std::string(kGlowTexture));
    const img::Image& fin = run.images.at(std::string(kFinalTexture));
    for (uint32_t y = 0; y < kH; ++y)
      for (uint32_t x = 0; x < kW; ++x) {
        const double k = closed_form(r.centre[0], r.centre[1], r.steps, r.step, x, y);
        peak = std::max(peak, k);
        const size_t i = (size_t(y) * kW + x) * 4;
        for (int c = 0; c < 4; ++c) {
          worst = std::max(worst, std::abs(beams.rgba[i + c] - k * kLit[c]));
          const double star = (x == kX0 && y == kY0) ? kLit[c] : 0.0;
          const double want = c == 3 ? star : star + r.strength * k * kLit[c];
          // docs/design.md: RGBA32F agrees to 1e-5 of full scale.
          ASSERT_NEAR(fin.rgba[i + c], want, 1e-5) << x << "," << y << " c" << c;
        }
      }
  }
  EXPECT_LE(worst, 1e-5);
  EXPECT_GT(peak, 0.05); // the beam is there: the nearest copies read the lit texel strongly
  EXPECT_TRUE(dev->messages().empty()) << dev->messages().front();
  std::printf("[radial] %s single pixel: max |device - closed form| %.3g (peak %.4f)\n",
              std::string(tier_name(GetParam())).c_str(), worst, peak);
}

img::Image random_scene(uint32_t seed) {
  return test_scenes::random_bytes(kW, kH, seed);
}

TEST_P(RadialWays, ThreeWaysAgreeOnEveryPassWithTheStarMoving) {
  for (img::Format f : {img::Format::RGBA32F, img::Format::RGBA8}) {
    RadialParams r = still_params();
    r.amplitude = 3;
    r.frame = 17;
    PlanResult plan_built = build_radial(glow_params(GetParam(), f), r);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    ThreeDevices devices(*dev);
    const test_ways::NamedRuns ways = test_ways::run_three_ways(plan, random_scene(7), devices);
    for (auto& [name, w] : ways) ASSERT_TRUE(w.run.ok()) << name << ": " << w.run.message();
    test_ways::compare_pairs(
        ways, [&](const std::string& a, const std::string& b, const RunAgreement& agree) {
          for (const PassAgreement& row : agree.passes) {
            EXPECT_TRUE(row.verdict.pass)
                << a << " vs " << b << ", " << row.pass << ": " << row.verdict.summary;
            std::printf("[radial] %s %s %s-%s %-10s max abs %.3g\n",
                        std::string(tier_name(GetParam())).c_str(),
                        std::string(img::format_name(f)).c_str(), a.c_str(), b.c_str(),
                        row.pass.c_str(), row.comparison.max_abs_all);
          }
        });
  }
  EXPECT_TRUE(dev->messages().empty()) << dev->messages().front();
}

// --frames animates the star: frame f of a run from radial.frame = F, on each device, is the
// still plan built for frame F + f (whose star the tests above check against the closed
// form), the frames differ from each other, and the devices agree frame by frame.
TEST_P(RadialWays, FramesAnimateTheStarAsTheStillFramesDo) {
  const RadialParams r = moving_params();
  const EffectParams g = glow_params(GetParam());
  PlanResult moving_built = build_radial(g, r);
  ASSERT_TRUE(moving_built) << moving_built.message();
  EffectPlan& moving = *moving_built;
  ASSERT_EQ(moving.graph.passes.front().vs_constants_per_frame.size(), kFrames);
  const img::Image scene = random_scene(3);
  ThreeDevices ways(*dev);
  std::vector<std::vector<img::Image>> stars; // [device][frame]
  for (PassDevice* d : ways.all()) {
    std::vector<img::Image> frames = star_frames(moving.graph, scene, *d);
    ASSERT_EQ(frames.size(), kFrames) << d->name();
    // Each frame equals the still plan of that frame, on the same device.
    for (unsigned f = 0; f < kFrames; ++f) {
      RadialParams still = r;
      still.frame = kFirst + f;
      still.frames = 1;
      PlanResult plan_built = build_radial(g, still);
      ASSERT_TRUE(plan_built) << plan_built.message();
      EffectPlan& plan = *plan_built;
      EffectRun one = run_effect(plan, scene, *d, false);
      ASSERT_TRUE(one.run.ok()) << one.run.message();
      EXPECT_EQ(frames[f].rgba, one.images.at(std::string(kStarTexture)).rgba)
          << d->name() << " frame " << f;
    }
    EXPECT_NE(frames[0].rgba, frames[1].rgba) << d->name();
    EXPECT_NE(frames[1].rgba, frames[2].rgba) << d->name();
    stars.push_back(std::move(frames));
  }
  for (unsigned f = 0; f < kFrames; ++f)
    for (size_t b = 1; b < stars.size(); ++b) {
      auto c = img::compare(stars[0][f], stars[b][f]);
      ASSERT_TRUE(c) << c.message();
      EXPECT_TRUE(img::judge(*c, img::Format::RGBA32F).pass) << "frame " << f << " way " << b;
    }
  EXPECT_TRUE(dev->messages().empty()) << dev->messages().front();
}

// The animated star against its closed form, re-derived here in double: set k reads the
// scene at u + (A·(sin(fx_k·t + φ_k) − sin φ_k) + ½)/W (and cos with fy_k for v), with t =
// (radial.frame + f)/rate for frame f of the run (the functions the star's vertex constants
// c0..c3 carry). On a scene whose red is x/W and green y/H (texel centres), a bilinear read
// at any point between texel centres returns the linear function exactly, so the star at
// pixel (x, y) is ((x + mean_k dx_k)/W, (y + mean_k dy_k)/H) away from the wrapped edges.
TEST_P(RadialWays, AnimatedStarMatchesTheClosedFormEachFrame) {
  constexpr double kFx[4] = {0.70, -0.55, 0.35, -0.90}, kFy[4] = {0.45, 0.80, -0.65, -0.30};
  constexpr double kPh[4] = {0.0, 1.3, 2.6, 4.1};
  PlanResult plan_built = build_radial(glow_params(GetParam()), moving_params());
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  img::Image ramp(kW, kH);
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      ramp.rgba[(size_t(y) * kW + x) * 4 + 0] = float(x) / kW;
      ramp.rgba[(size_t(y) * kW + x) * 4 + 1] = float(y) / kH;
      ramp.rgba[(size_t(y) * kW + x) * 4 + 3] = 1;
    }
  double mean[kFrames][2] = {};
  for (unsigned f = 0; f < kFrames; ++f) {
    const double t = (kFirst + f) / kRate;
    for (int k = 0; k < 4; ++k) {
      mean[f][0] += kA * (std::sin(kFx[k] * t + kPh[k]) - std::sin(kPh[k])) / 4;
      mean[f][1] += kA * (std::cos(kFy[k] * t + kPh[k]) - std::cos(kPh[k])) / 4;
    }
  }
  // The frames' closed forms differ by far more than the tolerance below.
  for (unsigned f = 1; f < kFrames; ++f)
    EXPECT_GT(std::abs(mean[f][0] - mean[f - 1][0]) + std::abs(mean[f][1] - mean[f - 1][1]), 0.05);
  // Float coordinates and weights: a few ulps of values below 1 (no subtexel rounding).
  constexpr double kTol = 1e-5;
  const uint32_t margin = uint32_t(2 * kA) + 2; // the reads stay clear of the wrap seam
  ThreeDevices ways(*dev);
  for (PassDevice* d : ways.all()) {
    const std::vector<img::Image> frames = star_frames(plan.graph, ramp, *d);
    ASSERT_EQ(frames.size(), kFrames) << d->name();
    for (unsigned f = 0; f < kFrames; ++f) {
      double worst = 0;
      for (uint32_t y = margin; y + margin < kH; ++y)
        for (uint32_t x = margin; x + margin < kW; ++x) {
          const float* p = &frames[f].rgba[(size_t(y) * kW + x) * 4];
          worst = std::max(worst, std::abs(p[0] - (x + mean[f][0]) / kW));
          worst = std::max(worst, std::abs(p[1] - (y + mean[f][1]) / kH));
        }
      EXPECT_LT(worst, kTol) << d->name() << " frame " << f;
      std::printf("[radial] %s star frame %u: max |device - closed form| %.3g\n",
                  std::string(d->name()).c_str(), f + 1, worst);
    }
  }
  EXPECT_TRUE(dev->messages().empty()) << dev->messages().front();
}

INSTANTIATE_TEST_SUITE_P(Radial, RadialWays, ::testing::Values(Tier::Dx9, Tier::Dx8),
                         [](const ::testing::TestParamInfo<Tier>& i) {
                           return std::string(tier_name(i.param));
                         });

TEST(Radial, CopiesFollowTheArticle) {
  RadialParams r;
  r.steps = 4;
  const std::vector<RadialCopy> c = radial_copies(r, 100, 50);
  ASSERT_EQ(c.size(), 4u);
  // Copy 1 (centre ½): the quad's texture range is [0.0075, 0.9925]; texel 0's centre maps
  // to 0.0075 + 0.985·0.5/100.
  EXPECT_NEAR(c[0].scale, 0.985, 1e-15);
  EXPECT_NEAR(c[0].offset[0], 0.0075 + 0.985 * 0.005, 1e-15);
  EXPECT_NEAR(c[0].offset[1], 0.0075 + 0.985 * 0.01, 1e-15);
  // Weights (1/8)(N − i)/N: 3/32, 2/32, 1/32, 0.
  EXPECT_DOUBLE_EQ(c[0].weight, 3.0 / 32);
  EXPECT_DOUBLE_EQ(c[2].weight, 1.0 / 32);
  EXPECT_DOUBLE_EQ(c[3].weight, 0.0);
}

TEST(Radial, StarMovesWithTheFrameAndStillAtAmplitudeZero) {
  RadialParams r;
  const auto a = star_offsets(r, 0, 64, 64), b = star_offsets(r, 45, 64, 64);
  for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(a[k][0], 0.5 / 64); // time 0: no offset
  for (int k = 0; k < 4; ++k)
    for (int j = k + 1; j < 4; ++j) EXPECT_NE(b[k], b[j]); // four different motions
  r.amplitude = 0;
  for (const auto& o : star_offsets(r, 45, 64, 64)) EXPECT_DOUBLE_EQ(o[1], 0.5 / 64);
}

TEST(Radial, PlanRefusesBadParameters) {
  RadialParams r;
  r.steps = 80; // 2·80·0.0075 = 1.2: zooms past the centre
  EXPECT_NE(build_radial(glow_params(Tier::Dx9), r).message().find("radial step"),
            std::string::npos);
  r = RadialParams{};
  r.strength = 2;
  EXPECT_NE(build_radial(glow_params(Tier::Dx8), r).message().find("strength"), std::string::npos);
  EXPECT_TRUE(build_radial(glow_params(Tier::Dx9), r));
}

// Scene errors sit at the value at fault (line:col) and name it by its JSON pointer.
std::string scene_error(const std::string& radial, const std::string& effect = "radial-beams") {
  const std::string text =
      "{\n  \"effect\": \"" + effect + "\",\n  \"radial\": " + radial + "\n}\n";
  ir::Result<Scene> load = parse_scene(text, "s.json", "");
  return load ? std::string() : load.message();
}

TEST(RadialScene, ReadsEveryField) {
  ir::Result<Scene> load = parse_scene(R"({"effect": "radial-beams", "size": [64, 32],
    "radial": {"centre": [0.25, 0.75], "steps": 12, "step": 0.01, "strength": 0.5,
               "tier": "dx8", "amplitude": 2, "rate": 24, "frame": 9}})",
                                       "s.json", "");
  ASSERT_TRUE(load) << load.message();
  const Scene& s = *load;
  EXPECT_EQ(s.effect, EffectKind::RadialBeams);
  EXPECT_EQ(s.params.tier, Tier::Dx8);
  EXPECT_EQ(s.radial.centre[1], 0.75);
  EXPECT_EQ(s.radial.steps, 12u);
  EXPECT_EQ(s.radial.step, 0.01);
  EXPECT_EQ(s.radial.frame, 9u);
  EXPECT_EQ(s.radial.rate, 24);
  EXPECT_TRUE(build_radial(s.params, s.radial));
}

TEST(RadialScene, BadFieldsArePositioned) {
  EXPECT_NE(scene_error(R"({"centre": [0.5, 1.5]})").find("s.json:3:30: error: /radial/centre/1"),
            std::string::npos)
      << scene_error(R"({"centre": [0.5, 1.5]})");
  EXPECT_NE(scene_error(R"({"steps": 40, "step": 0.02})").find("3:35: error: /radial/step"),
            std::string::npos)
      << scene_error(R"({"steps": 40, "step": 0.02})");
  EXPECT_NE(scene_error(R"({"steps": 0})").find("/radial/steps: 0 is outside"), std::string::npos);
  EXPECT_NE(scene_error(R"({"tier": "dx8", "strength": 1.5})").find("/radial/strength"),
            std::string::npos);
  EXPECT_NE(scene_error(R"({"rate": 0})").find("/radial/rate"), std::string::npos);
  EXPECT_NE(scene_error(R"({"zoom": 1})").find("/radial/zoom"), std::string::npos);
  EXPECT_NE(scene_error(R"({"tier": "dx7"})").find("/radial/tier"), std::string::npos);
  EXPECT_NE(scene_error("{}", "beams").find("/effect: \"beams\" is not an effect"),
            std::string::npos);
  EXPECT_NE(scene_error("{}", "glow").find("/radial"), std::string::npos);
  // The caret line is there.
  EXPECT_NE(scene_error(R"({"steps": 0})").find('^'), std::string::npos);
}

} // namespace
} // namespace tierlift::effects
