// cpu::DrawTargets::stale: a target holding leftovers draws as if it held zeros, whether the
// draw zeroes it first or overwrites every pixel (the effect device's saved clear relies on it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "draw_helpers.h"

namespace tierlift::cpu::test {
namespace {

// `p` drawn into a zeroed target and into one full of leftovers marked stale: the same bits.
void expect_as_zeros(const Pass& p, uint32_t w = 9, uint32_t h = 5) {
  img::Image fresh(w, h);
  ASSERT_TRUE(draw(p, fresh, 1).ok());
  img::Image left(w, h);
  std::fill(left.rgba.begin(), left.rgba.end(), 7.0f);
  DrawTargets targets;
  targets.color[0] = &left;
  targets.stale = true;
  ASSERT_TRUE(draw(p, targets, 1).ok());
  EXPECT_EQ(0, std::memcmp(fresh.rgba.data(), left.rgba.data(), fresh.rgba.size() * sizeof(float)));
}

TEST(StaleTarget, FullScreenReplaceOverwritesEverything) {
  Pass p;
  p.constant_inputs.color[0] = {1, 0.5f, 0.25f, 1};
  expect_as_zeros(p);
}

TEST(StaleTarget, PartialCoverageIsZeroedFirst) {
  // One triangle: half the target keeps no leftover.
  expect_as_zeros(
      flat_pass({screen_vertex(0, 0, 9, 5), screen_vertex(9, 0, 9, 5), screen_vertex(0, 5, 9, 5)},
                {1, 1, 1, 1}, BlendMode::Replace));
  Pass s;
  s.constant_inputs.color[0] = {1, 0.5f, 0.25f, 1};
  s.scissor = pass::ScissorRect{2, 1, 5, 3};
  expect_as_zeros(s);
  Pass v;
  v.constant_inputs.color[0] = {1, 0.5f, 0.25f, 1};
  v.viewport.x = 4;
  v.viewport.width = 3;
  expect_as_zeros(v);
}

TEST(StaleTarget, BlendingReadsZeros) {
  Pass p;
  p.constant_inputs.color[0] = {0.25f, 0.5f, 0.75f, 0.5f};
  for (BlendMode m : {BlendMode::OneOne, BlendMode::SrcAlphaOne, BlendMode::SrcAlphaInvSrcAlpha}) {
    p.blend = m;
    expect_as_zeros(p);
  }
}

TEST(StaleTarget, NothingDrawnStillZeroes) {
  // A triangle entirely off the target: no pixel drawn, the target reads as zeros.
  expect_as_zeros(flat_pass(
      {screen_vertex(20, 20, 9, 5), screen_vertex(30, 20, 9, 5), screen_vertex(20, 30, 9, 5)},
      {1, 1, 1, 1}, BlendMode::Replace));
}

} // namespace
} // namespace tierlift::cpu::test
