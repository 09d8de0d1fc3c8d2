// Mip chains on both devices (NUMERICS.md "Mip levels and LOD", M1-M6): lavapipe's level of
// detail measured against hand-computed values, and the interpreter (Rounding::Llvmpipe)
// bit-identical with it for texld with implicit lod on a minified quad, texldp, texldb,
// texldl and texldd, under each MIPFILTER, MAXMIPLEVEL and MIPMAPLODBIAS.
//
// The probe texture is 64×64 with seven levels, level k the constant (k, k, k, 1): a read
// filters within a level to that constant, so with MIPFILTER LINEAR it returns fine + f (the
// blend fma(f, 1, k) is exact for these), which is λ itself once clamped to [0, 6], and with
// POINT the level taken.
#include <cstring>

#include "diff_harness.h"
#include "tierlift/pass/mip_chain.h"

namespace tierlift::vulkan::test {
namespace {

using pass::MipFilter;

const char* kVs = "vs_3_0\ndcl_position v0\ndcl_texcoord v3\ndcl_position o0\n"
                  "dcl_texcoord0 o1\nmov o0, v0\nmov o1, v3\n";

std::shared_ptr<const img::Image> constant_level(uint32_t n, float v) {
  auto im = std::make_shared<img::Image>(n, n);
  for (size_t p = 0; p < im->rgba.size(); p += 4) {
    im->rgba[p] = im->rgba[p + 1] = im->rgba[p + 2] = v;
    im->rgba[p + 3] = 1;
  }
  return im;
}

// 64×64 … 1×1, level k = (k, k, k, 1).
pass::TextureBinding level_numbered(MipFilter f, float bias = 0, uint32_t max_level = 0,
                                    cpu::Filter filter = cpu::Filter::Linear) {
  std::vector<std::shared_ptr<const img::Image>> levels;
  for (uint32_t k = 0; k < 7; ++k) levels.push_back(constant_level(64u >> k, float(k)));
  pass::TextureBinding b = *pass::mipmapped_binding(levels);
  b.sampler.filter = filter;
  b.sampler.address_u = b.sampler.address_v = cpu::AddressMode::Clamp;
  b.sampler.mip = {f, bias, max_level};
  return b;
}

// A 64×64 texture of random values with its generated chain (a real image minified).
pass::TextureBinding random_chain(MipFilter f, cpu::Filter filter, uint64_t seed) {
  pass::TextureBinding b = *pass::mipmapped_binding(
      pass::generate_mips(random_texture(seed, {0.0f, 1.0f, 0}, 64, 64), 0));
  b.sampler.filter = filter;
  b.sampler.address_u = b.sampler.address_v = cpu::AddressMode::Wrap;
  b.sampler.mip.filter = f;
  return b;
}

bool same_bits(const img::Image& a, const img::Image& b) {
  return a.rgba.size() == b.rgba.size() &&
         std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * 4) == 0;
}

std::string first_difference(const img::Image& a, const img::Image& b) {
  for (size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i)
    if (std::memcmp(&a.rgba[i], &b.rgba[i], 4) != 0)
      return fmt::format("pixel ({}, {}) channel {}: cpu {} vulkan {}", (i / 4) % a.width,
                         (i / 4) / a.width, i % 4, a.rgba[i], b.rgba[i]);
  return "sizes differ";
}

// Draws `ps` over the 16×16 full-screen quad (t0 = quad uv) with `binding` on s0 and c0 =
// `c0`, on both devices.
DiffResult draw_mips(vulkan::Device& dev, const std::string& ps, const pass::TextureBinding& b,
                     cpu::Vec4 c0 = {0, 0, 0, 0}, cpu::Vec4 c1 = {0, 0, 0, 0}) {
  DiffSetup s;
  s.ps_c = {c0, c1};
  return run_diff_with(dev, kVs, ps, s, [&](cpu::Pass& p) {
    p.textures[0] = b;
    p.conventions.subtexel_bits = 0; // lavapipe weights float textures unquantised
  });
}

// The red channel of pixel (x, y).
float red(const img::Image& im, uint32_t x, uint32_t y) {
  return im.rgba[4 * (size_t{y} * im.width + x)];
}

// texldl with lod = u·c0.x + c0.y per pixel (u = (x + ½)/16): each pixel's own lod (M5:
// measured, lavapipe does not share an explicit lod across the quad).
const char* kTexldl = "ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\n"
                      "mov r0.xy, v0\nmad r0.w, v0.x, c0.x, c0.y\ntexldl r1, r0, s0\nmov oC0, r1\n";

// The lod of pixel column x: u·a + b with u = (x + ½)/16.
float pixel_lod(uint32_t x, float a, float b) {
  return (float(x) + 0.5f) / 16.0f * a + b;
}

TEST_F(VulkanTest, MipTexldlLinearReadsLevelPlusFractionOfItsLod) {
  // λ = u·8 − 1: −0.75 … 6.75 across the target, both ends clamped.
  DiffResult r = draw_mips(*dev, kTexldl, level_numbered(MipFilter::Linear), {8, -1, 0, 0});
  ASSERT_TRUE(r.ok);
  for (uint32_t x = 0; x < kDiffW; ++x) {
    const float want = std::clamp(pixel_lod(x, 8, -1), 0.0f, 6.0f);
    for (const img::Image* im : {&r.vk, &r.cpu})
      EXPECT_EQ(red(*im, x, 5), want) << (im == &r.vk ? "vulkan" : "cpu") << " x " << x;
  }
  EXPECT_TRUE(same_bits(r.cpu, r.vk)) << first_difference(r.cpu, r.vk);
}

TEST_F(VulkanTest, MipTexldlPointRoundsHalvesToEven) {
  // λ = u·8 + ¼ = x/2 + ½: a tie at every even x, which lavapipe rounds to the even level.
  DiffResult r = draw_mips(*dev, kTexldl, level_numbered(MipFilter::Point), {8, 0.25f, 0, 0});
  ASSERT_TRUE(r.ok);
  for (uint32_t x = 0; x < kDiffW; ++x) {
    const float lod = pixel_lod(x, 8, 0.25f);
    ASSERT_EQ(lod - std::floor(lod), x % 2 == 0 ? 0.5f : 0.0f);
    const float want = std::min(6.0f, std::nearbyint(lod)); // ties to even
    for (const img::Image* im : {&r.vk, &r.cpu})
      EXPECT_EQ(red(*im, x, 3), want) << (im == &r.vk ? "vulkan" : "cpu") << " x " << x;
  }
  EXPECT_TRUE(same_bits(r.cpu, r.vk)) << first_difference(r.cpu, r.vk);
}

TEST_F(VulkanTest, MipNoneReadsMaxMipLevelWhateverTheLod) {
  for (uint32_t m : {0u, 2u, 9u}) {
    DiffResult r =
        draw_mips(*dev, kTexldl, level_numbered(MipFilter::None, 0.5f, m), {8, -1, 0, 0});
    ASSERT_TRUE(r.ok);
    for (uint32_t x = 0; x < kDiffW; ++x)
      EXPECT_EQ(red(r.vk, x, 0), float(std::min(m, 6u))) << "MAXMIPLEVEL " << m << " x " << x;
    EXPECT_TRUE(same_bits(r.cpu, r.vk)) << first_difference(r.cpu, r.vk);
  }
}

TEST_F(VulkanTest, MipMaxMipLevelAndLodBiasClampAndShift) {
  // λ = u·8 − 1 + MIPMAPLODBIAS, clamped below by MAXMIPLEVEL 2.
  DiffResult r =
      draw_mips(*dev, kTexldl, level_numbered(MipFilter::Linear, 0.75f, 2), {8, -1, 0, 0});
  ASSERT_TRUE(r.ok);
  for (uint32_t x = 0; x < kDiffW; ++x) {
    const float want = std::clamp(pixel_lod(x, 8, -1) + 0.75f, 2.0f, 6.0f);
    EXPECT_EQ(red(r.vk, x, 7), want) << "x " << x;
  }
  EXPECT_TRUE(same_bits(r.cpu, r.vk)) << first_difference(r.cpu, r.vk);
}

// texld of t0·c0.xy (implicit lod). Across a quad du/dx = c0.x/16 and dv/dy = c0.y/16, so
// ρ = 4·max(c0.x, c0.y) texels on the 64-texel level 0.
const char* kTexldScaled = "ps_2_0\ndcl t0\ndcl_2d s0\n"
                           "mul r0, t0, c0\ntexld r1, r0, s0\nmov oC0, r1\n";

TEST_F(VulkanTest, MipImplicitLodIsHalfTheFastLog2OfRhoSquared) {
  // ρ = 4 → λ = 2 exactly; ρ = 6: ρ² = 36 = 1.125·2^5, fast_log2 = 4 + 1.125, λ = 2.5625
  // (log2 6 = 2.585); ρ = 2.5 (one axis only): ρ² = 6.25 = 1.5625·2², λ = (1 + 1.5625)/2.
  struct Case {
    float sx, sy, want;
  };
  for (const Case c :
       {Case{1, 1, 2.0f}, Case{1.5f, 1.5f, 2.5625f}, Case{0.625f, 0.25f, 1.28125f}}) {
    DiffResult r =
        draw_mips(*dev, kTexldScaled, level_numbered(MipFilter::Linear), {c.sx, c.sy, 0, 0});
    ASSERT_TRUE(r.ok);
    for (uint32_t y = 0; y < kDiffH; y += 5)
      for (uint32_t x = 0; x < kDiffW; x += 3)
        EXPECT_EQ(red(r.vk, x, y), c.want)
            << "scale " << c.sx << "," << c.sy << " at " << x << "," << y;
    EXPECT_TRUE(same_bits(r.cpu, r.vk)) << first_difference(r.cpu, r.vk);
  }
}

TEST_F(VulkanTest, MipImplicitPointLevelFromRho) {
  // No bias, MAXMIPLEVEL 0, POINT: the level is floor(log2(ρ·√2)), the nearest in log2:
  // ρ = 4 → 2; ρ = 5.6 → 2 (log2 = 2.49); ρ = 5.7 → 3 (2.51).
  struct Case {
    float s, want;
  };
  for (const Case c : {Case{1, 2}, Case{1.4f, 2}, Case{1.425f, 3}}) {
    DiffResult r =
        draw_mips(*dev, kTexldScaled, level_numbered(MipFilter::Point), {c.s, c.s, 0, 0});
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(red(r.vk, 6, 6), c.want) << "scale " << c.s;
    EXPECT_TRUE(same_bits(r.cpu, r.vk)) << first_difference(r.cpu, r.vk);
  }
}

// u = t0.x²·c0.x, v = t0.y·c0.y: the quads' gradients differ column by column, so one draw
// sweeps λ; every MIPFILTER, MAXMIPLEVEL and bias, bit-identical.
const char* kTexldSwept = "ps_2_0\ndcl t0\ndcl_2d s0\n"
                          "mov r0, t0\nmul r0.x, t0.x, t0.x\nmul r0, r0, c0\n"
                          "texld r1, r0, s0\nmov oC0, r1\n";

TEST_F(VulkanTest, MipImplicitLodSweepBitIdentical) {
  for (MipFilter f : {MipFilter::None, MipFilter::Point, MipFilter::Linear})
    for (uint32_t m : {0u, 2u})
      for (float bias : {0.0f, 0.75f, -1.25f})
        for (float sx : {3.0f, 7.3f, 40.0f}) {
          DiffResult r = draw_mips(*dev, kTexldSwept, level_numbered(f, bias, m), {sx, 0.5f, 0, 0});
          ASSERT_TRUE(r.ok);
          EXPECT_TRUE(same_bits(r.cpu, r.vk))
              << "mipfilter " << int(f) << " maxmiplevel " << m << " bias " << bias << " scale "
              << sx << ": " << first_difference(r.cpu, r.vk);
        }
}

TEST_F(VulkanTest, MipMinifiedImageBitIdentical) {
  // A real 64×64 image (its generated chain) on the 16×16 target, scaled 1…5×: texld, texldp
  // (w = 2) and both filters.
  const char* texldp = "ps_2_0\ndcl t0\ndcl_2d s0\ndef c2, 0, 0, 0, 2\n"
                       "mul r0, t0, c0\nadd r0, r0, r0\nmov r0.w, c2.w\ntexldp r1, r0, s0\n"
                       "mov oC0, r1\n";
  for (const char* ps : {kTexldScaled, kTexldSwept, texldp})
    for (MipFilter f : {MipFilter::Point, MipFilter::Linear})
      for (cpu::Filter filter : {cpu::Filter::Point, cpu::Filter::Linear})
        for (float s : {1.0f, 2.3f, 5.0f}) {
          DiffResult r = draw_mips(*dev, ps, random_chain(f, filter, 11), {s, s * 0.7f, 0, 0});
          ASSERT_TRUE(r.ok);
          EXPECT_TRUE(same_bits(r.cpu, r.vk))
              << ps << " mipfilter " << int(f) << " filter " << int(filter) << " scale " << s
              << ": " << first_difference(r.cpu, r.vk);
        }
}

TEST_F(VulkanTest, MipTexldbAddsEachPixelsBias) {
  // t0·1 (ρ = 4, λ = 2) plus a bias of 4·v − 2, each pixel's own.
  const char* ps = "ps_2_0\ndcl t0\ndcl_2d s0\n"
                   "mov r0, t0\nmad r0.w, t0.y, c0.z, c0.w\ntexldb r1, r0, s0\nmov oC0, r1\n";
  for (float m : {0.0f, 1.0f}) {
    DiffResult r =
        draw_mips(*dev, ps, level_numbered(MipFilter::Linear, 0, uint32_t(m)), {1, 1, 4, -2});
    ASSERT_TRUE(r.ok);
    for (uint32_t y = 0; y < kDiffH; ++y) {
      const float v0 = (float(y) + 0.5f) / 16.0f;
      const float want = std::clamp(2.0f + (v0 * 4 - 2), m, 6.0f);
      EXPECT_EQ(red(r.vk, 9, y), want) << "y " << y;
    }
    EXPECT_TRUE(same_bits(r.cpu, r.vk)) << first_difference(r.cpu, r.vk);
  }
}

TEST_F(VulkanTest, MipTexlddTakesEachPixelsGradients) {
  // ddx = (c0.x·u, 0), ddy = (0, c0.y): ρ = 64·max(c0.x·u, c0.y), each pixel's own.
  const char* ps = "ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\ndef c2, 0, 0, 0, 0\n"
                   "mov r0, v0\nmul r1, c2, c2\nmul r1.x, v0.x, c0.x\nmov r2, c2\n"
                   "mov r2.y, c0.y\ntexldd r3, r0, s0, r1, r2\nmov oC0, r3\n";
  for (MipFilter f : {MipFilter::Point, MipFilter::Linear})
    for (float bias : {0.0f, 0.5f}) {
      DiffResult r = draw_mips(*dev, ps, level_numbered(f, bias), {1.0f, 1.0f / 64, 0, 0});
      ASSERT_TRUE(r.ok);
      if (f == MipFilter::Linear && bias == 0) {
        // ρ = max(64·u, 1): at x = 14 u = 0.90625, ρ = 58 → ρ² = 3364 = 1.642578125·2^11,
        // λ = (10 + 1.642578125)/2 = 5.8212890625.
        EXPECT_EQ(red(r.vk, 14, 4), 5.8212890625f);
        // x = 0: u = 1/32, ρ = max(2, 1) = 2, λ = 1; x = 1: ρ = 6, λ = 2.5625.
        EXPECT_EQ(red(r.vk, 0, 4), 1.0f);
        EXPECT_EQ(red(r.vk, 1, 4), 2.5625f);
      }
      EXPECT_TRUE(same_bits(r.cpu, r.vk))
          << "mipfilter " << int(f) << " bias " << bias << ": " << first_difference(r.cpu, r.vk);
    }
}

} // namespace
} // namespace tierlift::vulkan::test
