// Coverage: the full-screen quad, the top-left fill rule on shared edges and on edges that
// pass exactly through pixel centres (docs/d3d9-rules.md §9.1). Counting is done with ONE/ONE
// blending of 1.0 on RGBA32F, so a pixel's value is the number of times it was drawn.
#include <gtest/gtest.h>

#include <numeric>

#include "draw_helpers.h"

namespace tierlift::ir {
// How a pixel centre prints in test listings (GetParam of QuadCoverage): found by argument-
// dependent lookup, so it lives in the enum's namespace.
static void PrintTo(PixelCenter c, std::ostream* os) {
  *os << (c == PixelCenter::D3D9 ? "D3D9 centres" : "modern centres");
}
} // namespace tierlift::ir

namespace tierlift::cpu {
namespace {

using test::flat_pass;
using test::screen_vertex;

// Draw count per pixel.
std::vector<int> counts(const img::Image& im) {
  std::vector<int> out;
  for (uint32_t y = 0; y < im.height; ++y)
    for (uint32_t x = 0; x < im.width; ++x) out.push_back(static_cast<int>(im.at(x, y)[0]));
  return out;
}

void expect_all(const img::Image& im, int n) {
  for (uint32_t y = 0; y < im.height; ++y)
    for (uint32_t x = 0; x < im.width; ++x)
      ASSERT_EQ(im.at(x, y)[0], static_cast<float>(n)) << "pixel " << x << "," << y;
}

// The triangles drawn white with ONE/ONE on a w×h target: each pixel holds its draw count.
img::Image draw_counting(std::vector<VertexOutput> tris, uint32_t w, uint32_t h) {
  img::Image im(w, h, img::Format::RGBA32F);
  ir::Result<DrawStats> s =
      draw(flat_pass(std::move(tris), {1, 1, 1, 1}, BlendMode::OneOne), im, 1);
  EXPECT_TRUE(s.ok()) << s.message();
  return im;
}

// Each pixel drawn once where inside(x, y) holds, and nowhere else.
template <class Inside> void expect_once_where(const img::Image& im, Inside inside) {
  for (uint32_t y = 0; y < im.height; ++y)
    for (uint32_t x = 0; x < im.width; ++x)
      EXPECT_EQ(im.at(x, y)[0], inside(x, y) ? 1.0f : 0.0f) << x << "," << y;
}

const char* centre_name(ir::PixelCenter c) {
  return c == ir::PixelCenter::D3D9 ? "D3D9" : "Modern";
}

class QuadCoverage : public ::testing::TestWithParam<std::tuple<int, int, ir::PixelCenter>> {};

TEST_P(QuadCoverage, EveryPixelExactlyOnce) {
  auto [w, h, centre] = GetParam();
  Pass p; // no vertex or pixel program: the full-screen quad with constant inputs
  p.constant_inputs.color[0] = {1, 1, 1, 1};
  p.blend = BlendMode::OneOne;
  p.conventions.pixel_center = centre;
  img::Image im(w, h, img::Format::RGBA32F);
  ir::Result<DrawStats> s = draw(p, im, 1);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->pixels_shaded, static_cast<uint64_t>(w) * h);
  expect_all(im, 1);
}

INSTANTIATE_TEST_SUITE_P(
    OddSizes, QuadCoverage,
    ::testing::Combine(::testing::Values(1, 7, 16, 33), ::testing::Values(1, 5, 3),
                       ::testing::Values(ir::PixelCenter::D3D9, ir::PixelCenter::Modern)),
    [](const ::testing::TestParamInfo<QuadCoverage::ParamType>& info) { // "7x5_D3D9"
      // std::get, not a structured binding: its commas would split the macro's arguments.
      return std::to_string(std::get<0>(info.param)) + "x" +
             std::to_string(std::get<1>(info.param)) + "_" + centre_name(std::get<2>(info.param));
    });

// The quad from a vertex list (the same two triangles, interpolated path) also covers
// every pixel exactly once: the shared diagonal goes through pixel centres on square
// targets with D3D9 centres, so the tie rule decides.
TEST(TopLeftRule, SharedDiagonalOfTheQuadDrawsOnce) {
  for (auto [w, h] : {std::pair{8u, 8u}, std::pair{7u, 5u}, std::pair{1u, 1u}}) {
    for (auto centre : {ir::PixelCenter::D3D9, ir::PixelCenter::Modern}) {
      std::vector<VertexOutput> v;
      for (int t = 0; t < 2; ++t)
        for (uint32_t k : kQuadTriangles[t]) {
          VertexOutput o;
          o.pos = kQuadCorners[k];
          v.push_back(o);
        }
      Pass p = flat_pass(v, {1, 1, 1, 1}, BlendMode::OneOne);
      p.conventions.pixel_center = centre;
      img::Image im(w, h, img::Format::RGBA32F);
      ASSERT_TRUE(draw(p, im, 1).ok());
      expect_all(im, 1);
    }
  }
}

// Square [0,4]² in D3D9 screen space split along the diagonal (0,0)-(4,4), whose pixel
// centres (i, i) lie exactly on the shared edge. Pixels with centres in [0,4)×[0,4) are
// drawn once (left and top edges in, right and bottom out); nothing else.
TEST(TopLeftRule, DiagonalThroughPixelCentres) {
  const uint32_t W = 8, H = 8;
  auto sv = [&](double x, double y) { return screen_vertex(x, y, W, H); };
  const img::Image im =
      draw_counting({sv(0, 0), sv(4, 0), sv(4, 4), sv(0, 0), sv(4, 4), sv(0, 4)}, W, H);
  expect_once_where(im, [](uint32_t x, uint32_t y) { return x < 4 && y < 4; });
}

// Four triangles fanned around the pixel centre (2,2): every pixel of [0,4)² exactly once,
// including (2,2) itself where all four meet.
TEST(TopLeftRule, FanAroundAPixelCentre) {
  const uint32_t W = 6, H = 6;
  auto sv = [&](double x, double y) { return screen_vertex(x, y, W, H); };
  VertexOutput c = sv(2, 2);
  const img::Image im = draw_counting(
      {c, sv(0, 0), sv(4, 0), c, sv(4, 0), sv(4, 4), c, sv(4, 4), sv(0, 4), c, sv(0, 4), sv(0, 0)},
      W, H);
  expect_once_where(im, [](uint32_t x, uint32_t y) { return x < 4 && y < 4; });
}

// Right triangle (0,0), (4,0), (0,4): the hypotenuse x + y = 4 runs through the centres
// (4,0), (3,1), …, (0,4) and is a right (bottom) edge, so those are out: 4+3+2+1 pixels.
TEST(TopLeftRule, HypotenuseThroughCentresIsExcluded) {
  const uint32_t W = 6, H = 6;
  auto sv = [&](double x, double y) { return screen_vertex(x, y, W, H); };
  for (bool flip : {false, true}) { // both windings give the same pixels
    SCOPED_TRACE(flip ? "flipped" : "as written");
    const img::Image im = flip ? draw_counting({sv(0, 0), sv(0, 4), sv(4, 0)}, W, H)
                               : draw_counting({sv(0, 0), sv(4, 0), sv(0, 4)}, W, H);
    expect_once_where(im, [](uint32_t x, uint32_t y) { return x + y < 4; });
    const std::vector<int> n = counts(im);
    EXPECT_EQ(std::accumulate(n.begin(), n.end(), 0), 10);
  }
}

// The mirrored triangle (4,0), (4,4), (0,4) has the same hypotenuse as a top-left edge:
// together with the one above it covers [0,4)² exactly once.
TEST(TopLeftRule, ComplementaryTrianglesTile) {
  const uint32_t W = 6, H = 6;
  auto sv = [&](double x, double y) { return screen_vertex(x, y, W, H); };
  const img::Image im =
      draw_counting({sv(0, 0), sv(4, 0), sv(0, 4), sv(4, 0), sv(4, 4), sv(0, 4)}, W, H);
  std::vector<int> got = counts(im), want;
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) want.push_back(x < 4 && y < 4 ? 1 : 0);
  EXPECT_EQ(got, want);
}

// A triangle far larger than the guard band is clipped into a fan; the fan's inner edges
// must not draw any pixel twice, and the whole 5×5 target lies inside it.
TEST(Clipping, HugeTriangleCoversOnce) {
  const uint32_t W = 5, H = 5;
  auto sv = [&](double x, double y) { return screen_vertex(x, y, W, H); };
  Pass p =
      flat_pass({sv(-100, -100), sv(200, -100), sv(-100, 200)}, {1, 1, 1, 1}, BlendMode::OneOne);
  img::Image im(W, H, img::Format::RGBA32F);
  ir::Result<DrawStats> s = draw(p, im, 1);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_GT(s->triangles, 1u); // really clipped
  expect_all(im, 1);
}

// Entirely behind the eye (w < 0): nothing is drawn. One vertex behind: clipped, finite.
TEST(Clipping, BehindTheEye) {
  const uint32_t W = 5, H = 5;
  auto behind = [&](double x, double y) { return screen_vertex(x, y, W, H, -1.0f); };
  Pass p = flat_pass({behind(0, 0), behind(4, 0), behind(0, 4)}, {1, 1, 1, 1}, BlendMode::OneOne);
  img::Image im(W, H, img::Format::RGBA32F);
  ir::Result<DrawStats> s = draw(p, im, 1);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->triangles, 0u);
  expect_all(im, 0);

  Pass q = flat_pass({screen_vertex(0, 0, W, H), screen_vertex(4, 0, W, H), behind(0, 4)},
                     {1, 1, 1, 1}, BlendMode::OneOne);
  ASSERT_TRUE(draw(q, im, 1).ok());
  for (float v : im.rgba) EXPECT_TRUE(v == 0.0f || v == 1.0f);
}

} // namespace
} // namespace tierlift::cpu
