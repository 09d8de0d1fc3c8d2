// Random and randomly damaged input through every decoder: an error or an image, never a
// crash (this runs under ASan/UBSan in CI). Seeded, so a failure reproduces.
#include <gtest/gtest.h>

#include "tierlift/image/builtin.h"
#include "tierlift/image/io.h"

namespace img = tierlift::img;

namespace {
std::vector<uint8_t> mutate(std::vector<uint8_t> b, uint64_t& state) {
  int edits = 1 + static_cast<int>(img::splitmix64(state) % 8);
  for (int e = 0; e < edits && !b.empty(); ++e) {
    uint64_t r = img::splitmix64(state);
    size_t at = static_cast<size_t>(r % b.size());
    switch ((r >> 32) % 3) {
    case 0: b[at] = static_cast<uint8_t>(r >> 40); break; // overwrite
    case 1: b.resize(at); break;                          // truncate
    default: b.insert(b.begin() + static_cast<long>(at), static_cast<uint8_t>(r >> 48)); // insert
    }
  }
  return b;
}
} // namespace

TEST(DecodeSmoke, RandomBytesNeverCrash) {
  uint64_t state = 99;
  for (int i = 0; i < 2000; ++i) {
    std::vector<uint8_t> b(img::splitmix64(state) % 200);
    for (auto& x : b) x = static_cast<uint8_t>(img::splitmix64(state));
    if (i % 2 == 0 && b.size() >= 8) { // half of them start like a PNG, to get past the magic
      const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
      std::copy(sig, sig + 8, b.begin());
    }
    auto png = img::decode_png(b);
    EXPECT_TRUE(png || !png.error.empty());
    if (b.size() >= 2) {
      b[0] = 'P';
      b[1] = 'F';
    }
    auto pfm = img::decode_pfm(b);
    EXPECT_TRUE(pfm || !pfm.error.empty());
  }
}

TEST(DecodeSmoke, DamagedValidFilesNeverCrash) {
  img::Image noise = img::builtin_noise(7, 5, 3);
  const std::vector<uint8_t> files[] = {
      img::encode_png(noise, img::PngDepth::Bits8), img::encode_png(noise, img::PngDepth::Bits16),
      img::encode_pfm(noise), img::encode_pfm(noise, img::PfmChannels::Grey)};
  uint64_t state = 5;
  for (const auto& f : files) {
    ASSERT_FALSE(f.empty());
    for (int i = 0; i < 1500; ++i) {
      auto b = mutate(f, state);
      auto r = (b.size() >= 2 && b[0] == 'P') ? img::decode_pfm(b) : img::decode_png(b);
      if (r) {
        EXPECT_LE(r.image->width, img::kMaxDimension);
        EXPECT_EQ(r.image->rgba.size(), size_t{r.image->width} * r.image->height * 4);
      } else {
        EXPECT_FALSE(r.error.empty());
      }
    }
  }
}
