// sRGB reads and writes on both devices (NUMERICS.md S1–S3): SRGBTEXTURE decodes an RGBA8
// texture's colour before filtering, SRGBWRITEENABLE encodes the output before the blender,
// and the interpreter and lavapipe agree bit for bit, with the values the closed form gives.
#include <cmath>
#include <limits>

#include "tierlift/rounding/rounding.h"
#include "vk_test_util.h"

namespace tierlift::vulkan::test {
namespace {

// A pass over the full-screen quad that samples s0 at the quad's uv and writes it to oC0.
cpu::Pass sampling_pass(std::shared_ptr<const img::Image> tex, cpu::Filter filter) {
  cpu::Pass p;
  p.vertex_program = parse_listing(
      "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n", "srgb.vsh");
  p.pixel_program =
      parse_listing("ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n", "srgb.psh");
  p.textures[0].image = std::move(tex);
  p.textures[0].sampler.filter = filter;
  p.textures[0].sampler.address_u = p.textures[0].sampler.address_v = cpu::AddressMode::Clamp;
  p.textures[0].sampler.srgb = true;
  cpu::set_full_screen_quad(p, 0);
  for (size_t k = 0; k < p.vertices.size(); ++k) p.vertices[k].v[3] = cpu::kQuadUV[k];
  p.conventions.pixel_center = ir::PixelCenter::Modern; // pixel i reads texel i
  return p;
}

// Every byte 0..255 read point-sampled through an sRGB stage: red and blue decode, alpha does
// not; both devices give the closed form's level for every byte.
TEST_F(VulkanTest, SrgbTextureDecodesAll256Levels) {
  auto tex = std::make_shared<img::Image>(256, 1, img::Format::RGBA8);
  for (int k = 0; k < 256; ++k) {
    float* t = tex->at(static_cast<uint32_t>(k), 0);
    t[0] = t[3] = static_cast<float>(k) / 255.0f;
    t[1] = static_cast<float>(255 - k) / 255.0f;
    t[2] = static_cast<float>(k) / 255.0f;
  }
  const TwoWays t =
      draw_both(*dev, sampling_pass(tex, cpu::Filter::Point), 256, 1, img::Format::RGBA32F);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.cmp.identical_share, 1.0);
  const std::array<float, 256>& levels = rounding::srgb_decode_levels();
  for (int k = 0; k < 256; ++k) {
    for (const img::Image* im : {&t.cpu, &t.vk}) {
      const float* v = im->at(static_cast<uint32_t>(k), 0);
      EXPECT_EQ(v[0], levels[k]) << k;
      EXPECT_EQ(v[1], levels[255 - k]) << k;
      EXPECT_EQ(v[3], static_cast<float>(k) / 255.0f) << k; // alpha stays linear
      const double closed =
          k / 255.0 <= 0.04045 ? k / 255.0 / 12.92 : std::pow((k / 255.0 + 0.055) / 1.055, 2.4);
      // Bound: levels[k] is `closed` rounded once to float, and closed ≤ 1, so the error is
      // at most half an ulp below 1, 2^-25 ≈ 3.0e-8 < 1e-7.
      EXPECT_NEAR(v[0], closed, 1e-7) << k;
    }
  }
}

// Decode comes before the bilinear filter: between a black and a white texel the read is the
// average of the linear values, 0.5 (decoding after filtering would give decode(0.5) =
// 0.214). A 2×1 texture read by a 4×1 target at u = 3/8 … : the middle pixels.
TEST_F(VulkanTest, SrgbTextureDecodesBeforeFiltering) {
  auto tex = std::make_shared<img::Image>(2, 1, img::Format::RGBA8);
  tex->rgba = {0, 0, 0, 1, 1, 1, 1, 1};
  const TwoWays t =
      draw_both(*dev, sampling_pass(tex, cpu::Filter::Linear), 4, 1, img::Format::RGBA32F);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.cmp.identical_share, 1.0);
  // Pixel 1 reads u = 3/8, i.e. u·2 − ½ = 0.25: 0.25 of the white texel; pixel 2 0.75.
  EXPECT_EQ(t.vk.at(1, 0)[0], 0.25f);
  EXPECT_EQ(t.vk.at(2, 0)[0], 0.75f);
  EXPECT_EQ(t.cpu.at(1, 0)[0], 0.25f);
}

// SRGBWRITEENABLE: the floats on either side of every encode threshold, point-sampled from an
// RGBA32F texture into an RGBA8 target, store bytes k and k − 1 on both devices.
TEST_F(VulkanTest, SrgbWriteStoresTheNearestByteAtEveryThreshold) {
  const std::array<float, 256>& th = rounding::srgb_encode_thresholds();
  auto tex = std::make_shared<img::Image>(256, 2, img::Format::RGBA32F);
  for (int k = 1; k < 256; ++k) {
    float* at = tex->at(static_cast<uint32_t>(k), 0);
    float* below = tex->at(static_cast<uint32_t>(k), 1);
    for (int c = 0; c < 3; ++c) {
      at[c] = th[k];
      below[c] = std::nextafter(th[k], -1.0f);
    }
    at[3] = below[3] = 0.5f; // alpha is not encoded
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  float* specials = tex->at(0, 0);
  specials[0] = nan;
  specials[1] = 2.0f;
  specials[2] = -1.0f;
  cpu::Pass p = sampling_pass(tex, cpu::Filter::Point);
  p.textures[0].sampler.srgb = false;
  p.srgb_write = true;
  const TwoWays t = draw_both(*dev, p, 256, 2, img::Format::RGBA8);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.cmp.identical_share, 1.0);
  for (int k = 1; k < 256; ++k) {
    EXPECT_EQ(std::lround(t.vk.at(static_cast<uint32_t>(k), 0)[0] * 255.0f), k) << k;
    EXPECT_EQ(std::lround(t.vk.at(static_cast<uint32_t>(k), 1)[2] * 255.0f), k - 1) << k;
    EXPECT_EQ(t.vk.at(static_cast<uint32_t>(k), 0)[3], 128.0f / 255.0f) << k;
  }
  EXPECT_EQ(t.vk.at(0, 0)[0], 0.0f); // NaN
  EXPECT_EQ(t.vk.at(0, 0)[1], 1.0f); // above 1
  EXPECT_EQ(t.vk.at(0, 0)[2], 0.0f); // below 0
}

// An image through both: a noise texture read bilinearly through an sRGB stage, written with
// SRGBWRITEENABLE and blended (SRCALPHA/INVSRCALPHA, after the encode) onto a random RGBA8
// destination: the interpreter and lavapipe store the same bytes.
TEST_F(VulkanTest, SrgbReadAndWriteImageBitIdentical) {
  auto tex = std::make_shared<img::Image>(17, 13, img::Format::RGBA8);
  uint64_t state = 30;
  for (float& v : tex->rgba) v = static_cast<float>(img::splitmix64(state) % 256) / 255.0f;
  cpu::Pass p = sampling_pass(tex, cpu::Filter::Linear);
  p.srgb_write = true;
  p.blend = cpu::BlendMode::SrcAlphaInvSrcAlpha;
  p.conventions.pixel_center = ir::PixelCenter::D3D9;
  img::Image dst(61, 47, img::Format::RGBA8);
  for (float& v : dst.rgba) v = static_cast<float>(img::splitmix64(state) % 256) / 255.0f;
  const TwoWays t = draw_both(*dev, p, 61, 47, img::Format::RGBA8, &dst);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.cmp.identical_share, 1.0) << t.cmp.max_abs_all;
  // Without the write the bytes differ (the encode changes what is stored).
  cpu::Pass linear = p;
  linear.srgb_write = false;
  img::Image plain = dst;
  ASSERT_TRUE(cpu::draw(linear, plain, 2).ok());
  EXPECT_NE(plain.rgba, t.cpu.rgba);
  report("srgb read + write, blended rgba8", t.cmp);
}

} // namespace
} // namespace tierlift::vulkan::test
