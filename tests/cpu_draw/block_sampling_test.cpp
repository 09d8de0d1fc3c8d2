// The block read (BoundTextures::sample_block) against the per-lane read (sample) bit for bit,
// on coordinates chosen to hit the edges of its eight-lane path: texel corners k/N and
// centres (k + ½)/N, 0 and 1 exactly, one float step either side of them, just outside the
// texture, NaN and ±inf, on textures holding denormals, in every address mode, point and
// bilinear, with and without sub-texel quantisation, for block sizes that leave a tail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {
namespace {

std::shared_ptr<const img::Image> texture(uint32_t w, uint32_t h, std::mt19937& rng) {
  auto im = std::make_shared<img::Image>(w, h, img::Format::RGBA32F);
  std::uniform_real_distribution<float> v(-1.0f, 2.0f);
  std::uniform_int_distribution<int> pick(0, 7);
  for (float& x : im->rgba) {
    const int k = pick(rng);
    // Denormals of both signs, and normals near 2^-126 whose differences and lerps are
    // denormal (the flushes of rounding::lerp).
    const float tiny[] = {1e-40f, -0x1p-149f, 0x1p-125f, -0x1.8p-126f, 0x1.8p-125f};
    x = k < 5 ? tiny[k] : v(rng);
  }
  return im;
}

// A coordinate on an edge of the fast path, or an ordinary one, for an axis of n texels.
float coordinate(uint32_t n, std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 9), texel(0, static_cast<int>(n));
  std::uniform_real_distribution<float> inside(0.0f, 1.0f), wide(-0.3f, 1.3f);
  const float k = static_cast<float>(texel(rng)), size = static_cast<float>(n);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  switch (kind(rng)) {
  case 0: return k / size;                                 // a texel corner
  case 1: return (k + 0.5f) / size;                        // a texel centre
  case 2: return std::nextafter(k / size, kInf);           // just right of a corner
  case 3: return std::nextafter(k / size, -kInf);          // just left of a corner
  case 4: return std::nextafter((k + 0.5f) / size, -kInf); // just left of a centre
  case 5: return wide(rng);                                // maybe outside
  case 6: {
    const float special[] = {0.0f, -0.0f, 1.0f, std::nanf(""), kInf, -kInf, 1e-40f, -1e-40f};
    return special[std::uniform_int_distribution<int>(0, 7)(rng)];
  }
  default: return inside(rng);
  }
}

// Lanes 0..n−1 read through the block read and through the per-lane read (sample) must be
// the same bits; the number of values compared (a failure names the first that differs).
size_t expect_block_as_lanes(const BoundTextures& t, const Lanes& u, const Lanes& v, int n,
                             const std::string& what) {
  Lanes zero{}, out[4];
  const float* coord[4] = {u, v, zero, zero};
  t.sample_block(0, coord, nullptr, n, out);
  size_t compared = 0;
  for (int l = 0; l < n; ++l) {
    const Vec4 want = t.sample(0, {u[l], v[l], 0, 0}, 0);
    for (int c = 0; c < 4; ++c, ++compared)
      if (std::memcmp(&out[c][l], &want[c], sizeof(float)) != 0) {
        ADD_FAILURE() << what << ", lane " << l << " channel " << c << " u " << u[l] << " v "
                      << v[l] << ": " << out[c][l] << " vs " << want[c];
        return compared;
      }
  }
  return compared;
}

TEST(BlockSampling, EveryLaneAsThePerLaneRead) {
  std::mt19937 rng(2024);
  const AddressMode modes[] = {AddressMode::Clamp, AddressMode::Wrap, AddressMode::Mirror,
                               AddressMode::Border, AddressMode::MirrorOnce};
  size_t compared = 0;
  for (const auto& [w, h] : {std::pair{37u, 23u}, std::pair{64u, 64u}, std::pair{1u, 5u}})
    for (int filter = 0; filter < 2; ++filter)
      for (AddressMode mu : modes)
        for (int bits : {0, 8})
          for (bool llvmpipe : {true, false}) {
            std::array<TextureBinding, kMaxSamplers> b{};
            b[0].image = texture(w, h, rng);
            b[0].sampler.filter = filter ? Filter::Linear : Filter::Point;
            b[0].sampler.address_u = mu;
            b[0].sampler.address_v = modes[(static_cast<int>(mu) + 1) % 5];
            b[0].sampler.border_color = {0.25f, 0.5f, 0.75f, 1.0f};
            const BoundTextures t(b, bits, llvmpipe);
            for (int round = 0; round < 40; ++round) {
              // Mostly blocks whose lanes are all inside (the vector path), sometimes with
              // one edge case among them, and a count that leaves a tail.
              Lanes u{}, v{};
              const bool plain = round % 2 == 0;
              std::uniform_real_distribution<float> in(0.0f, 1.0f);
              for (int l = 0; l < kBlockLanes; ++l) {
                u[l] = plain ? in(rng) : coordinate(w, rng);
                v[l] = plain ? in(rng) : coordinate(h, rng);
              }
              const int n = round % 5 == 4 ? 61 : kBlockLanes;
              compared += expect_block_as_lanes(t, u, v, n,
                                                "filter " + std::to_string(filter) + " mode " +
                                                    std::to_string(static_cast<int>(mu)) +
                                                    " bits " + std::to_string(bits) + " llvmpipe " +
                                                    std::to_string(llvmpipe));
            }
          }
  EXPECT_GT(compared, 100000u);
}

// Point reads of texels that lie side by side in memory, as a pass reading its source one
// to one makes them (the block read loads such a group of eight with four wide loads): runs
// along a row, runs that go on at the start of the next row (still side by side in memory),
// and runs with one lane moved a texel away or onto another row.
TEST(BlockSampling, PointReadsOfTexelsSideBySide) {
  std::mt19937 rng(5);
  size_t compared = 0;
  for (const auto& [w, h] : {std::pair{37u, 23u}, std::pair{64u, 64u}}) {
    std::array<TextureBinding, kMaxSamplers> b{};
    b[0].image = texture(w, h, rng);
    b[0].sampler.filter = Filter::Point;
    const BoundTextures t(b, 0, true);
    std::uniform_int_distribution<uint32_t> start(0, w * h - kBlockLanes), lane(0, kBlockLanes - 1),
        sign(0, 1);
    for (int round = 0; round < 300; ++round) {
      Lanes u{}, v{};
      const uint32_t first = start(rng);
      for (int l = 0; l < kBlockLanes; ++l) {
        const uint32_t p = first + static_cast<uint32_t>(l);
        u[l] = (static_cast<float>(p % w) + 0.5f) / static_cast<float>(w);
        v[l] = (static_cast<float>(p / w) + 0.5f) / static_cast<float>(h);
      }
      // One lane a texel left or right (onto its neighbour's texel, say), or a row down.
      const int moved = static_cast<int>(lane(rng));
      const float side = sign(rng) ? 1.0f : -1.0f;
      if (round % 3 == 1) u[moved] += side / static_cast<float>(w);
      if (round % 3 == 2) v[moved] = std::fmod(v[moved] + 1.0f / static_cast<float>(h), 1.0f);
      compared += expect_block_as_lanes(t, u, v, kBlockLanes, "round " + std::to_string(round));
    }
  }
  EXPECT_EQ(compared, size_t{2} * 300 * kBlockLanes * 4);
}

// The llvmpipe bilinear read skips rounding::lerp's flushes for a group whose texels are all
// 0, ±∞, NaN or at least 2^-40 in magnitude (smooth_texels in texture_sampling_block.cpp).
// The smallest values a lerp can make come from cancellation: texels of one magnitude a few
// ulps apart, with signs alternating in a checkerboard, read near texel corners (weights
// about ½) so that each lerp nearly cancels, or near centres (weights of a few 2^-24). At
// 2^-40 and 2^-41 (the bound the skip rests on, and the first scale below it) they stay
// normal; the smallest scales here reach the denormals, where the flushes must be kept (a
// bound of 2^-72 or lower fails this test; the proof beside smooth_texels holds for any
// bound of 2^-55 or more).
TEST(BlockSampling, BilinearFlushesSkippedOnlyWhereNothingCanBeDenormal) {
  std::mt19937 rng(77);
  size_t compared = 0;
  const float scales[] = {0x1p-40f, 0x1p-41f, 0x1p-52f, 0x1p-64f, 0x1p-76f, 0x1p-88f, 0x1p-100f};
  for (float scale : scales) {
    const uint32_t w = 16, h = 16;
    auto im = std::make_shared<img::Image>(w, h, img::Format::RGBA32F);
    std::uniform_int_distribution<int> ulps(0, 3);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x)
        for (int c = 0; c < 4; ++c)
          im->at(x, y)[c] =
              ((x + y) % 2 ? -scale : scale) * (1.0f + static_cast<float>(ulps(rng)) * 0x1p-23f);
    std::array<TextureBinding, kMaxSamplers> b{};
    b[0].image = im;
    b[0].sampler.filter = Filter::Linear;
    const BoundTextures t(b, 0, true);
    std::uniform_int_distribution<int> texel(1, static_cast<int>(w) - 2), step(-4, 4), half(0, 1);
    // A texel corner (weight ½) or centre (weight 0), moved by a few float steps.
    auto near = [&](uint32_t n) {
      float c =
          (static_cast<float>(texel(rng)) + (half(rng) ? 0.5f : 0.0f)) / static_cast<float>(n);
      const int k = step(rng);
      for (int i = 0; i < std::abs(k); ++i) c = std::nextafter(c, k > 0 ? 1.0f : 0.0f);
      return c;
    };
    for (int round = 0; round < 200; ++round) {
      Lanes u{}, v{};
      for (int l = 0; l < kBlockLanes; ++l) {
        u[l] = near(w);
        v[l] = near(h);
      }
      compared += expect_block_as_lanes(t, u, v, kBlockLanes, "scale " + std::to_string(scale));
    }
  }
  EXPECT_EQ(compared, std::size(scales) * 200 * kBlockLanes * 4);
}

} // namespace
} // namespace tierlift::cpu
