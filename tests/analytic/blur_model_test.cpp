// The analytic model on tiny images, every expected value computed by hand.
#include <gtest/gtest.h>

#include "corner_model.h"
#include "tierlift/analytic/blur_model.h"

namespace img = tierlift::img;
namespace analytic = tierlift::analytic;
using tierlift::ir::PixelCenter;

namespace {

// One row of four texels 1, 2, 4, 8 (all channels; alpha too, to see it is filtered alike).
img::Image row4() {
  img::Image im(4, 1);
  const float v[4] = {1, 2, 4, 8};
  for (uint32_t x = 0; x < 4; ++x)
    for (int c = 0; c < 4; ++c) im.at(x, 0)[c] = v[x];
  return im;
}

analytic::Tap tap(double du, double dv, double w) {
  analytic::Tap t;
  t.offset = {du, dv};
  t.weight = {w, w, w, w};
  return t;
}

std::vector<float> red_row(const img::Image& im) {
  std::vector<float> out;
  for (uint32_t x = 0; x < im.width; ++x) out.push_back(im.at(x, 0)[0]);
  return out;
}

} // namespace

TEST(BlurModel, HalfTexelOffsetsHitTexelCentres) {
  // D3D9: u = i/4; + 0.5/4 lands on texel i, + 1.5/4 on texel i + 1 (clamped at the edge).
  std::vector<analytic::Tap> taps = {tap(0.5 / 4, 0.5, 0.5), tap(1.5 / 4, 0.5, 0.25)};
  analytic::PassModel m;
  auto r = analytic::blur_pass(taps, row4(), m);
  ASSERT_TRUE(r) << r.message();
  EXPECT_EQ(red_row(*r), (std::vector<float>{1.0f, 2.0f, 4.0f, 6.0f}));
  EXPECT_EQ(r->at(3, 0)[3], 6.0f);
  // The same taps as whole texels 0 and 1 give the same plain convolution.
  auto texel_taps = tierlift::test::intended_texel_taps(taps, 4, 1);
  ASSERT_EQ(texel_taps.size(), 2u);
  EXPECT_EQ(texel_taps[0].dx, 0);
  EXPECT_EQ(texel_taps[1].dx, 1);
  EXPECT_EQ(texel_taps[0].dy, 0);
  auto conv = tierlift::test::discrete_convolution(texel_taps, row4(), m);
  ASSERT_TRUE(conv) << conv.message();
  EXPECT_EQ(red_row(*conv), red_row(*r));
}

TEST(BlurModel, WithoutHalfTexelBilinearWeightsAreHalfAndHalf) {
  // D3D9, offset 0: u·4 − 0.5 = i − 0.5, so each pixel mixes texels i−1 and i equally;
  // v = 0 likewise mixes rows −1 and 0, both row 0 under clamp.
  std::vector<analytic::Tap> taps = {tap(0, 0, 1.0)};
  analytic::PassModel m;
  auto r = analytic::blur_pass(taps, row4(), m);
  ASSERT_TRUE(r) << r.message();
  EXPECT_EQ(red_row(*r), (std::vector<float>{1.0f, 1.5f, 3.0f, 6.0f}));
  // The corner model says the same from its own rule.
  auto corner = tierlift::test::corner_model(taps, row4(), m);
  ASSERT_TRUE(corner) << corner.message();
  EXPECT_EQ(red_row(*corner), red_row(*r));
  // And predicts the difference from the plain convolution (texel i): 0, -0.5, -1, -2.
  auto p = tierlift::test::predict_corner_difference(taps, row4(), m);
  ASSERT_TRUE(p);
  EXPECT_EQ(red_row(p->difference), (std::vector<float>{0.0f, -0.5f, -1.0f, -2.0f}));
  EXPECT_DOUBLE_EQ(p->max_abs, 2.0);
  // Wrap addressing: pixel 0 mixes texel 3 and texel 0.
  m.sampler.address_u = analytic::AddressMode::Wrap;
  auto wrapped = analytic::blur_pass(taps, row4(), m);
  ASSERT_TRUE(wrapped);
  EXPECT_EQ(wrapped->at(0, 0)[0], 4.5f);
  // Modern pixel centres put u at the texel centre: the plain texels come back.
  m.sampler.address_u = analytic::AddressMode::Clamp;
  m.conventions.pixel_center = PixelCenter::Modern;
  auto modern = analytic::blur_pass(taps, row4(), m);
  ASSERT_TRUE(modern);
  EXPECT_EQ(red_row(*modern), (std::vector<float>{1.0f, 2.0f, 4.0f, 8.0f}));
}

TEST(BlurModel, PointFilterAndSubtexelBits) {
  analytic::PassModel m;
  m.sampler.filter = analytic::Filter::Point;
  auto point = analytic::blur_pass({tap(0, 0, 1.0)}, row4(), m);
  ASSERT_TRUE(point);
  // floor(u·4) = floor(i) = i.
  EXPECT_EQ(red_row(*point), (std::vector<float>{1.0f, 2.0f, 4.0f, 8.0f}));
  // Linear, pixel 1, offset 0.3 texel: p = 1 − 0.5 + 0.3 = 0.8 → 0.2·T0 + 0.8·T1.
  m.sampler.filter = analytic::Filter::Linear;
  std::vector<analytic::Tap> taps = {tap(0.3 / 4, 0.5, 1.0)};
  auto exact = analytic::blur_pass(taps, row4(), m);
  ASSERT_TRUE(exact);
  EXPECT_NEAR(exact->at(1, 0)[0], 0.2 * 1 + 0.8 * 2, 1e-6);
  m.conventions.subtexel_bits = 2; // α = round(0.8·4)/4 = 0.75
  auto two = analytic::blur_pass(taps, row4(), m);
  EXPECT_EQ(two->at(1, 0)[0], 1.75f);
  m.conventions.subtexel_bits = 1; // α = round(1.6)/2 = 1: texel 1 alone
  auto one = analytic::blur_pass(taps, row4(), m);
  EXPECT_EQ(one->at(1, 0)[0], 2.0f);
}

TEST(BlurModel, StoreQuantisesToTheTargetFormat) {
  img::Image src(2, 1);
  for (float& v : src.rgba) v = 0.5f;
  analytic::PassModel m;
  m.target_format = img::Format::RGBA8;
  auto r = analytic::blur_pass({tap(0.25, 0.5, 1.0)}, src, m);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->format, img::Format::RGBA8);
  EXPECT_EQ(r->at(0, 0)[0], static_cast<float>(128 / 255.0));
  m.target_format = img::Format::RGBA16F;
  auto h = analytic::blur_pass({tap(0.25, 0.5, 0.1)}, src, m);
  // 0.05 = 1.6·2^-5: half spacing 2^-15, 0.05/2^-15 = 1638.4 → 1638·2^-15.
  EXPECT_EQ(h->at(1, 0)[0], 0.04998779296875f);
}

TEST(BlurModel, BilinearMatchesTheFactSheetExamples) {
  // docs/d3d9-rules.md §10.1 on a 4×4 texture: (0.5, 0.5) = mean of the 4 central texels,
  // (0.375, 0.375) = texel (1, 1).
  img::Image t(4, 4);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) t.at(x, y)[0] = static_cast<float>(10 * y + x);
  analytic::SamplerModel s;
  EXPECT_DOUBLE_EQ(analytic::sample(t, 0.5, 0.5, s)[0], (11 + 12 + 21 + 22) / 4.0);
  EXPECT_DOUBLE_EQ(analytic::sample(t, 0.375, 0.375, s)[0], 11.0);
  s.address_u = s.address_v = analytic::AddressMode::Border;
  s.border = {100, 0, 0, 0};
  EXPECT_DOUBLE_EQ(analytic::sample(t, 0.0, 0.125, s)[0], (100 + 0) / 2.0);
}

TEST(BlurModel, IntendedTexelsOfBothOffsetStyles) {
  const uint32_t w = 64;
  std::vector<analytic::Tap> taps = {tap(-3.5 / w, 0, 1), tap(-4.0 / w, 0, 1), tap(2.5 / w, 0, 1),
                                     tap(2.0 / w, 0, 1)};
  auto t = tierlift::test::intended_texel_taps(taps, w, 1);
  EXPECT_EQ(t[0].dx, -4);
  EXPECT_EQ(t[1].dx, -4);
  EXPECT_EQ(t[2].dx, 2);
  EXPECT_EQ(t[3].dx, 2);
}

TEST(BlurModel, CornerModelRejectsOtherPositionsAndSizes) {
  auto r = tierlift::test::corner_model({tap(0.3 / 4, 0.5, 1.0)}, row4(), analytic::PassModel{});
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("neither"), std::string::npos) << r.message();
  analytic::PassModel half;
  half.target_width = 2;
  EXPECT_FALSE(tierlift::test::corner_model({tap(0, 0, 1)}, row4(), half));
  EXPECT_FALSE(tierlift::test::discrete_convolution({}, row4(), half));
  EXPECT_TRUE(analytic::blur_pass({tap(0, 0, 1)}, row4(), half));
  EXPECT_FALSE(analytic::blur_pass({}, img::Image(), analytic::PassModel{}));
}

TEST(BlurModel, DownsampleToHalfSizeByHand) {
  // 4 texels → 2 pixels, D3D9: pixel i at u = i/2, p = u·4 − 0.5 = 2i − 0.5: texels 2i−1
  // and 2i, half and half (clamped at the left edge).
  analytic::PassModel m;
  m.target_width = 2;
  auto plain = analytic::blur_pass({tap(0, 0.5, 1.0)}, row4(), m);
  ASSERT_TRUE(plain) << plain.message();
  EXPECT_EQ(red_row(*plain), (std::vector<float>{1.0f, 3.0f}));
  // Offset by one source texel (1/4): p = 2i + 0.5, the proper 2-texel box: 1.5 and 6.
  auto box = analytic::blur_pass({tap(0.25, 0.5, 1.0)}, row4(), m);
  ASSERT_TRUE(box);
  EXPECT_EQ(red_row(*box), (std::vector<float>{1.5f, 6.0f}));
}
