// The store rule of each target format, checked at its boundaries by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/image/image.h"

using tierlift::img::Format;
using tierlift::img::quantize;

TEST(Quantize, FormatNamesRoundTrip) {
  for (Format f : {Format::RGBA8, Format::RGBA16F, Format::RGBA32F})
    EXPECT_EQ(tierlift::img::parse_format(tierlift::img::format_name(f)), f);
  EXPECT_EQ(tierlift::img::format_name(Format::RGBA16F), "rgba16f");
  EXPECT_FALSE(tierlift::img::parse_format("rgba4").has_value());
}

TEST(Quantize, Rgba8ClampsAndRoundsToNearestStep) {
  EXPECT_EQ(quantize(Format::RGBA8, -0.25f), 0.0f);
  EXPECT_EQ(quantize(Format::RGBA8, 7.0f), 1.0f);
  EXPECT_EQ(quantize(Format::RGBA8, 1.0f), 1.0f);
  EXPECT_EQ(quantize(Format::RGBA8, std::numeric_limits<float>::quiet_NaN()), 0.0f);
  EXPECT_EQ(quantize(Format::RGBA8, std::numeric_limits<float>::infinity()), 1.0f);
  // Half a step is the boundary between 0 and 1/255.
  const float half_step = static_cast<float>(0.5 / 255.0);
  EXPECT_EQ(quantize(Format::RGBA8, std::nextafter(half_step, 0.0f) * 0.999f), 0.0f);
  EXPECT_EQ(quantize(Format::RGBA8, half_step * 1.001f), static_cast<float>(1.0 / 255.0));
  // 0.5 lies between 127/255 and 128/255 at 127.5/255: just above rounds up.
  EXPECT_EQ(quantize(Format::RGBA8, 0.5f), static_cast<float>(128.0 / 255.0));
  EXPECT_EQ(quantize(Format::RGBA8, static_cast<float>(127.4 / 255.0)),
            static_cast<float>(127.0 / 255.0));
  // A stored value is a fixed point of the rule.
  for (int k = 0; k <= 255; ++k) {
    float v = static_cast<float>(k / 255.0);
    EXPECT_EQ(quantize(Format::RGBA8, v), v) << k;
  }
}

TEST(Quantize, HalfRoundsToNearestEven) {
  // Around 1: half spacing is 2^-10. 1 + 2^-11 is a tie between 1 and 1 + 2^-10: even = 1.
  EXPECT_EQ(quantize(Format::RGBA16F, 1.0f + 0x1p-11f), 1.0f);
  // 1 + 3·2^-11 is a tie between 1 + 2^-10 (odd) and 1 + 2^-9 (even): goes up.
  EXPECT_EQ(quantize(Format::RGBA16F, 1.0f + 3 * 0x1p-11f), 1.0f + 0x1p-9f);
  // Just above the tie rounds up.
  EXPECT_EQ(quantize(Format::RGBA16F, 1.0f + 0x1p-11f + 0x1p-20f), 1.0f + 0x1p-10f);
  EXPECT_EQ(quantize(Format::RGBA16F, -(1.0f + 0x1p-11f + 0x1p-20f)), -(1.0f + 0x1p-10f));
  // 0.1 → nearest half is 0x2E66 = 1638/16384 = 0.0999755859375.
  EXPECT_EQ(quantize(Format::RGBA16F, 0.1f), 0.0999755859375f);
  // Largest half and overflow: 65504 stays, 65519 rounds down, 65520 (the tie) → inf.
  EXPECT_EQ(quantize(Format::RGBA16F, 65504.0f), 65504.0f);
  EXPECT_EQ(quantize(Format::RGBA16F, 65519.0f), 65504.0f);
  EXPECT_TRUE(std::isinf(quantize(Format::RGBA16F, 65520.0f)));
  EXPECT_EQ(quantize(Format::RGBA16F, -1e6f), -std::numeric_limits<float>::infinity());
  // Subnormal halves: spacing 2^-24. 1.5·2^-24 ties to 2·2^-24; 0.5·2^-24 ties to 0.
  EXPECT_EQ(quantize(Format::RGBA16F, 1.5f * 0x1p-24f), 0x1p-23f);
  EXPECT_EQ(quantize(Format::RGBA16F, 0.5f * 0x1p-24f), 0.0f);
  EXPECT_EQ(quantize(Format::RGBA16F, 0.75f * 0x1p-24f), 0x1p-24f);
  // Smallest normal half 2^-14 and its neighbour 2^-14 + 2^-24.
  EXPECT_EQ(quantize(Format::RGBA16F, 0x1p-14f + 0x1p-24f), 0x1p-14f + 0x1p-24f);
  // NaN kept, -0 kept.
  EXPECT_TRUE(std::isnan(quantize(Format::RGBA16F, std::numeric_limits<float>::quiet_NaN())));
  EXPECT_TRUE(std::signbit(quantize(Format::RGBA16F, -0.0f)));
  // Exact halves are fixed points; 2048 + 1 is not representable (spacing 2 there).
  EXPECT_EQ(quantize(Format::RGBA16F, 2049.0f), 2048.0f);
  EXPECT_EQ(quantize(Format::RGBA16F, 2051.0f), 2052.0f);
}

TEST(Quantize, Rgba32fUnchanged) {
  EXPECT_EQ(quantize(Format::RGBA32F, 0.1f), 0.1f);
  EXPECT_EQ(quantize(Format::RGBA32F, -3e38f), -3e38f);
  EXPECT_TRUE(std::isnan(quantize(Format::RGBA32F, std::nanf(""))));
}

TEST(Quantize, InPlaceUsesTheImageFormat) {
  tierlift::img::Image im(2, 1, Format::RGBA8);
  im.rgba = {0.1f, 2.0f, -1.0f, 0.5f, 0.0f, 0.0f, 0.0f, 1.0f};
  tierlift::img::quantize_in_place(im);
  EXPECT_EQ(im.rgba[0], static_cast<float>(26.0 / 255.0)); // 25.5 → 26 (0.1f > 0.1)
  EXPECT_EQ(im.rgba[1], 1.0f);
  EXPECT_EQ(im.rgba[2], 0.0f);
  EXPECT_EQ(im.rgba[3], static_cast<float>(128.0 / 255.0));
}
