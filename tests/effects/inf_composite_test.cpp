// A legal HDR input through the whole glow: one +inf texel in an RGBA32F scene. The three
// ways (interpreter, Vulkan on lavapipe, analytic model) must agree at the composite, and
// they must give what NUMERICS.md rule 36 says, computed here from the glow's closed form:
//   * the blur spreads +inf over exactly the kernel's (2R+1)² footprint (rule 8: the zero
//     weights of the padding taps multiply +inf to 0);
//   * the composite reads the glow with bilinear filtering, which the filter unit computes
//     as a + α·(b − a) per axis; at the glow's texel centres α = 0, so a pixel whose own glow
//     texel or whose right / lower neighbour holds +inf gets inf − inf or 0·inf: NaN;
//   * everywhere else the frame is the scene (0) plus a glow of 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "../vulkan/vk_test_util.h"
#include "three_ways.h"
#include "tierlift/effects/glow/glow.h"

namespace tierlift::effects {
namespace {

constexpr uint32_t kSize = 16; // a power of two: texel centres are exact in fp32
constexpr uint32_t kInfX = 8, kInfY = 8;
constexpr int kRadius = 3; // σ 1: 7 taps

class InfComposite : public vulkan::test::VulkanTest {};

// Where the glow holds +inf: the footprint of the kernel around the +inf source texel.
bool glow_is_inf(int64_t x, int64_t y) {
  // Clamp addressing: a read past the last texel reads the last one.
  x = std::min<int64_t>(x, kSize - 1);
  y = std::min<int64_t>(y, kSize - 1);
  return std::abs(x - int64_t(kInfX)) <= kRadius && std::abs(y - int64_t(kInfY)) <= kRadius;
}

// Rule 36 at a texel centre (α = β = 0): the lerp gives the lower texel when all four are
// finite, NaN when any of them is infinite.
bool expect_nan(uint32_t x, uint32_t y) {
  return glow_is_inf(x, y) || glow_is_inf(x + 1, y) || glow_is_inf(x, y + 1) ||
         glow_is_inf(x + 1, y + 1);
}

TEST_F(InfComposite, OneInfTexelAgreesThreeWaysAsTheFilterUnitComputes) {
  EffectParams p;
  p.width = p.height = kSize;
  p.downsample = 1;
  p.format = img::Format::RGBA32F;
  p.profile.terms = {{1.0, 1.0}};
  p.intensity = 1;
  const PlanResult plan = build_glow(p);
  ASSERT_TRUE(plan.ok()) << plan.message();
  ASSERT_EQ(plan->taps.size(), size_t(2 * kRadius + 1));

  img::Image scene(kSize, kSize, img::Format::RGBA32F);
  for (size_t i = 3; i < scene.rgba.size(); i += 4) scene.rgba[i] = 1; // opaque, black
  float* source = scene.at(kInfX, kInfY);
  source[0] = source[1] = source[2] = std::numeric_limits<float>::infinity();

  test_ways::ThreeDevices devices(*dev);
  const test_ways::NamedRuns runs = test_ways::run_three_ways(*plan, scene, devices);
  for (const auto& [way, run] : runs) {
    ASSERT_TRUE(run.run.ok()) << way << ": " << run.run.message();
    const img::Image& glow = run.images.at(std::string(kGlowTexture));
    const img::Image& final_frame = run.images.at(std::string(kFinalTexture));
    size_t nan_pixels = 0;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) {
        const float g = glow.at(x, y)[0], f = final_frame.at(x, y)[0];
        EXPECT_EQ(std::isinf(g) && g > 0, glow_is_inf(x, y)) << way << " glow " << x << "," << y;
        if (expect_nan(x, y)) {
          EXPECT_TRUE(std::isnan(f)) << way << " final " << x << "," << y << ": " << f;
          ++nan_pixels;
        } else {
          EXPECT_EQ(f, 0.0f) << way << " final " << x << "," << y;
        }
        EXPECT_EQ(final_frame.at(x, y)[3], 1.0f) << way << ": the scene's alpha is kept";
      }
    // (2R + 1)² footprint, one more column to its left and one more row above: 8².
    EXPECT_EQ(nan_pixels, size_t((2 * kRadius + 2) * (2 * kRadius + 2))) << way;
  }
  // And `tierlift glow`'s verdict: every pair within the targets.
  test_ways::compare_pairs(
      runs, [](const std::string& a, const std::string& b, const RunAgreement& agreement) {
        EXPECT_TRUE(agreement.all_pass) << a << " vs " << b;
      });
}

} // namespace
} // namespace tierlift::effects
