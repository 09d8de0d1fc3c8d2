// The RGBA8 store and blend rules of ir::Rounding::Llvmpipe (NUMERICS.md rule 34) against
// Rounding::Exact, on values where the two differ. Every expected byte is worked out by hand
// below from the rule: p = fl32(x·255) (the float product, rounded to 24 bits), then ties to
// even; products of bytes with (t + (t >> 8) + 128) >> 8, t = a·b; sums saturate at 255.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "program_helpers.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::cpu {
namespace {

const img::Format U8 = img::Format::RGBA8;
constexpr ir::Rounding kLlvmpipe = ir::Rounding::Llvmpipe, kExact = ir::Rounding::Exact;

float byte(int k) {
  return static_cast<float>(k) / 255.0f;
}

// The float nearest 0.5/255 is 0x1.010102p-9; times 255 it is 0.5 + 2.96e-8, and the float
// spacing at 0.5 is 2^-24 = 5.96e-8, so fl32 gives exactly 0.5: even → 0 (exact rule: 1).
TEST(Rgba8StoreLlvmpipe, ProductRoundingOntoAMidpointGoesToEven) {
  const float half_lsb = 0x1.010102p-9f;
  EXPECT_EQ(rounding::unorm8_llvmpipe(half_lsb), 0);
  EXPECT_EQ(img::quantize(U8, half_lsb), byte(1));
  // 2.5/255 ≈ 0x1.414142p-7: times 255 = 2.5 + 8.8e-8, spacing at 2.5 is 2^-22 = 2.4e-7 →
  // fl32 = 2.5 → 2 (exact: 3).
  EXPECT_EQ(rounding::unorm8_llvmpipe(0x1.414142p-7f), 2);
  EXPECT_EQ(img::quantize(U8, 0x1.414142p-7f), byte(3));
  // 0.3f = 0x1.333334p-2: times 255 = 76.5000030, spacing at 76.5 is 2^-17 = 7.6e-6 →
  // fl32 = 76.5 → 76 (exact: 77).
  EXPECT_EQ(rounding::unorm8_llvmpipe(0.3f), 76);
  EXPECT_EQ(img::quantize(U8, 0.3f), byte(77));
  // 0.9f = 0x1.cccccc p-1: times 255 = 229.4999939, spacing 2^-16 = 1.5e-5 → fl32 = 229.5 →
  // 230 (exact: 229). The float rule can also round up where the exact one rounds down.
  EXPECT_EQ(rounding::unorm8_llvmpipe(0.9f), 230);
  EXPECT_EQ(img::quantize(U8, 0.9f), byte(229));
}

TEST(Rgba8StoreLlvmpipe, AgreesWithExactAwayFromMidpointsAndAtTheEnds) {
  EXPECT_EQ(rounding::unorm8_llvmpipe(0.5f), 128); // 127.5 exactly: even is 128, as half up
  EXPECT_EQ(rounding::unorm8_llvmpipe(0.25f), 64); // 63.75
  EXPECT_EQ(rounding::unorm8_llvmpipe(0.1f), 26);  // 25.50000038 → fl32 25.5 → even 26
  EXPECT_EQ(rounding::unorm8_llvmpipe(0.05f), 13); // 12.75
  EXPECT_EQ(rounding::unorm8_llvmpipe(1.0f), 255);
  EXPECT_EQ(rounding::unorm8_llvmpipe(std::nextafter(1.0f, 0.0f)), 255); // 254.99998
  EXPECT_EQ(rounding::unorm8_llvmpipe(0.0f), 0);
  EXPECT_EQ(rounding::unorm8_llvmpipe(-0.0f), 0);
  EXPECT_EQ(rounding::unorm8_llvmpipe(-3.0f), 0);
  EXPECT_EQ(rounding::unorm8_llvmpipe(7.0f), 255);
  EXPECT_EQ(rounding::unorm8_llvmpipe(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(rounding::unorm8_llvmpipe(-std::numeric_limits<float>::infinity()), 0);
  EXPECT_EQ(rounding::unorm8_llvmpipe(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(rounding::unorm8_llvmpipe(1e-40f), 0); // denormal: 2.55e-38 rounds to 0
}

TEST(Rgba8StoreLlvmpipe, ReplaceStoresTheLlvmpipeByte) {
  const Vec4 src{0.3f, 0.9f, 0x1.010102p-9f, 0.5f};
  EXPECT_EQ(blend_and_store(BlendMode::Replace, U8, src, {}, kLlvmpipe),
            (Vec4{byte(76), byte(230), byte(0), byte(128)}));
  EXPECT_EQ(blend_and_store(BlendMode::Replace, U8, src, {}, kExact),
            (Vec4{byte(77), byte(229), byte(1), byte(128)}));
}

// ONE/ONE adds the source byte to the destination byte: 0.5/255 → 0, plus 10 = 10; the float
// blend gives 10.5000000296/255 → 11. 0.9 → 230, plus 30 = 260 → saturates at 255.
TEST(Rgba8StoreLlvmpipe, OneOneAddsBytes) {
  const Vec4 src{0x1.010102p-9f, 0.3f, 0.9f, 0.0f};
  const Vec4 dst{byte(10), byte(100), byte(30), byte(7)};
  EXPECT_EQ(blend_and_store(BlendMode::OneOne, U8, src, dst, kLlvmpipe),
            (Vec4{byte(10), byte(176), byte(255), byte(7)}));
  EXPECT_EQ(blend_and_store(BlendMode::OneOne, U8, src, dst, kExact)[0], byte(11));
}

// SRCALPHA/ONE: src 0.3 → 76, alpha 0.4 → fl32(102.0000015) = 102 → 102. 76·102 = 7752;
// (7752 + 30 + 128) >> 8 = 7910 >> 8 = 30. The float blend: 0.3·0.4·255 = 30.6 → 31.
// Alpha channel: 102·102 = 10404; (10404 + 40 + 128) >> 8 = 10572 >> 8 = 41; plus 200 = 241.
TEST(Rgba8StoreLlvmpipe, SrcAlphaOneMultipliesBytesWithRounding) {
  const Vec4 src{0.3f, 0.1f, 1.0f, 0.4f};
  const Vec4 dst{0, byte(5), byte(250), byte(200)};
  // Green: 0.1 → 26; 26·102 = 2652; (2652 + 10 + 128) >> 8 = 2790 >> 8 = 10; + 5 = 15.
  // Blue: 255·102 = 26010; (26010 + 101 + 128) >> 8 = 26239 >> 8 = 102; + 250 → 255.
  EXPECT_EQ(blend_and_store(BlendMode::SrcAlphaOne, U8, src, dst, kLlvmpipe),
            (Vec4{byte(30), byte(15), byte(255), byte(241)}));
  EXPECT_EQ(blend_and_store(BlendMode::SrcAlphaOne, U8, src, dst, kExact)[0], byte(31));
}

// The byte product is not always the nearest integer: 152·229 = 34808, 34808/255 = 136.502,
// but (34808 + 135 + 128) >> 8 = 35071 >> 8 = 136. The float blend rounds to 137.
TEST(Rgba8StoreLlvmpipe, ByteProductKeepsLlvmpipesRounding) {
  const Vec4 src{byte(152), 0, 0, byte(229)};
  EXPECT_EQ(blend_and_store(BlendMode::SrcAlphaOne, U8, src, {}, kLlvmpipe)[0], byte(136));
  EXPECT_EQ(blend_and_store(BlendMode::SrcAlphaOne, U8, src, {}, kExact)[0], byte(137));
}

// SRCALPHA/INVSRCALPHA: both products rounded on their own, then added. src 0.05 → 13,
// alpha 0.5 → 128, dst 100: 13·128 = 1664 → (1664 + 6 + 128) >> 8 = 7; 100·127 = 12700 →
// (12700 + 49 + 128) >> 8 = 12877 >> 8 = 50; 7 + 50 = 57. The float blend:
// (0.05·0.5 + 100/255·0.5)·255 = 56.375 → 56.
TEST(Rgba8StoreLlvmpipe, SrcAlphaInvSrcAlphaRoundsEachProduct) {
  const Vec4 src{0.05f, 0.05f, 0.05f, 0.5f};
  const Vec4 dst{byte(100), byte(100), byte(100), byte(100)};
  const Vec4 got = blend_and_store(BlendMode::SrcAlphaInvSrcAlpha, U8, src, dst, kLlvmpipe);
  EXPECT_EQ(got[0], byte(57));
  // Alpha: 128·128 = 16384 → (16384 + 64 + 128) >> 8 = 64; 100·127 → 50; 114.
  EXPECT_EQ(got[3], byte(114));
  EXPECT_EQ(blend_and_store(BlendMode::SrcAlphaInvSrcAlpha, U8, src, dst, kExact)[0], byte(56));
}

// Other formats are not affected by the convention.
TEST(Rgba8StoreLlvmpipe, FloatFormatsFollowTheirOwnRules) {
  const Vec4 src{0.3f, 0.9f, 2.0f, -1.0f};
  EXPECT_EQ(blend_and_store(BlendMode::Replace, img::Format::RGBA32F, src, {}, kLlvmpipe), src);
  // RGBA16F under Llvmpipe rounds toward zero (NUMERICS.md rule 35): 0.3 lies in
  // [0.25, 0.5), steps of 2^-12, 0.3 · 4096 = 1228.8 → 1228 (nearest-even gives 1229).
  EXPECT_EQ(
      blend_and_store(BlendMode::Replace, img::Format::RGBA16F, {0.3f, 0, 0, 0}, {}, kLlvmpipe)[0],
      1228.0f / 4096);
  EXPECT_EQ(
      blend_and_store(BlendMode::Replace, img::Format::RGBA16F, {0.3f, 0, 0, 0}, {}, kExact)[0],
      1229.0f / 4096);
}

// cpu::draw stores with the pass's convention: 0.3 stores 76 under Llvmpipe (the default)
// and 77 under Exact.
TEST(Rgba8StoreLlvmpipe, DrawFollowsThePassConvention) {
  Pass p;
  p.constant_inputs.color[0] = {0.3f, 0.9f, 0.5f, 1.0f};
  img::Image a(2, 2, U8), b(2, 2, U8);
  ASSERT_TRUE(draw(p, a, 1).ok());
  EXPECT_EQ(a.at(1, 1)[0], byte(76));
  EXPECT_EQ(a.at(1, 1)[1], byte(230));
  p.conventions.rounding = kExact;
  ASSERT_TRUE(draw(p, b, 1).ok());
  EXPECT_EQ(b.at(1, 1)[0], byte(77));
  EXPECT_EQ(b.at(1, 1)[1], byte(229));
}

// Zeros, denormals, negatives, 1 and above, ±inf, NaN; then around every byte's value and
// every midpoint (k ± ½)/255, 64 floats either side. The special values come first: the
// draw test below reads as many probes as fill whole rows of its texture, and the tail is
// cut.
std::vector<float> store_probes() {
  std::vector<float> probe;
  const float inf = std::numeric_limits<float>::infinity();
  for (float v : {0.0f, -0.0f, 0x1p-149f, -0x1p-149f, 0x1p-127f, 0x1.fffffcp-127f, 0x1p-126f, -1.0f,
                  1.0f, 1.5f, 256.0f, 3e38f, inf, -inf, std::numeric_limits<float>::quiet_NaN(),
                  -std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::max()})
    probe.push_back(v);
  auto around = [&](float c) {
    float v = c;
    for (int i = 0; i < 64; ++i) v = std::nextafter(v, -1.0f);
    for (int i = 0; i < 129; ++i, v = std::nextafter(v, 2.0f)) probe.push_back(v);
  };
  for (int k = 0; k <= 255; ++k) {
    around(static_cast<float>(k) / 255.0f);
    around((static_cast<float>(k) + 0.5f) / 255.0f);
    around(static_cast<float>((k + 0.5) / 255.0));
  }
  return probe;
}

// The lane form of the store (rounding::unorm8_llvmpipe_lane through the levels table, the
// block store's source byte) against the scalar rule, on store_probes().
TEST(Rgba8StoreLlvmpipe, LaneFormMatchesTheRuleBitForBit) {
  const std::vector<float> probe = store_probes();
  std::vector<int32_t> bytes(probe.size());
  for (size_t i = 0; i < probe.size(); ++i) bytes[i] = rounding::unorm8_llvmpipe_lane(probe[i]);
  size_t differ = 0;
  for (size_t i = 0; i < probe.size(); ++i) {
    const float want = rounding::unorm8_levels()[rounding::unorm8_llvmpipe(probe[i])];
    // The store of Replace through the scalar path gives the same float.
    const Vec4 store =
        blend_and_store(BlendMode::Replace, U8, {probe[i], 0, 0, 0}, {0, 0, 0, 0}, kLlvmpipe);
    EXPECT_EQ(std::memcmp(&store[0], &want, sizeof(float)), 0) << probe[i];
    const float out = rounding::unorm8_levels()[static_cast<size_t>(bytes[i])];
    if (std::memcmp(&out, &want, sizeof(float)) != 0 && ++differ < 10)
      ADD_FAILURE() << std::hexfloat << probe[i] << ": lane " << out << ", rule " << want;
  }
  EXPECT_EQ(differ, 0u);
}

// The byte forms the block blend uses (rounding::unorm8_llvmpipe_lane for the source,
// unorm8_nearest_lane for the destination) against the scalar rules, on store_probes().
TEST(Rgba8StoreLlvmpipe, ByteFormsMatchTheRules) {
  const std::vector<float> probe = store_probes();
  std::vector<int32_t> src(probe.size()), dst(probe.size());
  for (size_t i = 0; i < probe.size(); ++i) {
    src[i] = rounding::unorm8_llvmpipe_lane(probe[i]);
    dst[i] = rounding::unorm8_nearest_lane(probe[i]);
  }
  for (size_t i = 0; i < probe.size(); ++i) {
    ASSERT_EQ(src[i], rounding::unorm8_llvmpipe(probe[i])) << std::hexfloat << probe[i];
    const float nearest = rounding::unorm8_nearest(probe[i]);
    ASSERT_EQ(rounding::unorm8_levels()[static_cast<size_t>(dst[i])], nearest)
        << std::hexfloat << probe[i];
  }
}

// The block executor's store of every blend mode on an RGBA8 target (bytes in lane arrays)
// against blend_and_store pixel by pixel: each pixel reads one probe as its colour from a
// texel-for-pixel texture, over a destination that holds the probes shuffled, unquantised (a
// target uploaded as is: values between the steps, NaN, values outside [0, 1]) and, second
// round, quantised to k/255.
TEST(Rgba8StoreLlvmpipe, BlockBlendMatchesThePixelRule) {
  const std::vector<float> probe = store_probes();
  const uint32_t w = 61, h = static_cast<uint32_t>(probe.size() / 4 / 61);
  auto colours = std::make_shared<img::Image>(w, h);
  std::copy(probe.begin(), probe.begin() + colours->rgba.size(), colours->rgba.begin());
  Pass pass;
  pass.vertex_program = test::parsed("vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                                     "mov oT0, v3\n");
  pass.pixel_program =
      test::parsed("ps_2_0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n");
  set_full_screen_quad(pass, 0);
  for (size_t k = 0; k < pass.vertices.size(); ++k) pass.vertices[k].v[3] = kQuadUV[k];
  pass.conventions.pixel_center = ir::PixelCenter::Modern; // pixel i reads texel i
  pass.textures[0].image = colours;
  pass.textures[0].sampler.filter = Filter::Point;
  pass.textures[0].sampler.address_u = pass.textures[0].sampler.address_v = AddressMode::Clamp;
  img::Image start(w, h, U8);
  std::vector<float> shuffled = probe;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(34));
  std::copy(shuffled.begin(), shuffled.begin() + start.rgba.size(), start.rgba.begin());
  for (int round = 0; round < 2; ++round) {
    if (round == 1) img::quantize_in_place(start);
    for (BlendMode mode : {BlendMode::Replace, BlendMode::OneOne, BlendMode::SrcAlphaOne,
                           BlendMode::SrcAlphaInvSrcAlpha}) {
      SCOPED_TRACE(static_cast<int>(mode) + 10 * round);
      pass.blend = mode;
      img::Image block = start;
      ir::Result<DrawStats> a = draw(pass, block, 2);
      ASSERT_TRUE(a.ok());
      ASSERT_GT(a->pixels_block, 0u); // the block executor ran
      size_t differ = 0;
      for (size_t px = 0; px < size_t{w} * h; ++px) {
        const float* c = &colours->rgba[4 * px];
        const float* d = &start.rgba[4 * px];
        const Vec4 want = blend_and_store(mode, U8, {c[0], c[1], c[2], c[3]},
                                          {d[0], d[1], d[2], d[3]}, kLlvmpipe);
        if (std::memcmp(&block.rgba[4 * px], want.data(), 16) != 0 && ++differ < 5)
          ADD_FAILURE() << "pixel " << px << ": " << block.rgba[4 * px] << " vs " << want[0];
      }
      EXPECT_EQ(differ, 0u);
    }
  }
}

} // namespace
} // namespace tierlift::cpu
