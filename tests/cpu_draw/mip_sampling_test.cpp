// Mip chains on the CPU device (NUMERICS.md M1-M6) against values worked out by hand: a
// texture whose level k holds the constant k, read at known lods under both roundings, so
// the read is the blend fine + f; a generated level against its 2×2 box averages; and a
// ps_1_x pass with a mip chain read by lod refused.
#include <gtest/gtest.h>

#include "program_helpers.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/pass/mip_chain.h"

namespace tierlift::cpu {
namespace {

std::shared_ptr<const img::Image> constant_level(uint32_t n, float v) {
  auto im = std::make_shared<img::Image>(n, n);
  for (size_t p = 0; p < im->rgba.size(); p += 4) {
    im->rgba[p] = im->rgba[p + 1] = im->rgba[p + 2] = v;
    im->rgba[p + 3] = 1;
  }
  return im;
}

// 16×16 … 1×1, level k = (k, k, k, 1).
TextureBinding level_numbered(pass::MipFilter f, float bias = 0, uint32_t max_level = 0) {
  std::vector<std::shared_ptr<const img::Image>> levels;
  for (uint32_t k = 0; k < 5; ++k) levels.push_back(constant_level(16u >> k, float(k)));
  TextureBinding b = *pass::mipmapped_binding(levels);
  b.sampler.filter = Filter::Linear;
  b.sampler.mip = {f, bias, max_level};
  return b;
}

std::shared_ptr<const ir::Program> program(const std::string& text) {
  auto p = test::parsed(text, "mip.psh", true);
  EXPECT_TRUE(p) << text;
  return p;
}

// texldl at (½, ½) with lod `lod` on a 1×1 target: the red of the read.
float read_at_lod(const TextureBinding& b, float lod, ir::Rounding rounding) {
  Pass p;
  p.pixel_program = program("ps_3_0\ndcl_2d s0\nmov r0, c0\ntexldl r1, r0, s0\nmov oC0, r1\n");
  p.ps_constants.f = {{0.5f, 0.5f, 0, lod}};
  p.textures[0] = b;
  p.conventions.rounding = rounding;
  img::Image out(1, 1);
  ir::Result<DrawStats> s = draw(p, out, 1);
  EXPECT_TRUE(s.ok()) << s.message();
  return out.rgba[0];
}

TEST(MipSampling, LinearBlendIsFinePlusFraction) {
  for (ir::Rounding r : {ir::Rounding::Exact, ir::Rounding::Llvmpipe}) {
    const TextureBinding b = level_numbered(pass::MipFilter::Linear);
    EXPECT_EQ(read_at_lod(b, 2.25f, r), 2.25f); // ¾·2 + ¼·3
    EXPECT_EQ(read_at_lod(b, 0.5f, r), 0.5f);   // ½·0 + ½·1
    EXPECT_EQ(read_at_lod(b, -3.0f, r), 0.0f);  // magnified: level 0
    EXPECT_EQ(read_at_lod(b, 11.0f, r), 4.0f);  // beyond the last level
    // MIPMAPLODBIAS adds, MAXMIPLEVEL clamps from below.
    EXPECT_EQ(read_at_lod(level_numbered(pass::MipFilter::Linear, 1.5f), 0.25f, r), 1.75f);
    EXPECT_EQ(read_at_lod(level_numbered(pass::MipFilter::Linear, 0, 3), 0.25f, r), 3.0f);
    // NONE reads MAXMIPLEVEL whatever the lod.
    EXPECT_EQ(read_at_lod(level_numbered(pass::MipFilter::None, 0, 2), 0.25f, r), 2.0f);
  }
}

TEST(MipSampling, PointTiesDifferBetweenTheRoundings) {
  const TextureBinding b = level_numbered(pass::MipFilter::Point);
  // lavapipe rounds ties to even (M2, measured); the exact rule takes the coarser level.
  EXPECT_EQ(read_at_lod(b, 2.5f, ir::Rounding::Llvmpipe), 2.0f);
  EXPECT_EQ(read_at_lod(b, 2.5f, ir::Rounding::Exact), 3.0f);
  EXPECT_EQ(read_at_lod(b, 1.5f, ir::Rounding::Llvmpipe), 2.0f);
  EXPECT_EQ(read_at_lod(b, 1.49f, ir::Rounding::Exact), 1.0f);
}

TEST(MipSampling, GeneratedLevelIsTheBoxAverage) {
  // Level 1 of a 4×2 image read point-sampled through MIPFILTER NONE, MAXMIPLEVEL 1.
  auto base = std::make_shared<img::Image>(4, 2);
  const float v[2][4] = {{1, 2, 4, 8}, {16, 32, 64, 128}};
  for (uint32_t j = 0; j < 2; ++j)
    for (uint32_t i = 0; i < 4; ++i)
      for (int c = 0; c < 4; ++c) base->at(i, j)[c] = v[j][i];
  TextureBinding b = *pass::mipmapped_binding(pass::generate_mips(base, 0));
  ASSERT_EQ(b.levels.size(), 3u); // 4×2, 2×1, 1×1
  b.sampler.mip = {pass::MipFilter::None, 0, 1};
  Pass p;
  p.pixel_program = program("ps_2_0\ndcl_2d s0\nmov r1, c0\ntexld r0, r1, s0\nmov oC0, r0\n");
  p.ps_constants.f = {{0.75f, 0.5f, 0, 0}};
  p.textures[0] = b;
  img::Image out(1, 1);
  ASSERT_TRUE(draw(p, out, 1).ok());
  EXPECT_EQ(out.rgba[0], (4.0f + 8 + 64 + 128) / 4); // texel 1 of level 1
}

TEST(MipSampling, Ps1xWithAMipChainReadByLodIsRefused) {
  Pass p;
  p.pixel_program = program("ps_1_1\ntex t0\nmov r0, t0\n");
  p.textures[0] = level_numbered(pass::MipFilter::Linear);
  img::Image out(1, 1);
  ir::Result<DrawStats> s = draw(p, out, 1);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("mip chain"), std::string::npos) << s.message();
}

} // namespace
} // namespace tierlift::cpu
