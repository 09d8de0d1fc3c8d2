// Random and randomly damaged input through every decoder: rejected with a message, or, where
// the format allows the damage, read exactly as the bytes say; never a crash (this runs
// under ASan/UBSan in CI). Seeded, so a failure reproduces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

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

// Random bytes are never an image: after a PNG signature the first chunk's CRC (or its
// type, IHDR) cannot match by chance (2^-32 per try), and after "PF" the header needs white
// space, two decimal sizes and a scale. Every one is rejected with a message.
TEST(DecodeSmoke, RandomBytesAreRejected) {
  uint64_t state = 99;
  for (int i = 0; i < 2000; ++i) {
    std::vector<uint8_t> b(img::splitmix64(state) % 200);
    for (auto& x : b) x = static_cast<uint8_t>(img::splitmix64(state));
    if (i % 2 == 0 && b.size() >= 8) { // half of them start like a PNG, to get past the magic
      const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
      std::copy(sig, sig + 8, b.begin());
    }
    auto png = img::decode_png(b);
    EXPECT_FALSE(png) << "random bytes " << i << " decoded as a PNG";
    EXPECT_FALSE(png.message().empty());
    if (b.size() >= 2) {
      b[0] = 'P';
      b[1] = 'F';
    }
    auto pfm = img::decode_pfm(b);
    EXPECT_FALSE(pfm) << "random bytes " << i << " decoded as a PFM";
    EXPECT_FALSE(pfm.message().empty());
  }
}

// Damaged files: every PNG chunk carries a CRC and the reader checks them all, so a PNG
// decodes only when it is byte for byte the original (then to the original's pixels). A PFM
// has an exact size: a longer or shorter one is rejected; one of the same size whose header
// survived decodes, every float read from its own 4 bytes (little endian, rows bottom to
// top: the file's scale is -1).
TEST(DecodeSmoke, DamagedFilesAreRejectedOrReadExactly) {
  img::Image noise = img::builtin_noise(7, 5, 3);
  struct File {
    std::vector<uint8_t> bytes;
    bool png;
    uint32_t channels; // PFM: 3 (PF) or 1 (Pf)
  };
  const File files[] = {{img::encode_png(noise, img::PngDepth::Bits8), true, 4},
                        {img::encode_png(noise, img::PngDepth::Bits16), true, 4},
                        {img::encode_pfm(noise), false, 3},
                        {img::encode_pfm(noise, img::PfmChannels::Grey), false, 1}};
  uint64_t state = 5;
  int decoded_damaged = 0;
  for (const File& f : files) {
    ASSERT_FALSE(f.bytes.empty());
    const auto original = f.png ? img::decode_png(f.bytes) : img::decode_pfm(f.bytes);
    ASSERT_TRUE(original) << original.message();
    const size_t raster = size_t{7} * 5 * f.channels * 4;
    const size_t header = f.bytes.size() - raster; // PFM only
    for (int i = 0; i < 1500; ++i) {
      auto b = mutate(f.bytes, state);
      auto r = f.png ? img::decode_png(b) : img::decode_pfm(b);
      if (b == f.bytes) {
        ASSERT_TRUE(r) << r.message();
        EXPECT_EQ(r->rgba, original->rgba);
        continue;
      }
      if (f.png || b.size() != f.bytes.size()) {
        EXPECT_FALSE(r) << (f.png ? "damaged PNG" : "PFM of the wrong size") << " decoded";
        EXPECT_FALSE(r.message().empty());
        continue;
      }
      if (!std::equal(b.begin(), b.begin() + static_cast<long>(header), f.bytes.begin()))
        continue; // a damaged header may still read as some header: either answer is right
      ASSERT_TRUE(r) << r.message();
      ++decoded_damaged;
      ASSERT_EQ(r->width, 7u);
      ASSERT_EQ(r->height, 5u);
      for (uint32_t y = 0; y < 5; ++y)
        for (uint32_t x = 0; x < 7; ++x)
          for (uint32_t c = 0; c < 4; ++c) {
            float want = 1.0f;
            if (c < 3) {
              const size_t k = ((4 - y) * 7 + x) * f.channels + (f.channels == 3 ? c : 0);
              const uint8_t* p = b.data() + header + 4 * k;
              uint32_t bits = uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 |
                              uint32_t{p[3]} << 24;
              std::memcpy(&want, &bits, 4);
            }
            const float got = r->at(x, y)[c];
            EXPECT_EQ(std::memcmp(&got, &want, 4), 0) << x << "," << y << " channel " << c;
          }
    }
  }
  EXPECT_GT(decoded_damaged, 0); // the raster-only damage did happen
}
