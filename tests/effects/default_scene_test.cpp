// The built-in scene: layout rules of default_scene.h checked pixel by pixel.
#include <gtest/gtest.h>

#include <algorithm>

#include "tierlift/effects/scenes/default_scene.h"

namespace tierlift::effects {
namespace {

TEST(DefaultScene, SizeAndFormat) {
  img::Image s = make_default_scene();
  EXPECT_EQ(s.width, 1280u);
  EXPECT_EQ(s.height, 720u);
  EXPECT_EQ(make_default_scene(128, 64, img::Format::RGBA8).format, img::Format::RGBA8);
}

TEST(DefaultScene, AlphaMarksBrightGlowingPixelsOnADarkGround) {
  for (auto [w, h] : {std::pair{1280u, 720u}, std::pair{128u, 64u}}) {
    img::Image s = make_default_scene(w, h);
    uint64_t glowing = 0, ground = 0;
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        const float* p = s.at(x, y);
        const float brightest = std::max({p[0], p[1], p[2]});
        ASSERT_TRUE(p[3] == 0.0f || p[3] == 1.0f) << x << "," << y;
        if (p[3] == 1.0f) {
          ++glowing;
          EXPECT_EQ(brightest, 1.0f) << x << "," << y; // every glow colour has a full channel
        } else {
          EXPECT_LE(brightest, 100.0f / 255) << x << "," << y;
          if (p[0] == 10.0f / 255 && p[1] == 10.0f / 255 && p[2] == 16.0f / 255) ++ground;
        }
        for (int c = 0; c < 4; ++c) EXPECT_EQ(img::quantize(img::Format::RGBA8, p[c]), p[c]);
      }
    const double share = double(glowing) / (double(w) * h);
    EXPECT_GT(share, 0.005) << w;
    EXPECT_LT(share, 0.15) << w;
    EXPECT_GT(double(ground) / (double(w) * h), 0.5) << w; // mostly dark ground
  }
}

TEST(DefaultScene, FeaturesWhereTheHeaderPutsThem) {
  img::Image s = make_default_scene();
  // Magenta strip: x from 0.10·1280 = 128, y from 0.30·720 = 216, 720/60 = 12 rows.
  const float* m = s.at(300, 216 + 11);
  EXPECT_EQ(m[0], 1.0f);
  EXPECT_EQ(m[1], 40.0f / 255);
  EXPECT_EQ(m[3], 1.0f);
  EXPECT_EQ(s.at(300, 216 + 12)[3], 0.0f);
  EXPECT_EQ(s.at(300, 215)[3], 0.0f);
  // Light at (0.2·1280, 0.15·720) = (256, 108), radius 720/90 = 8.
  EXPECT_EQ(s.at(256, 108 + 8)[3], 1.0f);
  EXPECT_EQ(s.at(256, 108 + 9)[3], 0.0f);
  // The grey panel does not glow.
  const float* panel = s.at(200, 500);
  EXPECT_EQ(panel[0], 90.0f / 255);
  EXPECT_EQ(panel[3], 0.0f);
}

} // namespace
} // namespace tierlift::effects
