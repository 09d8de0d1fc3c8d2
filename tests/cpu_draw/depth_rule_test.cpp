// D3D9's depth rule (pass/depth.h; NUMERICS.md D1-D5) and the CPU device's depth buffer,
// against values worked out by hand. tests/vulkan/depth_buffer_test.cpp draws the same kinds
// of passes on both devices; these run where there is no Vulkan too.
#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <vector>

#include "program_helpers.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/pass/depth.h"

namespace tierlift::pass {
namespace {

using cpu::test::parsed;

TEST(DepthRule, ValueIsODepthOrInterpolatedClampedToTheRange) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float written[] = {-0.5f, 1.5f, nan, 0.25f, -0.0f, 1e-40f};
  const float keep[] = {0.0f, 1.0f, 0.0f, 0.25f, 0.0f, 1e-40f}; // denormals kept (Exact)
  const float flush[] = {0.0f, 1.0f, 0.0f, 0.25f, 0.0f, 0.0f};  // and flushed (lavapipe)
  for (size_t i = 0; i < std::size(written); ++i) {
    EXPECT_EQ(std::bit_cast<uint32_t>(fragment_depth(&written[i], 0.75f, false)),
              std::bit_cast<uint32_t>(keep[i]))
        << written[i];
    EXPECT_EQ(std::bit_cast<uint32_t>(fragment_depth(&written[i], 0.75f, true)),
              std::bit_cast<uint32_t>(flush[i]))
        << written[i];
  }
  // No oDepth: the interpolated z, clamped the same way.
  EXPECT_EQ(fragment_depth(nullptr, 0.75f, true), 0.75f);
  EXPECT_EQ(fragment_depth(nullptr, 1.0000001f, true), 1.0f);
}

TEST(DepthRule, CompareFunctionsPutTheFragmentOnTheLeft) {
  // (fragment 0.5 FUNC stored) for stored 0.25, 0.5, 0.75.
  struct Row {
    CompareFunc f;
    bool at_quarter, at_half, at_three_quarters;
  };
  const Row rows[] = {
      {CompareFunc::Never, false, false, false},      {CompareFunc::Less, false, false, true},
      {CompareFunc::Equal, false, true, false},       {CompareFunc::LessEqual, false, true, true},
      {CompareFunc::Greater, true, false, false},     {CompareFunc::NotEqual, true, false, true},
      {CompareFunc::GreaterEqual, true, true, false}, {CompareFunc::Always, true, true, true},
  };
  for (const Row& r : rows) {
    EXPECT_EQ(depth_passes(r.f, 0.5f, 0.25f), r.at_quarter) << compare_func_name(r.f);
    EXPECT_EQ(depth_passes(r.f, 0.5f, 0.5f), r.at_half) << compare_func_name(r.f);
    EXPECT_EQ(depth_passes(r.f, 0.5f, 0.75f), r.at_three_quarters) << compare_func_name(r.f);
    CompareFunc parsed_back = CompareFunc::Never;
    EXPECT_TRUE(parse_compare_func(compare_func_name(r.f), parsed_back));
    EXPECT_EQ(parsed_back, r.f);
  }
  CompareFunc f = CompareFunc::Never;
  EXPECT_TRUE(parse_compare_func("D3DCMP_GREATEREQUAL", f));
  EXPECT_EQ(f, CompareFunc::GreaterEqual);
  EXPECT_FALSE(parse_compare_func("lequal", f));
}

// A 4x1 quad whose pixels bring oDepth = u = i/4 against a buffer of 0.3 under GREATER:
// columns 2 and 3 (0.5, 0.75 > 0.3) pass, store their depth and colour; texkill of
// (0.7 − u) kills column 3 (0.7 − 0.75 < 0), which then keeps 0.3 and colour 0.
TEST(DepthRule, CpuDrawTestsWritesAndSkipsKilledPixels) {
  Pass p;
  p.vertex_program = parsed("vs_2_0\ndcl_position v0\ndcl_texcoord v1\nmov oPos, v0\n"
                            "mov oT0, v1\n");
  p.pixel_program = parsed("ps_2_0\ndcl t0\nsub r0, c0, t0\ntexkill r0\nmov oC0, c1\n"
                           "mov oDepth, t0.x\n");
  set_full_screen_quad_uv(p);
  p.ps_constants.f = {Vec4{0.7f, 1, 1, 1}, Vec4{1, 1, 1, 1}};
  p.depth_stencil.depth_test = true;
  p.depth_stencil.depth_write = true;
  p.depth_stencil.depth_func = CompareFunc::Greater;
  img::Image color(4, 1);
  std::vector<float> depth(4, 0.3f);
  cpu::DrawTargets t;
  t.color[0] = &color;
  t.depth = depth.data();
  ir::Result<cpu::DrawStats> s = cpu::draw(p, t, 1);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->pixels_killed, 1u);
  EXPECT_EQ(depth, (std::vector<float>{0.3f, 0.3f, 0.5f, 0.3f}));
  const float drawn[] = {0, 0, 1, 0};
  for (uint32_t x = 0; x < 4; ++x) EXPECT_EQ(color.at(x, 0)[0], drawn[x]) << x;
  // A depth and a stencil buffer in one pass: refused (no device draws both yet).
  std::vector<uint8_t> stencil(4, 0);
  t.stencil = stencil.data();
  p.depth_stencil.stencil_test = true;
  ir::Result<cpu::DrawStats> both = cpu::draw(p, t, 1);
  EXPECT_FALSE(both.ok());
  EXPECT_NE(both.message().find("not drawn yet"), std::string::npos) << both.message();
}

} // namespace
} // namespace tierlift::pass
