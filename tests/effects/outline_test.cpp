// The stencil outline (effects/outline.h) on the CPU device and the analytic device: the glow
// is zero inside the object and non-zero exactly in a ring as wide as the blur's radius. The
// expected coverage is computed here from the polygon's definition (corners on a circle), and
// the ring from the separable blur's support: a pixel receives glow from a covered pixel at
// most R texels away in x and in y (Chebyshev distance ≤ R), R = ceil(3σ) taps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/outline.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/scenes/scene.h"

#include "../vulkan/vk_test_util.h"

namespace tierlift::effects {
namespace {

constexpr uint32_t kW = 64, kH = 48;
constexpr double kSigma = 1.5;
constexpr int kRadius = 5; // ceil(3 · 1.5): the profile's taps reach ±5 texels

EffectParams params() {
  EffectParams p;
  p.width = kW;
  p.height = kH;
  p.downsample = 1;
  p.profile.terms = {{kSigma, 1.0}};
  p.intensity = 1;
  return p;
}

OutlineParams object() {
  OutlineParams o;
  o.center_x = 31.3;
  o.center_y = 23.6;
  o.radius = 12;
  o.sides = 5;
  o.rotation = 10;
  o.color = {0.25f, 0.5f, 0.75f, 1};
  o.glow_color = {1, 1, 1, 1};
  return o;
}

// 1 inside, 0 outside, -1 within 0.01 pixel of an edge (vertices are snapped to 1/256 pixel,
// so the test does not claim those).
std::vector<int> expected_coverage(const OutlineParams& o) {
  std::vector<std::array<double, 2>> c;
  for (uint32_t k = 0; k < o.sides; ++k) {
    const double a = (o.rotation + 360.0 * k / o.sides) * std::numbers::pi / 180.0;
    c.push_back({o.center_x + o.radius * std::cos(a), o.center_y + o.radius * std::sin(a)});
  }
  std::vector<int> out(size_t{kW} * kH, 0);
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      double nearest = 1e9;
      bool inside = true;
      for (size_t k = 0; k < c.size(); ++k) {
        const auto& a = c[k];
        const auto& b = c[(k + 1) % c.size()];
        const double ex = b[0] - a[0], ey = b[1] - a[1];
        // Corners run clockwise on screen (y down): inside is where the cross product is > 0.
        const double d = (ex * (y - a[1]) - ey * (x - a[0])) / std::hypot(ex, ey);
        nearest = std::min(nearest, std::abs(d));
        inside = inside && d > 0;
      }
      out[y * kW + x] = nearest < 0.01 ? -1 : (inside ? 1 : 0);
    }
  return out;
}

struct OutlineResult {
  img::Image final, stencil;
};

OutlineResult run_on(PassDevice& device) {
  PlanResult plan_built = build_outline(params(), object());
  if (!plan_built) {
    ADD_FAILURE() << plan_built.message();
    return {};
  }
  EffectRun r = run_effect(*plan_built, img::Image(kW, kH), device);
  EXPECT_TRUE(r.run.ok()) << r.run.message();
  return {r.images[std::string(kFinalTexture)], r.images[std::string(kStencilTexture)]};
}

void expect_ring(const OutlineResult& r) {
  ASSERT_EQ(r.final.width, kW);
  const std::vector<int> cover = expected_coverage(object());
  const OutlineParams o = object();
  size_t inside = 0, ring = 0, at_radius = 0, beyond = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      const int c = cover[y * kW + x];
      if (c < 0) continue;
      const float* px = r.final.at(x, y);
      if (c == 1) {
        // Inside: the object's colour and nothing else (the glow is masked by the stencil);
        // the base pass keeps the scene's alpha (0 here), as the glow's composite does.
        for (int k = 0; k < 3; ++k) EXPECT_EQ(px[k], o.color[size_t(k)]) << x << "," << y;
        EXPECT_EQ(px[3], 0.0f);
        EXPECT_EQ(r.stencil.at(x, y)[0], 1.0f);
        ++inside;
        continue;
      }
      EXPECT_EQ(r.stencil.at(x, y)[0], 0.0f);
      int d = 1 << 20; // Chebyshev distance to the nearest covered pixel
      for (uint32_t v = 0; v < kH; ++v)
        for (uint32_t u = 0; u < kW; ++u)
          if (cover[v * kW + u] == 1)
            d = std::min(d, std::max(std::abs(int(u) - int(x)), std::abs(int(v) - int(y))));
      if (d <= kRadius) {
        EXPECT_GT(px[0], 0.0f) << x << "," << y << " d=" << d;
        ++ring;
        if (d == kRadius) ++at_radius;
      } else {
        EXPECT_EQ(px[0], 0.0f) << x << "," << y << " d=" << d;
        ++beyond;
      }
    }
  EXPECT_GT(inside, 300u); // a pentagon of radius 12: area ≈ 342 pixels
  EXPECT_GT(ring, 200u);
  EXPECT_GT(at_radius, 20u); // the ring reaches the radius all round
  EXPECT_GT(beyond, 1000u);
}

TEST(Outline, GlowIsZeroInsideAndARingAsWideAsTheBlurRadius) {
  CpuPassDevice cpu(1);
  expect_ring(run_on(cpu));
}

// The Vulkan device draws the object into two render targets and its stencil buffer, and
// masks the glow with the stencil test: the same ring, and the CPU device's images within
// design's RGBA32F target (the stencil buffers equal).
class OutlineVulkan : public vulkan::test::VulkanTest {};

TEST_F(OutlineVulkan, SameRingAndAgreesWithTheCpuDevice) {
  auto vk = make_vulkan_pass_device(*dev);
  const OutlineResult v = run_on(*vk);
  expect_ring(v);
  CpuPassDevice cpu(1);
  const OutlineResult c = run_on(cpu);
  EXPECT_EQ(v.stencil.rgba, c.stencil.rgba);
  ASSERT_EQ(v.final.rgba.size(), c.final.rgba.size());
  double worst = 0;
  for (size_t i = 0; i < v.final.rgba.size(); ++i)
    worst = std::max(worst, std::abs(double(v.final.rgba[i]) - c.final.rgba[i]));
  EXPECT_LE(worst, 1e-5);
}

TEST(Outline, AnalyticModelAgreesWithTheCpuDevice) {
  CpuPassDevice cpu(1);
  const OutlineResult c = run_on(cpu);
  std::unique_ptr<PassDevice> analytic = make_analytic_pass_device();
  const OutlineResult a = run_on(*analytic);
  ASSERT_EQ(a.final.rgba.size(), c.final.rgba.size());
  EXPECT_EQ(a.stencil.rgba, c.stencil.rgba); // the coverage is exact on both
  double worst = 0;
  for (size_t i = 0; i < a.final.rgba.size(); ++i)
    worst = std::max(worst, std::abs(double(a.final.rgba[i]) - c.final.rgba[i]));
  // RGBA32F: design's float target (the blur's fp32 sums against double).
  EXPECT_LE(worst, 1e-5);
}

TEST(Outline, StencilStateOutOfRangeIsRefusedByTheGraph) {
  PlanResult plan_built = build_outline(params(), object());
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  plan.graph.passes[0].draw.depth_stencil.stencil_ref = 256;
  EXPECT_NE(check_graph(plan.graph).message().find("0..255"), std::string::npos)
      << check_graph(plan.graph).message();
  OutlineParams o = object();
  o.stencil_ref = 0;
  EXPECT_NE(build_outline(params(), o).message().find("stencil_ref 0"), std::string::npos);
  EffectParams dx8 = params();
  dx8.tier = Tier::Dx8;
  EXPECT_NE(build_outline(dx8, object()).message().find("tier dx8"), std::string::npos);
}

TEST(Outline, SceneErrorsArePositioned) {
  const std::string text = "{\n  \"effect\": \"stencil-outline\",\n  \"size\": [64, 48],\n"
                           "  \"outline\": { \"stencil_ref\": 300 }\n}\n";
  ir::Result<Scene> s = parse_scene(text, "o.json", "");
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("o.json:4:31: error: /outline/stencil_ref"), std::string::npos)
      << s.message();
  ir::Result<Scene> wrong = parse_scene("{\"outline\": {}}", "w.json", "");
  ASSERT_FALSE(wrong);
  EXPECT_NE(wrong.message().find("w.json:1:2: error: /outline"), std::string::npos)
      << wrong.message();
  ir::Result<Scene> effect = parse_scene("{\"effect\": \"beams\"}", "e.json", "");
  ASSERT_FALSE(effect);
  EXPECT_NE(effect.message().find("e.json:1:12: error: /effect"), std::string::npos)
      << effect.message();
}

} // namespace
} // namespace tierlift::effects
