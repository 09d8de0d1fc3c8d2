// D3D9's scissor rectangle on the CPU device (pass::Pass::scissor): a full-screen pass writes
// only x0 ≤ x < x1, y0 ≤ y < y1, intersected with the viewport; the rest keeps its pixels.
#include <gtest/gtest.h>

#include "tierlift/cpu/draw.h"
#include "tierlift/pass/pass.h"

namespace tierlift::pass {
namespace {

TEST(Scissor, OnlyTheRectangleIsDrawn) {
  Pass p;
  p.constant_inputs.color[0] = {1, 0.5f, 0.25f, 1};
  p.scissor = ScissorRect{2, 1, 5, 3};
  img::Image t(7, 4);
  ASSERT_TRUE(cpu::draw(p, t, 1).ok());
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 7; ++x)
      EXPECT_EQ(t.at(x, y)[0], x >= 2 && x < 5 && y >= 1 && y < 3 ? 1.0f : 0.0f) << x << "," << y;
  // Intersected with the viewport (x 4..6): only x = 4 of the rectangle remains.
  img::Image u(7, 4);
  p.viewport.x = 4;
  p.viewport.width = 3;
  ASSERT_TRUE(cpu::draw(p, u, 1).ok());
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 7; ++x)
      EXPECT_EQ(u.at(x, y)[0], x == 4 && y >= 1 && y < 3 ? 1.0f : 0.0f) << x << "," << y;
  // An empty rectangle draws nothing.
  img::Image v(7, 4);
  p.scissor = ScissorRect{3, 3, 3, 4};
  ASSERT_TRUE(cpu::draw(p, v, 1).ok());
  for (float c : v.rgba) EXPECT_EQ(c, 0.0f);
}

} // namespace
} // namespace tierlift::pass
