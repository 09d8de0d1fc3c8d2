// The default glow is one a person can see: on the built-in scene, at least 3 in 4 pixels of
// the halo's ring around the lights (8..24 px from a glowing pixel) change by more than 8/255
// between the scene and the final frame. 8 steps is about 3 % of full scale, a change seen
// plainly on the scene's near-black background (its wall is ~0.04). The old default (σ 8 +
// σ 1.5 at 1/2 resolution, intensity 1) fails the same bar (a third of the ring), which is
// why it changed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/scenes/default_scene.h"

namespace tierlift::effects {
namespace {

// The halo's ring: 8..24 px from the nearest glowing pixel (beyond the lights' own edge and
// their nearest blur, out to 1.5 σ of the default's Gaussian).
constexpr int kRingFrom = 8, kRingTo = 24;

// The share of the ring around the lights whose final frame differs from the scene by more
// than 8/255 in some channel.
double visible_share(const EffectParams& p) {
  const img::Image scene = make_default_scene(p.width, p.height);
  PlanResult plan_built = build_glow(p);
  if (!plan_built) {
    ADD_FAILURE() << plan_built.message();
    return 0;
  }
  EffectPlan& plan = *plan_built;
  CpuPassDevice cpu;
  EffectRun run = run_effect(plan, scene, cpu);
  EXPECT_TRUE(run.run.ok()) << run.run.message();
  const img::Image& fin = run.images.at(std::string(kFinalTexture));
  const int w = int(p.width), h = int(p.height);
  // Chebyshev distance to the nearest glowing pixel (alpha > 0), two passes.
  std::vector<int> dist(size_t(w) * h, 1 << 20);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (scene.at(uint32_t(x), uint32_t(y))[3] > 0) dist[size_t(y) * w + x] = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < w * h; ++i) {
      const int k = pass == 0 ? i : w * h - 1 - i, x = k % w, y = k / w, s = pass == 0 ? -1 : 1;
      int& d = dist[size_t(k)];
      for (const auto& [dx, dy] : {std::pair{s, 0}, {0, s}, {s, s}, {-s, s}}) {
        const int nx = x + dx, ny = y + dy;
        if (nx >= 0 && nx < w && ny >= 0 && ny < h) d = std::min(d, dist[size_t(ny) * w + nx] + 1);
      }
    }
  size_t ring = 0, seen = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int d = dist[size_t(y) * w + x];
      if (d < kRingFrom || d > kRingTo) continue;
      ++ring;
      const float *a = scene.at(uint32_t(x), uint32_t(y)), *b = fin.at(uint32_t(x), uint32_t(y));
      float most = 0;
      for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(b[c] - a[c]));
      seen += most > 8.0f / 255;
    }
  EXPECT_GT(ring, 10000u);
  return ring ? double(seen) / double(ring) : 0;
}

TEST(DefaultGlow, IsVisibleAroundTheLights) {
  const EffectParams p; // the defaults: 1280×720, dx9, σ 16 px, downsample 4, intensity 3
  const double share = visible_share(p);
  std::printf("[default glow] %.1f %% of the ring around the lights changes by > 8/255\n",
              100 * share);
  EXPECT_GE(share, 0.75);
}

TEST(DefaultGlow, TheOldDefaultWasNot) {
  EffectParams p;
  p.profile.terms = {{8.0, 0.7}, {1.5, 0.3}};
  p.downsample = 2;
  p.intensity = 1;
  const double share = visible_share(p);
  std::printf("[old default glow] %.1f %% of the ring changes by > 8/255\n", 100 * share);
  EXPECT_LT(share, 0.75);
}

} // namespace
} // namespace tierlift::effects
