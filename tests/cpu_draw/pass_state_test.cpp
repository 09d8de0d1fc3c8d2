// The device-neutral pass state (tierlift/pass): which vertex input the full-screen quad's
// position and uv feed (one rule for `tierlift run` and the effect graph), and the refusal of
// state a device cannot draw yet. Expected values are the D3D9 rules and the quad's corners
// written out by hand.
#include <gtest/gtest.h>

#include "program_helpers.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/pass/pass.h"

namespace tierlift::pass {
namespace {

std::shared_ptr<const ir::Program> vertex(const std::string& text) {
  return cpu::test::parsed(text);
}

TEST(PassState, PositionIsTheInputDeclaredPositionWithUsageIndexZero) {
  // dcl_position1 is a second position stream (e.g. tweening), not the one the quad feeds.
  auto both = vertex("vs_2_0\ndcl_position1 v2\ndcl_position v5\nmov oPos, v5\n");
  ASSERT_TRUE(both);
  EXPECT_EQ(position_input(*both), 5u);
  auto only_one = vertex("vs_2_0\ndcl_position1 v4\nmov oPos, v4\n");
  ASSERT_TRUE(only_one);
  EXPECT_EQ(position_input(*only_one), 0u); // no position 0 declared: v0, as D3D8 listings
  auto none = vertex("vs.1.1\nmov oPos, v0\n");
  ASSERT_TRUE(none);
  EXPECT_EQ(position_input(*none), 0u);
}

TEST(PassState, QuadUvFeedsEveryTexcoordInput) {
  auto vs = vertex("vs_2_0\ndcl_position v5\ndcl_texcoord v1\ndcl_texcoord3 v3\ndcl_color v2\n"
                   "mov oPos, v5\nadd oT0, v1, v3\nmov oD0, v2\n");
  ASSERT_TRUE(vs);
  EXPECT_EQ(texcoord_inputs(*vs), (std::vector<uint32_t>{1, 3}));
  Pass p;
  p.vertex_program = vs;
  set_full_screen_quad_uv(p);
  ASSERT_EQ(p.vertices.size(), 4u);
  // Corners top-left, top-right, bottom-left, bottom-right.
  const Vec4 pos[4] = {{-1, 1, 0, 1}, {1, 1, 0, 1}, {-1, -1, 0, 1}, {1, -1, 0, 1}};
  const Vec4 uv[4] = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}};
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(p.vertices[c].v[5], pos[c]) << c;
    EXPECT_EQ(p.vertices[c].v[1], uv[c]) << c;
    EXPECT_EQ(p.vertices[c].v[3], uv[c]) << c;
    EXPECT_EQ(p.vertices[c].v[2], (Vec4{0, 0, 0, 1})) << c; // not a texcoord: the default
  }
  EXPECT_EQ(p.triangles.size(), 2u);
}

TEST(PassState, StateADeviceCannotDrawIsRefused) {
  Pass p;
  EXPECT_TRUE(check_supported(p, Capabilities{}, "cpu"));
  p.color_targets = 2;
  ir::Status mrt = check_supported(p, Capabilities{}, "cpu");
  ASSERT_FALSE(mrt);
  EXPECT_EQ(mrt.diagnostics()[0].rule, "unsupported");
  EXPECT_NE(mrt.message().find("2 render targets"), std::string::npos) << mrt.message();
  EXPECT_TRUE(check_supported(p, Capabilities{.max_color_targets = 4}, "future"));

  Pass stencil;
  stencil.depth_stencil.stencil_test = true;
  EXPECT_FALSE(check_supported(stencil, Capabilities{}, "cpu"));
  EXPECT_TRUE(check_supported(stencil, Capabilities{.depth_stencil = true}, "future"));
}

TEST(PassState, CpuDeviceRefusesAStencilPassWithoutABufferAndLeavesTheTarget) {
  Pass p;
  p.depth_stencil.stencil_test = true;
  p.constant_inputs.color[0] = {1, 1, 1, 1};
  img::Image target(2, 2, img::Format::RGBA32F);
  ir::Result<cpu::DrawStats> s = cpu::draw(p, target);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("no stencil buffer"), std::string::npos) << s.message();
  for (float v : target.rgba) EXPECT_EQ(v, 0.0f);
}

} // namespace
} // namespace tierlift::pass
