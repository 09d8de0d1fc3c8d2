// The Vulkan device leaves out what ir::plain_values proves changes nothing
// (codegen::CodegenOptions::plain_values): the zero test of a product of two plain factors
// (decoded RGBA8 texels, positive weights, their sums) and a ps_1_x range clamp no plain
// result reaches. The image must stay the interpreter's, bit for bit, on values that sit on
// each edge of the facts: zero texels times negative weights and −0 (rule 8 makes +0 where a
// plain product would make −0), sums that overflow to ∞ times zero texels (+0, not NaN),
// weights up to FLT_MAX, and ps_1_x results above and below the range.
#include <cfloat>

#include "resident_fixture.h"

namespace tierlift::vulkan::test {
namespace {

// RGBA8 levels 0, 1, 128, 254 and 255, zeros most often, in an odd size. The next texel
// along x (four floats on) holds the previous level of the list in the same channel: each
// large level has a zero beside it.
img::Image zero_heavy_texture() {
  const int levels[] = {0, 255, 0, 128, 0, 254, 1};
  img::Image im(19, 7, img::Format::RGBA8);
  for (size_t i = 0; i < im.rgba.size(); ++i)
    im.rgba[i] = static_cast<float>(levels[(i * 5) % std::size(levels)]) / 255.0f;
  return im;
}

void expect_same_bits(const std::pair<img::Image, img::Image>& cpu_vk) {
  std::string where;
  EXPECT_TRUE(same_bits(cpu_vk.first, cpu_vk.second, &where)) << where;
}

TEST_F(ResidentTest, PlainProductsKeepTheZeroRule) {
  const img::Image tex = zero_heavy_texture();
  // r2 = texel·c0 + c1 may reach ∞; oC0.xy = texel·c2; oC0.zw = r2·texel.
  const auto ps = parse_listing("ps_2_0\ndcl t0.xy\ndcl t1.xy\ndcl_2d s0\ntexld r0, t0, s0\n"
                                "texld r1, t1, s0\nmad r2, r0, c0, c1\nmul r4, r1, c2\n"
                                "mul r4.zw, r2, r1\nmov oC0, r4\n",
                                "plain.psh");
  const std::vector<cpu::Vec4> banks[] = {
      // Every product plain: the tests are left out.
      {{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f, 0.25f}, {0.75f, 1.5f, 2, 3}},
      // A −0.5 weight, then a −0 one: +0 where the texel is 0, not −0 (the other weights are
      // plain: each product is tested for that one component). 3e38·k/255 + 3e38 reaches ∞
      // for k >= 128: ∞ times a zero texel is +0, not NaN.
      {{3e38f, 3e38f, 3e38f, 3e38f}, {3e38f, 3e38f, 3e38f, 3e38f}, {-0.5f, 0.5f, 0.5f, 0.5f}},
      {{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f, 0.25f}, {0.5f, -0.0f, 0.5f, 0.5f}},
      // Up to FLT_MAX without overflow (plain); a denormal weight (not plain).
      {{FLT_MAX, FLT_MAX, FLT_MAX, FLT_MAX}, {0, 0, 0, 0}, {1e-39f, 0, FLT_MAX, 0.5f}},
  };
  for (const auto& bank : banks)
    expect_same_bits(draw_both_ways(*dev, tex, ps, bank, img::Format::RGBA8));
}

TEST_F(ResidentTest, Ps1xRangeClampOnlyWhereAResultCanLeaveIt) {
  const img::Image tex = zero_heavy_texture();
  // rgb: texel·c0·4, up to 2 with c0 = 0.5 (above a range of ±1, within ±8); alpha: texel·c1,
  // at most 0.25. Co-issued, as the glow's dx8 composite.
  const auto ps = parse_listing("ps.1.3\ntex t0\ntex t1\nmul_x4 r0.rgb, t0, c0\n"
                                "+mul r0.a, t1, c1\n",
                                "plain13.psh");
  const std::vector<cpu::Vec4> bank = {{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f, 0.25f}};
  for (const float max : {1.0f, 8.0f}) {
    SCOPED_TRACE(max);
    ir::Conventions c;
    c.ps1x_max_value = max;
    const auto both = draw_both_ways(*dev, tex, ps, bank, img::Format::RGBA8, c);
    expect_same_bits(both);
    // The clamp did its work with the range ±1: no value above 1.
    float most = 0;
    for (float x : both.second.rgba) most = std::max(most, x);
    EXPECT_EQ(most, max == 1.0f ? 1.0f : 2.0f);
  }
}

} // namespace
} // namespace tierlift::vulkan::test
