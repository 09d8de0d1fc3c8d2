// Built-in textures: texel values by hand, spec parsing and its errors.
#include <gtest/gtest.h>

#include "tierlift/image/builtin.h"

namespace img = tierlift::img;

TEST(Builtin, ImpulseIsOneWhiteTexelAtTheCentre) {
  auto r = img::make_builtin("builtin:impulse:5x4");
  ASSERT_TRUE(r) << r.message();
  const img::Image& im = *r;
  ASSERT_EQ(im.width, 5u);
  ASSERT_EQ(im.height, 4u);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 5; ++x) {
      float expect = (x == 2 && y == 2) ? 1.0f : 0.0f;
      EXPECT_EQ(im.at(x, y)[0], expect) << x << "," << y;
      EXPECT_EQ(im.at(x, y)[2], expect);
      EXPECT_EQ(im.at(x, y)[3], 1.0f);
    }
}

TEST(Builtin, RampHoldsTheTexelCentreCoordinate) {
  auto r = img::make_builtin("builtin:ramp:4x2");
  ASSERT_TRUE(r) << r.message();
  const float expect[4] = {0.125f, 0.375f, 0.625f, 0.875f};
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      EXPECT_EQ(r->at(x, y)[0], expect[x]);
      EXPECT_EQ(r->at(x, y)[1], expect[x]);
      EXPECT_EQ(r->at(x, y)[3], 1.0f);
    }
}

TEST(Builtin, CheckerHasEightTexelSquares) {
  auto r = img::make_builtin("builtin:checker:20x17");
  ASSERT_TRUE(r) << r.message();
  EXPECT_EQ(r->at(0, 0)[0], 1.0f);
  EXPECT_EQ(r->at(7, 7)[0], 1.0f);
  EXPECT_EQ(r->at(8, 0)[0], 0.0f);
  EXPECT_EQ(r->at(0, 8)[1], 0.0f);
  EXPECT_EQ(r->at(8, 8)[2], 1.0f);
  EXPECT_EQ(r->at(19, 16)[0], 1.0f); // square (2, 2)
  EXPECT_EQ(r->at(19, 16)[3], 1.0f);
}

TEST(Builtin, NoiseIsSplitmix64AndSeeded) {
  // splitmix64 from state 0: first output 0xE220A8397B1DCDAF (published reference value).
  uint64_t state = 0;
  EXPECT_EQ(img::splitmix64(state), 0xE220A8397B1DCDAFull);
  EXPECT_EQ(img::unit_float24(0xFFFFFF0000000000ull), 1.0f - 0x1p-24f);
  EXPECT_EQ(img::unit_float24(0x0000010000000000ull), 0x1p-24f);
  auto a = img::make_builtin("builtin:noise:8x8:7");
  auto b = img::make_builtin("builtin:noise:8x8:7");
  auto c = img::make_builtin("builtin:noise:8x8:8");
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(a->rgba, b->rgba);
  EXPECT_NE(a->rgba, c->rgba);
  // Texel (0,0).r is the first draw of seed 7, top 24 bits scaled by 2^-24.
  uint64_t s = 7;
  EXPECT_EQ(a->at(0, 0)[0], static_cast<float>(img::splitmix64(s) >> 40) * 0x1p-24f);
  double mean = 0;
  for (size_t i = 0; i < a->rgba.size(); ++i) {
    if (i % 4 == 3) {
      EXPECT_EQ(a->rgba[i], 1.0f);
      continue;
    }
    EXPECT_GE(a->rgba[i], 0.0f);
    EXPECT_LT(a->rgba[i], 1.0f);
    mean += a->rgba[i];
  }
  mean /= 8 * 8 * 3;
  EXPECT_NEAR(mean, 0.5, 0.1);
}

TEST(Builtin, DefaultSizeAndErrors) {
  auto d = img::make_builtin("builtin:checker");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->width, img::kBuiltinDefaultSize);
  const char* bad[] = {"builtin:",
                       "builtin:sparkle",
                       "builtin:ramp:0x4",
                       "builtin:ramp:4",
                       "builtin:ramp:4x",
                       "builtin:ramp:x4",
                       "builtin:ramp:-1x4",
                       "builtin:ramp:16385x1",
                       "builtin:ramp:4x4:1",
                       "builtin:noise:4x4:seed",
                       "builtin:noise:4x4:1:2",
                       "ramp",
                       "builtin:ramp:99999999999999999999999x1"};
  for (const char* spec : bad) {
    auto r = img::make_builtin(spec);
    EXPECT_FALSE(r) << spec;
    EXPECT_FALSE(r.message().empty()) << spec;
  }
  auto unknown = img::make_builtin("builtin:sparkle");
  EXPECT_NE(unknown.message().find("unknown builtin"), std::string::npos) << unknown.message();
  EXPECT_TRUE(img::load_texture("builtin:impulse:3x3"));
}

// The size cap every input reads (img::valid_size): each side 1..16384.
TEST(ImageSize, CapByHand) {
  EXPECT_TRUE(tierlift::img::valid_size(1, 1));
  EXPECT_TRUE(tierlift::img::valid_size(16384, 16384));
  EXPECT_FALSE(tierlift::img::valid_size(16385, 1));
  EXPECT_FALSE(tierlift::img::valid_size(1, 16385));
  EXPECT_FALSE(tierlift::img::valid_size(0, 7));
  EXPECT_FALSE(tierlift::img::valid_size(7, 0));
}
