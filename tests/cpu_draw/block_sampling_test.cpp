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
              Lanes u{}, v{}, zero{}, out[4];
              const bool plain = round % 2 == 0;
              std::uniform_real_distribution<float> in(0.0f, 1.0f);
              for (int l = 0; l < kBlockLanes; ++l) {
                u[l] = plain ? in(rng) : coordinate(w, rng);
                v[l] = plain ? in(rng) : coordinate(h, rng);
              }
              const int n = round % 5 == 4 ? 61 : kBlockLanes;
              const float* coord[4] = {u, v, zero, zero};
              t.sample_block(0, coord, nullptr, n, out);
              for (int l = 0; l < n; ++l) {
                const Vec4 want = t.sample(0, {u[l], v[l], 0, 0}, 0);
                for (int c = 0; c < 4; ++c) {
                  ASSERT_EQ(std::memcmp(&out[c][l], &want[c], sizeof(float)), 0)
                      << "lane " << l << " channel " << c << " u " << u[l] << " v " << v[l]
                      << " filter " << filter << " mode " << static_cast<int>(mu) << " bits "
                      << bits << " llvmpipe " << llvmpipe << ": " << out[c][l] << " vs " << want[c];
                  ++compared;
                }
              }
            }
          }
  EXPECT_GT(compared, 100000u);
}

} // namespace
} // namespace tierlift::cpu
