// PFM round trips (RGB and grey, both byte orders) and broken headers.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <limits>
#include <string>

#include "temp_dir.h"
#include "tierlift/image/io.h"

namespace img = tierlift::img;

namespace {
std::vector<uint8_t> bytes_of(const std::string& s) {
  return {s.begin(), s.end()};
}
void put_float(std::vector<uint8_t>& b, float f, bool little) {
  uint32_t u = std::bit_cast<uint32_t>(f);
  for (int i = 0; i < 4; ++i) {
    int shift = little ? 8 * i : 24 - 8 * i;
    b.push_back(static_cast<uint8_t>(u >> shift));
  }
}
} // namespace

TEST(Pfm, RgbRoundTripKeepsFloatsExactlyAndDropsAlpha) {
  tierlift::test::TempDir dir("pfm");
  img::Image im(2, 3);
  for (size_t i = 0; i < im.rgba.size(); ++i) im.rgba[i] = static_cast<float>(i) * 0.37f - 2.0f;
  im.at(1, 2)[0] = 1e30f;
  im.at(0, 1)[1] = -0.0f;
  im.at(1, 0)[2] = std::numeric_limits<float>::infinity();
  ASSERT_TRUE(img::write_pfm(dir.file("a.pfm"), im));
  auto back = img::read_image(dir.file("a.pfm"));
  ASSERT_TRUE(back) << back.message();
  ASSERT_EQ(back->width, 2u);
  ASSERT_EQ(back->height, 3u);
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 2; ++x) {
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(std::bit_cast<uint32_t>(back->at(x, y)[c]),
                  std::bit_cast<uint32_t>(im.at(x, y)[c]));
      EXPECT_EQ(back->at(x, y)[3], 1.0f);
    }
}

TEST(Pfm, HeaderAndRowOrderByHand) {
  img::Image im(1, 2);
  im.at(0, 0)[0] = 1.0f; // top row
  im.at(0, 1)[0] = 2.0f; // bottom row
  auto b = img::encode_pfm(im);
  std::string header = "PF\n1 2\n-1.0\n";
  ASSERT_EQ(b.size(), header.size() + 2 * 3 * 4);
  EXPECT_EQ(std::string(b.begin(), b.begin() + header.size()), header);
  float first;
  std::memcpy(&first, &b[header.size()], 4); // little-endian host assumed by CI (x86/arm)
  if constexpr (std::endian::native == std::endian::little) {
    EXPECT_EQ(first, 2.0f);
  }
}

TEST(Pfm, BigEndianAndGreyAreRead) {
  auto b = bytes_of("Pf\n2 1\n1.0\n"); // positive scale: big-endian
  put_float(b, 0.25f, false);
  put_float(b, -3.0f, false);
  auto r = img::decode_pfm(b);
  ASSERT_TRUE(r) << r.message();
  EXPECT_EQ(r->at(0, 0)[0], 0.25f);
  EXPECT_EQ(r->at(0, 0)[2], 0.25f);
  EXPECT_EQ(r->at(1, 0)[1], -3.0f);
  EXPECT_EQ(r->at(1, 0)[3], 1.0f);
  // Grey written out reads back the R channel.
  tierlift::test::TempDir dir("pfmgrey");
  ASSERT_TRUE(img::write_pfm(dir.file("g.pfm"), *r, img::PfmChannels::Grey));
  auto g = img::read_pfm(dir.file("g.pfm"));
  ASSERT_TRUE(g) << g.message();
  EXPECT_EQ(g->at(1, 0)[0], -3.0f);
}

TEST(Pfm, BrokenFilesAreErrors) {
  auto good = bytes_of("PF\n1 1\n-1.0\n");
  for (int i = 0; i < 3; ++i) put_float(good, 0.5f, true);
  ASSERT_TRUE(img::decode_pfm(good));
  for (size_t n = 0; n < good.size(); ++n)
    EXPECT_FALSE(img::decode_pfm(std::span(good.data(), n))) << n;
  auto extra = good;
  extra.push_back(0);
  EXPECT_FALSE(img::decode_pfm(extra));
  const char* bad_headers[] = {
      "PX\n1 1\n-1.0\n", "PF\n0 1\n-1.0\n", "PF\n1 -1\n-1.0\n",  "PF\n1 1\n0\n",
      "PF\n1 1\nnan\n",  "PF\n1 1\ninf\n",  "PF\n16385 1\n-1\n", "PF\n99999999999 1\n-1\n",
      "PF\n1x 1\n-1\n",  "PF1 1\n-1\n",     "PF\n1 1\n-1.0",     "PF\n4294967297 1\n-1\n"};
  for (const char* h : bad_headers) {
    auto b = bytes_of(h);
    for (int i = 0; i < 3; ++i) put_float(b, 0.5f, true);
    auto r = img::decode_pfm(b);
    EXPECT_FALSE(r) << h;
    EXPECT_FALSE(r.message().empty());
  }
  // A huge but in-range size with no data: truncated, not an allocation.
  auto big = bytes_of("PF\n16384 16384\n-1\n");
  auto r = img::decode_pfm(big);
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("truncated"), std::string::npos) << r.message();
}

TEST(Pfm, ReadImageRejectsUnknownSignature) {
  tierlift::test::TempDir dir("pfmsig");
  auto bytes = bytes_of("GIF89a");
  ASSERT_TRUE(img::write_file_atomic(dir.file("x.gif"), bytes));
  auto r = img::read_image(dir.file("x.gif"));
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("x.gif"), std::string::npos);
}
