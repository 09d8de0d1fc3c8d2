// img::diff_images, judge_diff and heat_map on hand-made images whose differences are
// worked out by hand below.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/image/diff.h"

namespace tierlift::img {
namespace {

// 4x1 images: pixel 0 equal, pixel 1 one 8-bit step apart in G, pixel 2 three steps apart in
// B, pixel 3 0.5 apart in A.
struct Pair {
  Image a{4, 1, Format::RGBA8}, b{4, 1, Format::RGBA8};
  Pair() {
    for (uint32_t x = 0; x < 4; ++x)
      for (int c = 0; c < 4; ++c) a.at(x, 0)[c] = b.at(x, 0)[c] = 100.0f / 255.0f;
    b.at(1, 0)[1] = 101.0f / 255.0f;
    b.at(2, 0)[2] = 103.0f / 255.0f;
    b.at(3, 0)[3] = 100.0f / 255.0f + 0.5f;
  }
};

TEST(ImageDiff, FiguresOfHandMadeImages) {
  Pair p;
  ir::Result<Diff> d = diff_images(p.a, p.b, {1, 10});
  ASSERT_TRUE(d) << d.message();
  // Max abs: pixel 3's 0.5 (in float: the sum rounded, so compare to the float values).
  const double half = double(100.0f / 255.0f + 0.5f) - double(100.0f / 255.0f);
  EXPECT_DOUBLE_EQ(d->comparison.max_abs_all, half);
  // RMSE over the 16 values: sqrt((d1² + d3² + half²) / 16), d1 ≈ 1/255, d3 ≈ 3/255.
  const double d1 = double(101.0f / 255.0f) - double(100.0f / 255.0f);
  const double d3 = double(103.0f / 255.0f) - double(100.0f / 255.0f);
  EXPECT_NEAR(d->comparison.rmse_all, std::sqrt((d1 * d1 + d3 * d3 + half * half) / 16.0), 1e-12);
  // Off by more than 1/255: pixels 2 and 3 (pixel 1 is exactly one step): 2 of 4.
  EXPECT_EQ(d->off_pixels, 2u);
  EXPECT_DOUBLE_EQ(d->off_share, 0.5);
  // Worst first: pixel 3 (A), pixel 2 (B), pixel 1 (G); the equal pixel is not listed.
  ASSERT_EQ(d->worst.size(), 3u);
  EXPECT_EQ(d->worst[0].x, 3u);
  EXPECT_EQ(d->worst[0].channel, 3);
  EXPECT_EQ(d->worst[1].x, 2u);
  EXPECT_EQ(d->worst[1].channel, 2);
  EXPECT_EQ(d->worst[2].x, 1u);
  EXPECT_EQ(d->worst[2].channel, 1);
  EXPECT_FLOAT_EQ(d->worst[1].a[2], 100.0f / 255.0f);
  EXPECT_FLOAT_EQ(d->worst[1].b[2], 103.0f / 255.0f);
}

TEST(ImageDiff, OffStepsAndWorstCount) {
  Pair p;
  // Off by more than 3 steps: pixel 3 alone; 2 steps: pixels 2 and 3.
  EXPECT_EQ(diff_images(p.a, p.b, {3, 1})->off_pixels, 1u);
  EXPECT_EQ(diff_images(p.a, p.b, {2, 1})->off_pixels, 2u);
  // 0 steps: every pixel that differs at all.
  EXPECT_EQ(diff_images(p.a, p.b, {0, 1})->off_pixels, 3u);
  ir::Result<Diff> one = diff_images(p.a, p.b, {1, 1});
  ASSERT_EQ(one->worst.size(), 1u);
  EXPECT_EQ(one->worst[0].x, 3u);
}

TEST(ImageDiff, EqualDifferencesListInRowMajorOrder) {
  Image a(2, 2), b(2, 2);
  b.at(1, 1)[0] = 0.25f;
  b.at(0, 1)[0] = 0.25f;
  b.at(1, 0)[1] = 0.25f;
  ir::Result<Diff> d = diff_images(a, b, {1, 2});
  ASSERT_EQ(d->worst.size(), 2u);
  EXPECT_EQ(d->worst[0].x, 1u);
  EXPECT_EQ(d->worst[0].y, 0u);
  EXPECT_EQ(d->worst[1].x, 0u);
  EXPECT_EQ(d->worst[1].y, 1u);
}

TEST(ImageDiff, SizesMustMatch) {
  ir::Result<Diff> d = diff_images(Image(2, 2), Image(2, 3));
  ASSERT_FALSE(d);
  EXPECT_NE(d.message().find("2x2 vs 2x3"), std::string::npos) << d.message();
}

TEST(ImageDiff, JudgeEachLimit) {
  Pair p;
  Diff d = *diff_images(p.a, p.b);
  EXPECT_TRUE(judge_diff(d, {}).pass); // no limit
  EXPECT_TRUE(judge_diff(d, {0.6, std::nullopt}).pass);
  EXPECT_FALSE(judge_diff(d, {0.4, std::nullopt}).pass);
  EXPECT_TRUE(judge_diff(d, {std::nullopt, 0.5}).pass); // 2 of 4 off
  Verdict v = judge_diff(d, {std::nullopt, 0.25});
  EXPECT_FALSE(v.pass);
  EXPECT_NE(v.summary.find("BEYOND"), std::string::npos) << v.summary;
  EXPECT_FALSE(judge_diff(d, {0.6, 0.25}).pass); // both must hold
}

TEST(ImageDiff, HeatMapColours) {
  // Differences 0, 0.25, 0.4, 1 (scale: the largest, 1) and one NaN against a number.
  Image a(5, 1), b(5, 1);
  b.at(1, 0)[0] = 0.25f; // t = 0.25: 3t = 0.75 → red 0.75
  b.at(2, 0)[1] = 0.4f;  // t = 0.4: 1.2 → red 1, green 0.2
  b.at(3, 0)[2] = 1.0f;  // t = 1: white
  b.at(4, 0)[3] = std::numeric_limits<float>::quiet_NaN();
  Image h = heat_map(a, b);
  ASSERT_EQ(h.format, Format::RGBA8);
  auto px = [&](uint32_t x, int c) { return std::lround(h.at(x, 0)[c] * 255.0f); };
  EXPECT_EQ(px(0, 0), 0);
  EXPECT_EQ(px(0, 3), 255); // opaque
  EXPECT_EQ(px(1, 0), 191); // 0.75 × 255 = 191.25
  EXPECT_EQ(px(1, 1), 0);
  EXPECT_EQ(px(2, 0), 255);
  EXPECT_EQ(px(2, 1), 51); // 0.2 × 255
  EXPECT_EQ(px(2, 2), 0);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(px(3, c), 255);
  EXPECT_EQ(px(4, 0), 255); // magenta
  EXPECT_EQ(px(4, 1), 0);
  EXPECT_EQ(px(4, 2), 255);
}

} // namespace
} // namespace tierlift::img
