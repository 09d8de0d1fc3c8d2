// Comparison metrics on hand-made images and the verdict per target format.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/image/compare.h"

namespace img = tierlift::img;

namespace {
img::Image flat(uint32_t w, uint32_t h, float v) {
  img::Image im(w, h);
  for (float& x : im.rgba) x = v;
  return im;
}
} // namespace

TEST(Compare, MetricsByHand) {
  img::Image a = flat(2, 2, 0.5f), b = flat(2, 2, 0.5f);
  b.at(1, 0)[1] = 0.75f;   // one G difference of 0.25
  b.at(0, 1)[3] = 0.4375f; // one A difference of 0.0625
  auto c = img::compare(a, b);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->max_abs[0], 0.0);
  EXPECT_DOUBLE_EQ(c->max_abs[1], 0.25);
  EXPECT_DOUBLE_EQ(c->max_abs[3], 0.0625);
  EXPECT_DOUBLE_EQ(c->max_abs_all, 0.25);
  EXPECT_EQ(c->worst_x, 1u);
  EXPECT_EQ(c->worst_y, 0u);
  EXPECT_EQ(c->worst_channel, 1);
  EXPECT_DOUBLE_EQ(c->rmse[1], std::sqrt(0.0625 / 4));
  EXPECT_DOUBLE_EQ(c->rmse_all, std::sqrt((0.0625 + 0.00390625) / 16));
  EXPECT_EQ(c->identical_pixels, 2u);
  EXPECT_DOUBLE_EQ(c->identical_share, 0.5);
  EXPECT_FALSE(img::judge(*c, img::Format::RGBA32F).pass);
}

TEST(Compare, SizeMismatchIsAnError) {
  auto c = img::compare(flat(2, 2, 0), flat(2, 3, 0));
  EXPECT_FALSE(c);
  EXPECT_NE(c.message().find("2x2"), std::string::npos) << c.message();
}

TEST(Compare, NanAgreesWithNanButNotWithNumbers) {
  img::Image a = flat(1, 1, std::numeric_limits<float>::quiet_NaN());
  auto same = img::compare(a, a);
  ASSERT_TRUE(same);
  EXPECT_EQ(same->max_abs_all, 0.0);
  auto diff = img::compare(a, flat(1, 1, 0.0f));
  ASSERT_TRUE(diff);
  EXPECT_TRUE(std::isinf(diff->max_abs_all));
  EXPECT_TRUE(diff->non_finite_mismatch);
  EXPECT_FALSE(img::judge(*diff, img::Format::RGBA32F).pass);
}

TEST(Compare, Rgba32fTargetIsOneE5OfFullScale) {
  img::Image a = flat(4, 4, 0.5f), b = flat(4, 4, 0.5f);
  b.at(2, 2)[0] = 0.5f + 9e-6f;
  EXPECT_TRUE(img::judge(*img::compare(a, b), img::Format::RGBA32F).pass);
  b.at(2, 2)[0] = 0.5f + 2e-5f;
  EXPECT_FALSE(img::judge(*img::compare(a, b), img::Format::RGBA32F).pass);
  // HDR: full scale 1000 allows 1e-2.
  a.at(0, 0)[0] = b.at(0, 0)[0] = 1000.0f;
  b.at(2, 2)[0] = 0.5f + 5e-3f;
  EXPECT_TRUE(img::judge(*img::compare(a, b), img::Format::RGBA32F).pass);
}

TEST(Compare, Rgba8TargetIsOneLsbAndIdenticalShare) {
  // 2000 pixels; stored RGBA8 values.
  img::Image a = flat(40, 50, static_cast<float>(100 / 255.0));
  img::Image b = a;
  b.at(3, 3)[0] = static_cast<float>(101 / 255.0); // 1 LSB, 1 of 2000 pixels differ
  b.at(4, 3)[0] = static_cast<float>(99 / 255.0);  // 2 of 2000 = 99.9 % identical
  auto c = img::compare(a, b);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->identical_share, 0.999);
  EXPECT_TRUE(img::judge(*c, img::Format::RGBA8).pass)
      << img::judge(*c, img::Format::RGBA8).summary;
  b.at(5, 3)[0] = static_cast<float>(101 / 255.0); // 3 of 2000: 99.85 %
  EXPECT_FALSE(img::judge(*img::compare(a, b), img::Format::RGBA8).pass);
  img::Image d = a;
  d.at(0, 0)[2] = static_cast<float>(102 / 255.0); // 2 LSB
  EXPECT_FALSE(img::judge(*img::compare(a, d), img::Format::RGBA8).pass);
}
