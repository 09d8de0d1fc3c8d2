// Texture sampling (docs/d3d9-rules.md §10.1, §10.2, §10.6): point vs bilinear on the
// documentation's worked examples, every address mode on hand-computed indices, sub-texel
// quantisation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {
namespace {

// 4×4 texture whose texel (x, y) holds R = x + 4y (distinct values), G = x, B = y, A = 1.
img::Image numbered4x4() {
  img::Image im(4, 4, img::Format::RGBA32F);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      float* p = im.at(x, y);
      p[0] = static_cast<float>(x + 4 * y);
      p[1] = static_cast<float>(x);
      p[2] = static_cast<float>(y);
      p[3] = 1;
    }
  return im;
}

SamplerState linear_clamp() {
  SamplerState s;
  s.filter = Filter::Linear;
  s.address_u = s.address_v = AddressMode::Clamp;
  return s;
}

// §10.1: bilinear at (0.5, 0.5) is the equal mix of texels (1,1), (2,1), (1,2), (2,2):
// R = (5 + 6 + 9 + 10)/4 = 7.5.
TEST(Sampling, BilinearAtCentreMixesFourCentralTexels) {
  img::Image t = numbered4x4();
  Vec4 r = sample_texture(t, linear_clamp(), 0.5f, 0.5f, 0);
  EXPECT_FLOAT_EQ(r[0], 7.5f);
  EXPECT_FLOAT_EQ(r[1], 1.5f);
  EXPECT_FLOAT_EQ(r[2], 1.5f);
  EXPECT_FLOAT_EQ(r[3], 1.0f);
}

// §10.1: bilinear at (0.375, 0.375) is exactly texel (1,1): R = 5.
TEST(Sampling, BilinearAtTexelCentreIsThatTexel) {
  img::Image t = numbered4x4();
  Vec4 r = sample_texture(t, linear_clamp(), 0.375f, 0.375f, 0);
  EXPECT_EQ(r[0], 5.0f);
  EXPECT_EQ(r[1], 1.0f);
  EXPECT_EQ(r[2], 1.0f);
}

// Point: i = floor(u·N). (0.5, 0.5) → u·N = 2 → texel (2,2), R = 10; (0.375, 0.375) →
// 1.5 → texel (1,1); just below 0.5 → texel (1,1).
TEST(Sampling, PointSampling) {
  img::Image t = numbered4x4();
  SamplerState s; // D3D9 defaults: point, wrap
  EXPECT_EQ(sample_texture(t, s, 0.5f, 0.5f, 0)[0], 10.0f);
  EXPECT_EQ(sample_texture(t, s, 0.375f, 0.375f, 0)[0], 5.0f);
  EXPECT_EQ(sample_texture(t, s, 0.4999f, 0.4999f, 0)[0], 5.0f);
}

// Indices −1, N, 2N+1 with N = 4, by the formulas of §10.2:
//   wrap:   i mod 4                        → 3, 0, 1
//   mirror: t = (i mod 8) − 4, 3 − mirror(t) → −1: t=3 → 0;  4: t=0 → 3;  9: t=−3 → 1
//   clamp:  clamp(i, 0, 3)                 → 0, 3, 3
//   border: outside [0,3]                  → border, border, border
//   mirroronce: clamp(mirror(i), 0, 3)     → 0, 3, 3
TEST(Addressing, EveryModeOnIndicesOutside) {
  struct Case {
    AddressMode mode;
    std::optional<int64_t> minus1, n, two_n_plus1;
  };
  const Case cases[] = {
      {AddressMode::Wrap, 3, 0, 1},
      {AddressMode::Mirror, 0, 3, 1},
      {AddressMode::Clamp, 0, 3, 3},
      {AddressMode::Border, std::nullopt, std::nullopt, std::nullopt},
      {AddressMode::MirrorOnce, 0, 3, 3},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(address_texel(c.mode, -1, 4), c.minus1) << static_cast<int>(c.mode);
    EXPECT_EQ(address_texel(c.mode, 4, 4), c.n) << static_cast<int>(c.mode);
    EXPECT_EQ(address_texel(c.mode, 9, 4), c.two_n_plus1) << static_cast<int>(c.mode);
    for (int64_t i = 0; i < 4; ++i) EXPECT_EQ(address_texel(c.mode, i, 4), i);
  }
  // Mirror's period: 0 1 2 3 3 2 1 0 | 0 1 …; negative side −1..−8: 0 1 2 3 3 2 1 0.
  const int64_t mirror_neg[] = {0, 1, 2, 3, 3, 2, 1, 0};
  for (int k = 1; k <= 8; ++k)
    EXPECT_EQ(address_texel(AddressMode::Mirror, -k, 4), mirror_neg[k - 1]);
}

// More edge values of the one address rule (pass::address_texel, which the CPU samplers
// and the analytic model both read), by hand for N = 4: wrap 9 → 9 − 8 = 1; mirror 5 → 2
// (period 0 1 2 3 3 2 1 0), 8 → 0 (next period); clamp far out → the edge texel; mirror-once
// −2 → 1, −7 → mirror 6 → clamped 3; a one-texel axis maps everything to 0 but for Border;
// an empty axis reads the border colour.
TEST(Addressing, OneRuleAtEdgeValues) {
  using pass::address_texel;
  EXPECT_EQ(address_texel(AddressMode::Wrap, 9, 4), 1);
  EXPECT_EQ(address_texel(AddressMode::Wrap, -4, 4), 0);
  EXPECT_EQ(address_texel(AddressMode::Wrap, -5, 4), 3);
  EXPECT_EQ(address_texel(AddressMode::Mirror, 5, 4), 2);
  EXPECT_EQ(address_texel(AddressMode::Mirror, 8, 4), 0);
  EXPECT_EQ(address_texel(AddressMode::Clamp, -6, 4), 0);
  EXPECT_EQ(address_texel(AddressMode::Clamp, 6, 4), 3);
  EXPECT_EQ(address_texel(AddressMode::Clamp, INT64_MIN / 2, 4), 0);
  EXPECT_EQ(address_texel(AddressMode::Border, 4, 4), std::nullopt);
  EXPECT_EQ(address_texel(AddressMode::Border, 3, 4), 3);
  EXPECT_EQ(address_texel(AddressMode::MirrorOnce, -2, 4), 1);
  EXPECT_EQ(address_texel(AddressMode::MirrorOnce, -7, 4), 3);
  for (AddressMode m :
       {AddressMode::Wrap, AddressMode::Mirror, AddressMode::Clamp, AddressMode::MirrorOnce})
    for (int64_t i : {-3, -1, 0, 1, 5})
      EXPECT_EQ(address_texel(m, i, 1), 0) << static_cast<int>(m) << " " << i;
  EXPECT_EQ(address_texel(AddressMode::Border, 1, 1), std::nullopt);
  EXPECT_EQ(address_texel(AddressMode::Wrap, 0, 0), std::nullopt);
}

// The same through the sampler: point sampling at the centre of texel index −1, 4, 9 on
// the u axis (row 0), R = texel x.
TEST(Addressing, ThroughThePointSampler) {
  img::Image t = numbered4x4();
  auto at_index = [](int i) { return static_cast<float>((i + 0.5) / 4.0); };
  SamplerState s;
  s.border_color = {0.25f, 0.5f, 0.75f, 1.0f};
  const std::pair<AddressMode, std::array<float, 3>> cases[] = {
      {AddressMode::Wrap, {3, 0, 1}},
      {AddressMode::Mirror, {0, 3, 1}},
      {AddressMode::Clamp, {0, 3, 3}},
      {AddressMode::Border, {0.25f, 0.25f, 0.25f}}};
  for (const auto& [mode, want] : cases) {
    s.address_u = mode;
    s.address_v = AddressMode::Clamp;
    int k = 0;
    for (int i : {-1, 4, 9}) {
      Vec4 r = sample_texture(t, s, at_index(i), 0.125f, 0);
      EXPECT_EQ(r[0], want[k++]) << "mode " << static_cast<int>(mode) << " index " << i;
    }
  }
}

// Bilinear next to the border blends the border colour in: at u = 0 (x = −0.5) texels −1
// and 0 are mixed half and half: (border 0.25 + texel 0 (R=0)) / 2 on row 0 centre.
TEST(Addressing, BilinearBlendsBorderColour) {
  img::Image t = numbered4x4();
  SamplerState s = linear_clamp();
  s.address_u = AddressMode::Border;
  s.border_color = {0.25f, 0, 0, 0};
  Vec4 r = sample_texture(t, s, 0.0f, 0.125f, 0);
  EXPECT_FLOAT_EQ(r[0], 0.125f);
  EXPECT_FLOAT_EQ(r[3], 0.5f);
}

// 2×1 texture (0 | 1), clamp: bilinear at u gives α = frac(2u − 0.5). u = 0.4 gives
// α = 0.3000000119 exactly (float 0.4 times 2), which 8 sub-texel bits round to
// round(76.80000305) / 256 = 77/256 = 0.30078125; with 0 bits it stays 0.3000000119.
TEST(Sampling, SubTexelQuantisation) {
  img::Image t(2, 1, img::Format::RGBA32F);
  t.at(1, 0)[0] = 1;
  SamplerState s = linear_clamp();
  EXPECT_NEAR(sample_texture(t, s, 0.4f, 0.5f, 0)[0], 0.3000000119, 1e-7);
  EXPECT_EQ(sample_texture(t, s, 0.4f, 0.5f, 8)[0], 77.0f / 256.0f);
  EXPECT_EQ(sample_texture(t, s, 0.4f, 0.5f, 4)[0], 5.0f / 16.0f); // round(4.8) = 5
  EXPECT_EQ(quantize_fraction(0.3, 1), 0.5);
  EXPECT_EQ(quantize_fraction(0.2, 1), 0.0);
  EXPECT_EQ(quantize_fraction(0.99, 2), 1.0); // rounds up to the next texel: weight 1
}

TEST(Sampling, UnboundStageReadsOpaqueBlack) {
  std::array<TextureBinding, kMaxSamplers> none{};
  BoundTextures unit(none, 0);
  Vec4 r = unit.sample(3, {0.5f, 0.5f, 0, 1}, 0);
  EXPECT_EQ(r, (Vec4{0, 0, 0, 1}));
  EXPECT_EQ(unit.sample(999, {0.5f, 0.5f, 0, 1}, 0), (Vec4{0, 0, 0, 1}));
}

// Coordinates no texture holds: texel_space turns NaN into 0 and clamps u·N to ±2^40 (far
// outside any address-mode period, so the index conversion is defined). With u = v every
// result sits on the diagonal, so R = 5·G and B = G (numbered4x4); G is computed by hand:
//   point:  i = floor(u·N): NaN → 0; +inf, 3e38 → 2^40; 1e9 → 4e9; −inf, −3e38 → −2^40.
//           Wrap: every one ≡ 0 (mod 4) → 0. Mirror: ≡ 0 (mod 8), or −2^40 → t = −4 → 0.
//           Clamp: 0 / 3 / 0. MirrorOnce: 0 for NaN, else beyond the texture → 3.
//   linear: x = u·N − ½ straddles texels i0, i0 + 1 with weight ½: NaN → (−1, 0); +big →
//           (k − 1, k), k ≡ 0 (mod 8); −big → (−2^40 − 1, −2^40). Wrap: columns 3 and 0
//           → 1.5. Mirror: both map to 0. Clamp: 0 / 3 / 0. MirrorOnce: NaN → 0, else 3.
//   Border (transparent black): any index outside is the border; NaN's linear tap keeps
//   texel (0, 0) with weight ¼ (A = ¼), point keeps texel (0, 0); every other one is border.
TEST(Sampling, ExtremeCoordinatesFollowTheAddressRules) {
  img::Image t = numbered4x4();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float coords[] = {nan, inf, -inf, 3e38f, -3e38f, 1e9f};
  struct Row {
    AddressMode mode;
    Filter filter;
    float g[6]; // G for each of `coords`; -1: the border colour
  };
  const Row rows[] = {
      {AddressMode::Wrap, Filter::Point, {0, 0, 0, 0, 0, 0}},
      {AddressMode::Mirror, Filter::Point, {0, 0, 0, 0, 0, 0}},
      {AddressMode::Clamp, Filter::Point, {0, 3, 0, 3, 0, 3}},
      {AddressMode::Border, Filter::Point, {0, -1, -1, -1, -1, -1}},
      {AddressMode::MirrorOnce, Filter::Point, {0, 3, 3, 3, 3, 3}},
      {AddressMode::Wrap, Filter::Linear, {1.5f, 1.5f, 1.5f, 1.5f, 1.5f, 1.5f}},
      {AddressMode::Mirror, Filter::Linear, {0, 0, 0, 0, 0, 0}},
      {AddressMode::Clamp, Filter::Linear, {0, 3, 0, 3, 0, 3}},
      {AddressMode::Border, Filter::Linear, {0, -1, -1, -1, -1, -1}},
      {AddressMode::MirrorOnce, Filter::Linear, {0, 3, 3, 3, 3, 3}},
  };
  for (const Row& row : rows) {
    SamplerState s;
    s.filter = row.filter;
    s.address_u = s.address_v = row.mode;
    for (int k = 0; k < 6; ++k) {
      SCOPED_TRACE("mode " + std::to_string(static_cast<int>(row.mode)) + ", filter " +
                   std::to_string(static_cast<int>(row.filter)) +
                   ", u = v = " + std::to_string(coords[k]));
      Vec4 r = sample_texture(t, s, coords[k], coords[k], 8);
      if (row.g[k] < 0) {
        EXPECT_EQ(r, (Vec4{0, 0, 0, 0}));
        continue;
      }
      const bool border_nan_linear =
          row.mode == AddressMode::Border && row.filter == Filter::Linear;
      const float a = border_nan_linear ? 0.25f : 1.0f;
      EXPECT_EQ(r[0], 5 * row.g[k]);
      EXPECT_EQ(r[1], row.g[k]);
      EXPECT_EQ(r[2], row.g[k]);
      EXPECT_EQ(r[3], a);
    }
  }
}

} // namespace
} // namespace tierlift::cpu
