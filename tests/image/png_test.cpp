// PNG round trips at 8 and 16 bits, foreign colour types, and every kind of broken file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "temp_dir.h"
#include "tierlift/image/io.h"

namespace img = tierlift::img;

namespace {

img::Image sample_image() {
  img::Image im(3, 2, img::Format::RGBA32F);
  const float v[] = {0.0f,  1.0f,  0.5f,  0.25f, 0.3f,   0.7f,   1.5f,   -0.2f,
                     0.1f,  0.9f,  0.42f, 1.0f,  0.6f,   0.2f,   0.8f,   0.0f,
                     0.33f, 0.66f, 0.99f, 0.01f, 0.123f, 0.456f, 0.789f, 0.5f};
  for (size_t i = 0; i < im.rgba.size(); ++i) im.rgba[i] = v[i];
  return im;
}

// Big-endian 32-bit write and PNG CRC, written here independently of the decoder.
void put32(std::vector<uint8_t>& b, uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<uint8_t>(v >> s));
}
uint32_t crc(const uint8_t* p, size_t n) {
  uint32_t c = 0xFFFFFFFFu;
  for (size_t i = 0; i < n; ++i) {
    c ^= p[i];
    for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
  }
  return c ^ 0xFFFFFFFFu;
}
void chunk(std::vector<uint8_t>& b, const char* type, const std::vector<uint8_t>& data) {
  put32(b, static_cast<uint32_t>(data.size()));
  size_t start = b.size();
  b.insert(b.end(), type, type + 4);
  b.insert(b.end(), data.begin(), data.end());
  put32(b, crc(&b[start], b.size() - start));
}
// A PNG with stored (uncompressed) zlib data: raw = filter byte + samples per row.
std::vector<uint8_t> handmade_png(uint32_t w, uint32_t h, uint8_t depth, uint8_t colour,
                                  const std::vector<uint8_t>& raw) {
  std::vector<uint8_t> b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<uint8_t> ihdr;
  put32(ihdr, w);
  put32(ihdr, h);
  ihdr.insert(ihdr.end(), {depth, colour, 0, 0, 0});
  chunk(b, "IHDR", ihdr);
  std::vector<uint8_t> z = {0x78, 0x01, 0x01}; // zlib header, final stored block
  uint16_t len = static_cast<uint16_t>(raw.size());
  z.insert(z.end(), {static_cast<uint8_t>(len & 0xFF), static_cast<uint8_t>(len >> 8),
                     static_cast<uint8_t>(~len & 0xFF), static_cast<uint8_t>((~len >> 8) & 0xFF)});
  z.insert(z.end(), raw.begin(), raw.end());
  uint32_t a = 1, s = 0;
  for (uint8_t c : raw) {
    a = (a + c) % 65521;
    s = (s + a) % 65521;
  }
  put32(z, (s << 16) | a);
  chunk(b, "IDAT", z);
  chunk(b, "IEND", {});
  return b;
}

} // namespace

TEST(Png, EightBitRoundTripStoresTheRgba8Rule) {
  tierlift::test::TempDir dir("png8");
  img::Image im = sample_image();
  ASSERT_TRUE(img::write_png(dir.file("a.png"), im, img::PngDepth::Bits8));
  auto back = img::read_png(dir.file("a.png"));
  ASSERT_TRUE(back) << back.message();
  EXPECT_EQ(back->format, img::Format::RGBA8);
  ASSERT_EQ(back->width, 3u);
  ASSERT_EQ(back->height, 2u);
  for (size_t i = 0; i < im.rgba.size(); ++i)
    EXPECT_EQ(back->rgba[i], img::quantize(img::Format::RGBA8, im.rgba[i])) << i;
  // By hand: 0.3 → 76.5 → 77; 1.5 clamps to 1; -0.2 clamps to 0.
  EXPECT_EQ(back->at(1, 0)[0], static_cast<float>(77 / 255.0));
  EXPECT_EQ(back->at(1, 0)[2], 1.0f);
  EXPECT_EQ(back->at(1, 0)[3], 0.0f);
}

TEST(Png, SixteenBitRoundTrip) {
  tierlift::test::TempDir dir("png16");
  img::Image im = sample_image();
  ASSERT_TRUE(img::write_png(dir.file("a.png"), im, img::PngDepth::Bits16));
  auto back = img::read_image(dir.file("a.png"));
  ASSERT_TRUE(back) << back.message();
  EXPECT_EQ(back->format, img::Format::RGBA32F);
  for (size_t i = 0; i < im.rgba.size(); ++i) {
    double clamped = std::fmin(std::fmax(im.rgba[i], 0.0f), 1.0f);
    double expect = std::floor(clamped * 65535.0 + 0.5) / 65535.0;
    EXPECT_NEAR(back->rgba[i], expect, 1e-7) << i;
    EXPECT_LE(std::fabs(back->rgba[i] - clamped), 0.5 / 65535.0 + 1e-7) << i;
  }
}

TEST(Png, GreyAndGreyAlphaAndRgbExpandToRgba) {
  // 2×1 grey 8-bit: values 0 and 255.
  auto grey = img::decode_png(handmade_png(2, 1, 8, 0, {0, 0, 255}));
  ASSERT_TRUE(grey) << grey.message();
  EXPECT_EQ(grey->at(1, 0)[0], 1.0f);
  EXPECT_EQ(grey->at(1, 0)[1], 1.0f);
  EXPECT_EQ(grey->at(0, 0)[3], 1.0f);
  // 1×1 grey+alpha 16-bit: grey 0x8000, alpha 0x4000.
  auto ga = img::decode_png(handmade_png(1, 1, 16, 4, {0, 0x80, 0x00, 0x40, 0x00}));
  ASSERT_TRUE(ga) << ga.message();
  EXPECT_FLOAT_EQ(ga->at(0, 0)[2], 32768.0f / 65535.0f);
  EXPECT_FLOAT_EQ(ga->at(0, 0)[3], 16384.0f / 65535.0f);
  // 1×1 RGB 8-bit (51, 102, 204): alpha reads 1.
  auto rgb = img::decode_png(handmade_png(1, 1, 8, 2, {0, 51, 102, 204}));
  ASSERT_TRUE(rgb) << rgb.message();
  EXPECT_EQ(rgb->at(0, 0)[0], static_cast<float>(51 / 255.0));
  EXPECT_EQ(rgb->at(0, 0)[2], static_cast<float>(204 / 255.0));
  EXPECT_EQ(rgb->at(0, 0)[3], 1.0f);
}

TEST(Png, TruncatedFilesAreErrors) {
  auto bytes = img::encode_png(sample_image(), img::PngDepth::Bits8);
  ASSERT_FALSE(bytes.empty());
  ASSERT_TRUE(img::decode_png(bytes));
  for (size_t n = 0; n < bytes.size(); ++n) {
    auto r = img::decode_png(std::span(bytes.data(), n));
    EXPECT_FALSE(r) << "prefix of " << n << " bytes decoded";
    EXPECT_FALSE(r.message().empty());
  }
}

TEST(Png, EveryFlippedBitIsAnError) {
  auto bytes = img::encode_png(sample_image(), img::PngDepth::Bits16);
  for (size_t i = 0; i < bytes.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      auto copy = bytes;
      copy[i] ^= static_cast<uint8_t>(1u << bit);
      auto r = img::decode_png(copy);
      EXPECT_FALSE(r) << "flip of byte " << i << " bit " << bit << " decoded";
    }
}

TEST(Png, OversizedAndEmptyHeadersAreErrors) {
  auto huge = img::decode_png(handmade_png(img::kMaxDimension + 1, 1, 8, 0, {0, 0}));
  EXPECT_FALSE(huge);
  EXPECT_NE(huge.message().find("exceeds"), std::string::npos) << huge.message();
  EXPECT_FALSE(img::decode_png(handmade_png(0xFFFFFFFFu, 0xFFFFFFFFu, 8, 6, {0})));
  EXPECT_FALSE(img::decode_png(handmade_png(0, 1, 8, 0, {0})));
  // Valid header, too little pixel data for 4×4.
  auto shortdata = img::decode_png(handmade_png(4, 4, 8, 0, {0, 1, 2, 3, 4}));
  EXPECT_FALSE(shortdata);
  // Bad bit depth for RGB.
  EXPECT_FALSE(img::decode_png(handmade_png(1, 1, 4, 2, {0, 0})));
  // Not a PNG at all.
  std::vector<uint8_t> text = {'h', 'e', 'l', 'l', 'o'};
  EXPECT_FALSE(img::decode_png(text));
  EXPECT_FALSE(img::decode_png({}));
}

TEST(Png, MissingFileAndUnwritableFolderAreErrors) {
  tierlift::test::TempDir dir("pngio");
  auto r = img::read_png(dir.file("nope.png"));
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("nope.png"), std::string::npos);
  auto st = img::write_png(dir.file("no/such/folder/a.png"), sample_image());
  EXPECT_FALSE(st);
  EXPECT_FALSE(st.message().empty());
  EXPECT_FALSE(img::write_png(dir.file("empty.png"), img::Image()));
  EXPECT_FALSE(std::filesystem::exists(dir.file("empty.png")));
}

TEST(Png, AtomicWriteLeavesNoTemporaryFiles) {
  tierlift::test::TempDir dir("pngatomic");
  ASSERT_TRUE(img::write_png(dir.file("a.png"), sample_image()));
  ASSERT_TRUE(img::write_png(dir.file("a.png"), sample_image(), img::PngDepth::Bits16));
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
    ++files;
    EXPECT_EQ(e.path().filename(), "a.png");
  }
  EXPECT_EQ(files, 1);
  auto back = img::read_png(dir.file("a.png"));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->format, img::Format::RGBA32F); // the 16-bit file replaced the 8-bit
}

TEST(Png, DecodeBudgetIsCheckedBeforeInflating) {
  // 8192 × 8192 RGBA floats are 8192² × 16 bytes = 2^30, exactly the budget: allowed past
  // the check (and refused later for its missing pixels); one column more is over it.
  auto at_budget = img::decode_png(handmade_png(8192, 8192, 8, 6, {0}));
  EXPECT_FALSE(at_budget);
  EXPECT_EQ(at_budget.message().find("budget"), std::string::npos) << at_budget.message();
  auto over = img::decode_png(handmade_png(8193, 8192, 8, 6, {0}));
  EXPECT_FALSE(over);
  EXPECT_NE(over.message().find("image 8193x8192 needs 1024 MiB as RGBA floats, over the decode "
                                "budget of 1024 MiB"),
            std::string::npos)
      << over.message();
  auto bomb = img::decode_png(handmade_png(16384, 16384, 8, 6, {0}));
  EXPECT_NE(bomb.message().find("needs 4096 MiB"), std::string::npos) << bomb.message();
}

TEST(Png, ReadErrorsTellIoFromInvalidContent) {
  tierlift::test::TempDir dir("pngkind");
  auto missing = img::read_png(dir.file("nope.png"));
  EXPECT_TRUE(img::is_io_error(missing));
  ASSERT_FALSE(missing.diagnostics().empty());
  EXPECT_EQ(missing.diagnostics()[0].rule, img::kIoRule);
  EXPECT_EQ(missing.diagnostics()[0].subject, dir.file("nope.png"));
  auto zero = img::read_image("/dev/zero"); // refused from its first bytes, not read whole
  EXPECT_FALSE(zero);
  EXPECT_FALSE(img::is_io_error(zero));
  EXPECT_EQ(zero.diagnostics()[0].rule, img::kImageRule);
  EXPECT_NE(zero.message().find("unknown signature"), std::string::npos) << zero.message();
}
