// analytic::linear_pass and mask_by_alpha_pass on tiny images (4×1, 2×1, 2×2, 1×1), every
// expected value computed by hand in the comments: scaled and offset coordinates
// (downsampling, upsampling), two sampler stages, ONE/ONE blending, the ps_1_x range rule,
// the store rule, and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "tierlift/analytic/linear_pass.h"

namespace img = tierlift::img;
namespace analytic = tierlift::analytic;

namespace {

// A w×1 image whose R channel is `r`; G = R / 2, B = 0, A = 1.
img::Image row(std::vector<float> r, img::Format f = img::Format::RGBA32F) {
  img::Image im(static_cast<uint32_t>(r.size()), 1, f);
  for (uint32_t x = 0; x < im.width; ++x) {
    float* p = im.at(x, 0);
    p[0] = r[x], p[1] = r[x] / 2, p[2] = 0, p[3] = 1;
  }
  return im;
}

std::vector<float> red(const img::Image& im) {
  std::vector<float> out;
  for (uint32_t j = 0; j < im.height; ++j)
    for (uint32_t i = 0; i < im.width; ++i) out.push_back(im.at(i, j)[0]);
  return out;
}

analytic::Tap tap(uint32_t stage, double du, double dv, double w, double su = 1, double sv = 1) {
  analytic::Tap t;
  t.texcoord = stage;
  t.sampler = stage;
  t.offset = {du, dv};
  t.scale = {su, sv};
  t.weight = {w, w, w, w};
  return t;
}

analytic::SamplerModel sampler(analytic::Filter f) {
  analytic::SamplerModel s;
  s.filter = f;
  return s; // clamp addressing
}

analytic::LinearPassInput input(uint32_t w, uint32_t h, const img::Image& tex0,
                                analytic::Filter f = analytic::Filter::Linear) {
  analytic::LinearPassInput in;
  in.textures.push_back({0, &tex0, sampler(f)});
  in.model.target_width = w;
  in.model.target_height = h;
  return in;
}

} // namespace

// Downsampling a 4×1 row to 2×1: D3D9 centres give u = i/2; with offset 1/4 the read lies at
// texel-space (i/2 + 1/4)·4 − 0.5 = 2i + 0.5, the midpoint of texels 2i and 2i + 1.
TEST(LinearPass, DownsampleReadsMidpoints) {
  const img::Image src = row({0.0f, 0.25f, 0.5f, 1.0f});
  auto r = analytic::linear_pass({tap(0, 0.25, 0.5, 1.0)}, input(2, 1, src));
  ASSERT_TRUE(r) << r.message();
  EXPECT_EQ(red(*r), (std::vector<float>{0.125f, 0.75f}));
  EXPECT_EQ(r->at(1, 0)[1], 0.375f); // G = R / 2 filtered alike
  EXPECT_EQ(r->at(0, 0)[3], 1.0f);
}

// Upsampling a 2×1 row [0, 1] to 4×1. Scale 1, offset 0: x = (i/4)·2 − 0.5 = i/2 − 0.5:
// −0.5 (clamp: 0), 0 (texel 0), 0.5 (half way), 1 (texel 1) → 0, 0, 0.5, 1.
// Offset 1/8: x = i/2 − 0.25 → 0, 0.25, 0.75, 1 (1.25 mixes texel 1 with itself).
TEST(LinearPass, UpsampleFollowsBilinearWeights) {
  const img::Image src = row({0.0f, 1.0f});
  auto a = analytic::linear_pass({tap(0, 0, 0.5, 1.0)}, input(4, 1, src));
  ASSERT_TRUE(a) << a.message();
  EXPECT_EQ(red(*a), (std::vector<float>{0.0f, 0.0f, 0.5f, 1.0f}));
  auto b = analytic::linear_pass({tap(0, 0.125, 0.5, 1.0)}, input(4, 1, src));
  ASSERT_TRUE(b) << b.message();
  EXPECT_EQ(red(*b), (std::vector<float>{0.0f, 0.25f, 0.75f, 1.0f}));
}

// The scale: target 2×1 over a 4×1 texture with scale 2 and offset 1/8 reads
// x = (2·i/2 + 1/8)·4 − 0.5 = 4i: texel 0 for i = 0 and texel 4 → clamped 3 for i = 1.
// Modern centres: u = (i + ½)/2, x = (2(i + ½)/2 + 1/8)·4 − 0.5 = 4i + 2: texel 2, then 6 → 3.
TEST(LinearPass, ScaleMultipliesTheQuadUv) {
  const img::Image src = row({0.25f, 0.5f, 0.75f, 1.0f});
  auto in = input(2, 1, src);
  auto d3d9 = analytic::linear_pass({tap(0, 0.125, 0.5, 1.0, 2.0, 1.0)}, in);
  ASSERT_TRUE(d3d9) << d3d9.message();
  EXPECT_EQ(red(*d3d9), (std::vector<float>{0.25f, 1.0f}));
  in.model.conventions.pixel_center = tierlift::ir::PixelCenter::Modern;
  auto modern = analytic::linear_pass({tap(0, 0.125, 0.5, 1.0, 2.0, 1.0)}, in);
  ASSERT_TRUE(modern) << modern.message();
  EXPECT_EQ(red(*modern), (std::vector<float>{0.75f, 1.0f}));
}

// Two stages, as the composite: out.rgb = A + 0.5·B, out.a = A.a. A is 2×2 point-sampled at
// its centres (offset ¼); B is 1×1 = (0.5, 0.25, 0, 1) read bilinearly (one texel: itself).
TEST(LinearPass, TwoStagesAreSummed) {
  img::Image a(2, 2);
  const float av[4] = {0.0f, 0.125f, 0.25f, 0.5f}; // (0,0), (1,0), (0,1), (1,1)
  for (uint32_t k = 0; k < 4; ++k) {
    float* p = a.at(k % 2, k / 2);
    p[0] = av[k], p[1] = 0, p[2] = av[k], p[3] = 0.5f;
  }
  img::Image b(1, 1);
  b.rgba = {0.5f, 0.25f, 0.0f, 1.0f};
  analytic::LinearPassInput in;
  in.textures.push_back({0, &a, sampler(analytic::Filter::Point)});
  in.textures.push_back({1, &b, sampler(analytic::Filter::Linear)});
  in.model.target_width = in.model.target_height = 2;
  analytic::Tap t1 = tap(1, 0.3, 0.7, 0.5);
  t1.weight[3] = 0;
  auto r = analytic::linear_pass({tap(0, 0.25, 0.25, 1.0), t1}, in);
  ASSERT_TRUE(r) << r.message();
  for (uint32_t k = 0; k < 4; ++k) {
    const float* p = r->at(k % 2, k / 2);
    EXPECT_EQ(p[0], av[k] + 0.25f) << k;
    EXPECT_EQ(p[1], 0.125f) << k;
    EXPECT_EQ(p[2], av[k]) << k;
    EXPECT_EQ(p[3], 0.5f) << k;
  }
  // A tap on an unbound stage reads (0, 0, 0, 1), and a note says so.
  std::vector<std::string> notes;
  auto u = analytic::linear_pass({tap(0, 0.25, 0.25, 1.0), tap(5, 0, 0, 0.25)}, in, &notes);
  ASSERT_TRUE(u) << u.message();
  EXPECT_EQ(u->at(1, 1)[0], 0.5f);
  EXPECT_EQ(u->at(1, 1)[3], 0.75f); // 0.5 + 0.25·1
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("unbound"), std::string::npos);
}

// ONE/ONE: dst + src. RGBA32F: exact sums. RGBA8: the source clamps to [0, 1] before the
// add, the sum clamps at 1 in the store, and values round to 1/255 steps.
TEST(LinearPass, OneOneAddsToTheDestination) {
  const img::Image src = row({0.25f, 0.5f, -0.5f, 2.0f});
  auto in = input(4, 1, src, analytic::Filter::Point);
  const img::Image dst = row({0.5f, 0.75f, 0.5f, 0.0f});
  in.blend = analytic::Blend::OneOne;
  in.destination = &dst;
  // Point read at texel centres: offset 1/8.
  auto f32 = analytic::linear_pass({tap(0, 0.125, 0.5, 1.0)}, in);
  ASSERT_TRUE(f32) << f32.message();
  EXPECT_EQ(red(*f32), (std::vector<float>{0.75f, 1.25f, 0.0f, 2.0f}));
  EXPECT_EQ(f32->at(0, 0)[3], 2.0f); // alpha 1 + 1

  // RGBA8: dst = 51/255 (0.2), src 0.31 → 0.51·255 = 130.05 → 130; src −0.5 → 0 (not −0.3);
  // src 2 → 1; src 0.5 onto 0.75 → 1 (clamped store).
  const img::Image src8 = row({0.31f, -0.5f, 2.0f, 0.5f});
  const img::Image dst8 = row({51 / 255.0f, 0.2f, 0.0f, 0.75f}, img::Format::RGBA8);
  auto in8 = input(4, 1, src8, analytic::Filter::Point);
  in8.model.target_format = img::Format::RGBA8;
  in8.blend = analytic::Blend::OneOne;
  in8.destination = &dst8;
  auto u8 = analytic::linear_pass({tap(0, 0.125, 0.5, 1.0)}, in8);
  ASSERT_TRUE(u8) << u8.message();
  EXPECT_EQ(u8->format, img::Format::RGBA8);
  EXPECT_EQ(red(*u8), (std::vector<float>{130 / 255.0f, 0.2f, 1.0f, 1.0f}));
  // Replace on RGBA8 stores round(0.31·255 = 79.05) = 79.
  in8.blend = analytic::Blend::Replace;
  auto r8 = analytic::linear_pass({tap(0, 0.125, 0.5, 1.0)}, in8);
  ASSERT_TRUE(r8) << r8.message();
  EXPECT_EQ(r8->at(0, 0)[0], 79 / 255.0f);
}

// ps_1_x: each sample clamps to [−1, 1] (a t# write), and so does the sum (r0).
// Texel values 1.5 and 0.75: taps 0.5·t0 + 0.75·t1 with t0 = texel 0, t1 = texel 1.
// Without the rule: 0.75 + 0.5625 = 1.3125. With it: 0.5·1 + 0.5625 = 1.0625 → 1.
// Weights 0.25 each: 0.25·1 + 0.1875 = 0.4375 (the sample clamp alone shows).
TEST(LinearPass, Ps1xClampsSamplesAndTheSum) {
  const img::Image src = row({1.5f, 0.75f});
  auto in = input(1, 1, src, analytic::Filter::Point);
  in.textures.push_back({1, &src, sampler(analytic::Filter::Point)});
  const std::vector<analytic::Tap> taps = {tap(0, 0.25, 0.5, 0.5), tap(1, 0.75, 0.5, 0.75)};
  auto plain = analytic::linear_pass(taps, in);
  ASSERT_TRUE(plain) << plain.message();
  EXPECT_EQ(plain->at(0, 0)[0], 1.3125f);
  in.ps1x_clamp = true;
  in.model.conventions.ps1x_max_value = 1.0f; // geforce3's range, the clamps shown above
  std::vector<std::string> notes;
  auto clamped = analytic::linear_pass(taps, in, &notes);
  ASSERT_TRUE(clamped) << clamped.message();
  EXPECT_EQ(clamped->at(0, 0)[0], 1.0f);
  EXPECT_EQ(clamped->at(0, 0)[1], 0.65625f); // G: 0.5·0.75 + 0.75·0.375
  EXPECT_EQ(clamped->at(0, 0)[3], 1.0f);     // 0.5 + 0.75 = 1.25 → 1
  const std::vector<analytic::Tap> quarter = {tap(0, 0.25, 0.5, 0.25), tap(1, 0.75, 0.5, 0.25)};
  auto q = analytic::linear_pass(quarter, in);
  ASSERT_TRUE(q) << q.message();
  EXPECT_EQ(q->at(0, 0)[0], 0.4375f);
  // No note about negative weights here; one when a weight is negative.
  for (const auto& n : notes) EXPECT_EQ(n.find("negative"), std::string::npos) << n;
  std::vector<std::string> neg_notes;
  auto neg =
      analytic::linear_pass({tap(0, 0.25, 0.5, 1.0), tap(1, 0.75, 0.5, -0.5)}, in, &neg_notes);
  ASSERT_TRUE(neg) << neg.message();
  EXPECT_EQ(neg->at(0, 0)[0], 0.625f); // 1 − 0.5·0.75
  bool said = false;
  for (const auto& n : neg_notes) said |= n.find("weight is negative") != std::string::npos;
  EXPECT_TRUE(said);
}

// rgb × alpha of one read: (0.75, 0.5, 0.25, 0.5) → (0.375, 0.25, 0.125, 0.5).
TEST(LinearPass, MaskByAlpha) {
  img::Image src(2, 1);
  src.rgba = {0.75f, 0.5f, 0.25f, 0.5f, 1.0f, 1.0f, 1.0f, 0.0f};
  auto in = input(2, 1, src, analytic::Filter::Point);
  auto r = analytic::mask_by_alpha_pass(tap(0, 0.25, 0.5, 0.0), in);
  ASSERT_TRUE(r) << r.message();
  EXPECT_EQ(r->rgba, (std::vector<float>{0.375f, 0.25f, 0.125f, 0.5f, 0.0f, 0.0f, 0.0f, 0.0f}));
  // ps_1_x: a sample of 2 clamps to 1 first: (2, 2, 2, 0.5) → (0.5, 0.5, 0.5, 0.5).
  src.rgba = {2.0f, 2.0f, 2.0f, 0.5f, 0, 0, 0, 0};
  in.ps1x_clamp = true;
  in.model.conventions.ps1x_max_value = 1.0f; // geforce3's range
  auto c = analytic::mask_by_alpha_pass(tap(0, 0.25, 0.5, 0.0), in);
  ASSERT_TRUE(c) << c.message();
  EXPECT_EQ(c->at(0, 0)[0], 0.5f);
}

TEST(LinearPass, BadInputIsAnError) {
  const img::Image src = row({0.5f});
  auto in = input(0, 1, src);
  auto r = analytic::linear_pass({tap(0, 0, 0, 1)}, in);
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("target 0x1"), std::string::npos) << r.message();
  in = input(1, 1, src);
  in.blend = analytic::Blend::OneOne;
  r = analytic::linear_pass({tap(0, 0, 0, 1)}, in);
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("destination"), std::string::npos) << r.message();
  in = input(1, 1, src);
  in.textures.push_back({0, &src, {}});
  r = analytic::linear_pass({tap(0, 0, 0, 1)}, in);
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("bound twice"), std::string::npos) << r.message();
  in = input(1, 1, src);
  in.textures[0].image = nullptr;
  EXPECT_FALSE(analytic::mask_by_alpha_pass(tap(0, 0, 0, 1), in));
  // A huge offset stays finite (no UB): it reads the clamped edge.
  in = input(1, 1, src);
  auto far = analytic::linear_pass({tap(0, 1e300, -1e300, 1)}, in);
  ASSERT_TRUE(far) << far.message();
  EXPECT_EQ(far->at(0, 0)[0], 0.5f);
}

// RGBA8 stores from exact values: midpoints go by the tie rule (within 1e-9 of a step, so a
// double sum that should be a midpoint still is), everything else to the nearest step.
TEST(StoreValue, Rgba8MidpointsFollowTheTieRule) {
  using analytic::Unorm8Ties;
  const auto u8 = img::Format::RGBA8;
  EXPECT_EQ(analytic::store_value(u8, 127.5 / 255, Unorm8Ties::ToEven), 128 / 255.0f);
  EXPECT_EQ(analytic::store_value(u8, 126.5 / 255, Unorm8Ties::ToEven), 126 / 255.0f);
  EXPECT_EQ(analytic::store_value(u8, 126.5 / 255, Unorm8Ties::HalfUp), 127 / 255.0f);
  // 0.3 · 255 = 76.5 exactly, but 0.3 is no double: still a midpoint.
  EXPECT_EQ(analytic::store_value(u8, 0.3, Unorm8Ties::ToEven), 76 / 255.0f);
  EXPECT_EQ(analytic::store_value(u8, 0.3, Unorm8Ties::HalfUp), 77 / 255.0f);
  EXPECT_EQ(analytic::store_value(u8, 126.4999 / 255, Unorm8Ties::HalfUp), 126 / 255.0f);
  EXPECT_EQ(analytic::store_value(u8, -2.0, Unorm8Ties::ToEven), 0.0f);
  EXPECT_EQ(analytic::store_value(u8, std::nan(""), Unorm8Ties::ToEven), 0.0f);
  EXPECT_EQ(analytic::store_value(u8, 7.0, Unorm8Ties::ToEven), 1.0f);
  EXPECT_EQ(analytic::store_value(img::Format::RGBA32F, 1e300, Unorm8Ties::ToEven), INFINITY);
  EXPECT_EQ(analytic::store_value(img::Format::RGBA32F, 0.25, Unorm8Ties::ToEven), 0.25f);
}

// An RGBA8 texel holds k/255 exactly (its float is only the nearest float to that).
TEST(StoreValue, Rgba8TexelsAreExactSteps) {
  img::Image im(1, 1, img::Format::RGBA8);
  im.rgba = {1 / 255.0f, 254 / 255.0f, 0.0f, 1.0f};
  EXPECT_EQ(analytic::texel_value(im, 0, 0, 0), 1 / 255.0);
  EXPECT_EQ(analytic::texel_value(im, 0, 0, 1), 254 / 255.0);
  EXPECT_NE(double(1 / 255.0f), 1 / 255.0); // the float alone is not the step
  im.format = img::Format::RGBA32F;
  EXPECT_EQ(analytic::texel_value(im, 0, 0, 0), double(1 / 255.0f));
}

// A bilinear read 1e-7 texel off a midpoint (float constants) reads the midpoint exactly;
// one 0.01 texel off does not (N = 64: the snap is 64 · 2^-21 ≈ 3e-5 texel).
TEST(StoreValue, ReadsNearAMidpointAreSnapped) {
  img::Image im(64, 1);
  for (uint32_t x = 0; x < 64; ++x) im.at(x, 0)[0] = float(x % 2);
  analytic::SamplerModel s; // bilinear, clamp
  // Texel-space x = u·64 − 0.5 = 10.5 ± δ: half of texel 10 (0) and half of texel 11 (1).
  EXPECT_EQ(analytic::sample(im, (11.0 + 1e-7) / 64, 0.5, s)[0], 0.5);
  EXPECT_EQ(analytic::sample(im, (11.0 - 1e-7) / 64, 0.5, s)[0], 0.5);
  EXPECT_NEAR(analytic::sample(im, (11.0 + 0.01) / 64, 0.5, s)[0], 0.51, 1e-12); // 0.51 of texel 11
  EXPECT_NEAR(analytic::snap_tolerance(64), 64.0 / 2097152, 1e-18);
}
