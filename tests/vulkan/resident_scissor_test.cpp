// D3D9's scissor rectangle on the Vulkan device (pass::Pass::scissor): a full-screen pass
// writes only the rectangle, intersected with the viewport; a draw kept in the TextureSet's
// cache is not reused for another rectangle.
#include "resident_fixture.h"

namespace tierlift::vulkan::test {
namespace {

TEST_F(ResidentTest, ScissorLimitsTheDraw) {
  TextureSet set(*dev);
  TextureId t{};
  ASSERT_TRUE(succeeded(set.create(7, 4, img::Format::RGBA32F), t));
  cpu::Pass p;
  p.vertex_program = parse_listing("vs_2_0\ndcl_position v0\nmov oPos, v0\n", "pos.vsh");
  p.pixel_program = parse_listing("ps_2_0\nmov oC0, c0\n", "c0.psh");
  cpu::set_full_screen_quad(p, 0);
  p.ps_constants.f = {cpu::Vec4{1, 0.5f, 0.25f, 1}};
  p.scissor = pass::ScissorRect{2, 1, 5, 3};
  ASSERT_TRUE(set.draw(p, StageTextures{}, t).ok());
  img::Image out;
  ASSERT_TRUE(succeeded(set.read(t), out));
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 7; ++x)
      EXPECT_EQ(out.at(x, y)[0], x >= 2 && x < 5 && y >= 1 && y < 3 ? 1.0f : 0.0f) << x << "," << y;
  // The same pass with another rectangle (and the viewport x 4..6): a new draw, not the
  // cached one; only x = 4, 5 of rows 0..1 are added to what the texture holds.
  p.scissor = pass::ScissorRect{0, 0, 6, 2};
  p.viewport.x = 4;
  p.viewport.width = 3;
  p.ps_constants.f = {cpu::Vec4{2, 0, 0, 1}};
  ASSERT_TRUE(set.draw(p, StageTextures{}, t).ok());
  ASSERT_TRUE(succeeded(set.read(t), out));
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 7; ++x) {
      const bool second = (x == 4 || x == 5) && y < 2;
      const bool first = x >= 2 && x < 5 && y >= 1 && y < 3;
      EXPECT_EQ(out.at(x, y)[0], second ? 2.0f : first ? 1.0f : 0.0f) << x << "," << y;
    }
}

} // namespace
} // namespace tierlift::vulkan::test
