// cpu::draw's workers come from one pool of threads kept between draws (worker_pool.h). The
// image and the counts must not depend on how many workers a draw asks for, nor on other
// draws running at the same time from other threads (those take threads of their own while
// one draw holds the pool).
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <thread>

#include "random_passes.h"
#include "tierlift/cpu/draw.h"

namespace tierlift::cpu {
namespace {

// Random perspective triangles over a 97×61 target with a textured, killing pixel shader and
// SRCALPHA blending: every worker's bands differ, and a mix-up of bands, of per-worker state
// or of counters shows in the image or the stats.
Pass random_pass(uint32_t seed) {
  std::mt19937 rng(seed);
  Pass pass = test::random_perspective_pass(rng, 30, 97, 61);
  pass.blend = BlendMode::SrcAlphaInvSrcAlpha;
  return pass;
}

struct Drawn {
  img::Image image{97, 61, img::Format::RGBA8};
  DrawStats stats;
};

Drawn draw_with(const Pass& pass, unsigned threads) {
  Drawn d;
  ir::Result<DrawStats> s = draw(pass, d.image, threads);
  EXPECT_TRUE(s.ok()) << s.message();
  if (s.ok()) d.stats = *s;
  return d;
}

void expect_same(const Drawn& a, const Drawn& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.stats.pixels_shaded, b.stats.pixels_shaded);
  EXPECT_EQ(a.stats.pixels_killed, b.stats.pixels_killed);
  EXPECT_EQ(a.stats.pixels_block, b.stats.pixels_block);
  ASSERT_EQ(a.image.rgba.size(), b.image.rgba.size());
  EXPECT_EQ(std::memcmp(a.image.rgba.data(), b.image.rgba.data(), a.image.rgba.size() * 4), 0);
}

TEST(DrawThreads, SameImageAndCountsForAnyWorkerCount) {
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    const Pass pass = random_pass(seed);
    const Drawn one = draw_with(pass, 1);
    EXPECT_GT(one.stats.pixels_shaded, 1000u);
    EXPECT_GT(one.stats.pixels_killed, 0u);
    // More workers than bands of rows (16 here) and than cores; then fewer again, so the
    // pool's threads past the count sit one draw out.
    for (unsigned threads : {2u, 3u, 8u, 40u, 2u, 5u})
      expect_same(one, draw_with(pass, threads), "threads " + std::to_string(threads));
  }
}

TEST(DrawThreads, DrawsFromSeveralThreadsAtOnce) {
  constexpr uint32_t kPasses = 6;
  std::vector<Pass> passes;
  std::vector<Drawn> want;
  for (uint32_t seed = 0; seed < kPasses; ++seed) {
    passes.push_back(random_pass(100 + seed));
    want.push_back(draw_with(passes.back(), 1));
  }
  std::vector<std::vector<Drawn>> got(4);
  std::vector<std::thread> callers;
  for (size_t c = 0; c < got.size(); ++c)
    callers.emplace_back([&, c] {
      for (int round = 0; round < 5; ++round)
        for (uint32_t p = 0; p < kPasses; ++p) got[c].push_back(draw_with(passes[p], 3));
    });
  for (auto& t : callers) t.join();
  for (size_t c = 0; c < got.size(); ++c) {
    ASSERT_EQ(got[c].size(), size_t{5} * kPasses);
    for (size_t i = 0; i < got[c].size(); ++i)
      expect_same(want[i % kPasses], got[c][i],
                  "caller " + std::to_string(c) + " draw " + std::to_string(i));
  }
}

} // namespace
} // namespace tierlift::cpu
