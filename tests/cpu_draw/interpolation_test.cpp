// Where pixels sample the primitive (D3D9 vs modern centres, §9.2), perspective-correct
// interpolation with w ≠ 1, and thread-count independence.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "draw_helpers.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"

namespace tierlift::cpu {
namespace {

using test::flat_pass;
using test::screen_vertex;

// The quad's corners as pre-transformed vertices with (u, v) = quad UV in oD0.
Pass uv_quad(ir::PixelCenter centre) {
  std::vector<VertexOutput> v;
  for (const auto& tri : kQuadTriangles)
    for (uint32_t k : tri) {
      VertexOutput o;
      o.pos = kQuadCorners[k];
      o.color[0] = kQuadUV[k];
      v.push_back(o);
    }
  Pass p;
  p.transformed = v;
  p.conventions.pixel_center = centre;
  return p;
}

// uv_quad on a 7×5 target: pixel (x, y) interpolates uv ((x + at)/W, (y + at)/H).
void expect_quad_uv(ir::PixelCenter centre, double at) {
  const uint32_t W = 7, H = 5;
  img::Image im(W, H, img::Format::RGBA32F);
  ASSERT_TRUE(draw(uv_quad(centre), im, 1).ok());
  for (uint32_t y = 0; y < H; ++y)
    for (uint32_t x = 0; x < W; ++x) {
      EXPECT_NEAR(im.at(x, y)[0], (x + at) / W, 1e-6) << x << "," << y;
      EXPECT_NEAR(im.at(x, y)[1], (y + at) / H, 1e-6) << x << "," << y;
    }
}

TEST(PixelCentres, D3D9QuadInterpolatesTexelCorners) {
  expect_quad_uv(ir::PixelCenter::D3D9, 0); // u = x/W: the texel corners
}

TEST(PixelCentres, ModernQuadInterpolatesTexelCentres) {
  expect_quad_uv(ir::PixelCenter::Modern, 0.5); // u = (x + ½)/W: the texel centres
}

// Screen triangle A(0,0) w=1, B(8,0) w=4, C(0,8) w=1 with u = (0,1,0), v = (0,0,1).
// Screen-space weights at (x, y): λB = x/8, λC = y/8, λA = 1 − λB − λC; perspective-correct
// u = (λB/4) / (λA + λB/4 + λC), v = λC / (same).
//   (4,0): λ = (0.5, 0.5, 0)  → u = 0.125/0.625 = 0.2,  v = 0
//   (2,2): λ = (0.5, 0.25, 0.25) → u = 0.0625/0.8125 = 1/13, v = 0.25/0.8125 = 4/13
//   (0,4): λ = (0.5, 0, 0.5)  → u = 0, v = 0.5
TEST(Interpolation, PerspectiveCorrectWithW) {
  const uint32_t W = 10, H = 10;
  VertexOutput a = screen_vertex(0, 0, W, H, 1), b = screen_vertex(8, 0, W, H, 4),
               c = screen_vertex(0, 8, W, H, 1);
  a.color[0] = {0, 0, 0, 1};
  b.color[0] = {1, 0, 0, 1};
  c.color[0] = {0, 1, 0, 1};
  Pass p;
  p.transformed = {a, b, c};
  img::Image im(W, H, img::Format::RGBA32F);
  ASSERT_TRUE(draw(p, im, 1).ok());
  EXPECT_NEAR(im.at(4, 0)[0], 0.2, 1e-6);
  EXPECT_NEAR(im.at(4, 0)[1], 0.0, 1e-6);
  EXPECT_NEAR(im.at(2, 2)[0], 1.0 / 13, 1e-6);
  EXPECT_NEAR(im.at(2, 2)[1], 4.0 / 13, 1e-6);
  EXPECT_NEAR(im.at(0, 4)[0], 0.0, 1e-6);
  EXPECT_NEAR(im.at(0, 4)[1], 0.5, 1e-6);
  // Screen-linear interpolation would give u = 0.5 at (4,0): make sure we are not that.
  EXPECT_GT(std::abs(im.at(4, 0)[0] - 0.5f), 0.1f);
}

// oD# is saturated before interpolation: a vertex colour of 3 reads as 1.
TEST(Interpolation, ColoursSaturated) {
  Pass p;
  for (const auto& tri : kQuadTriangles)
    for (uint32_t k : tri) {
      VertexOutput o;
      o.pos = kQuadCorners[k];
      o.color[0] = {3, -2, 0.5f, 1};
      p.transformed.push_back(o);
    }
  img::Image im(3, 3, img::Format::RGBA32F);
  ASSERT_TRUE(draw(p, im, 1).ok());
  EXPECT_FLOAT_EQ(im.at(1, 1)[0], 1.0f);
  EXPECT_FLOAT_EQ(im.at(1, 1)[1], 0.0f);
  EXPECT_NEAR(im.at(1, 1)[2], 0.5f, 1e-6);
}

// Many overlapping triangles with additive blending: the image is bit-identical whatever
// the number of worker threads.
TEST(Threads, SameImageForAnyThreadCount) {
  const uint32_t W = 61, H = 47;
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> pos(-10, 70), col(0, 1);
  std::vector<VertexOutput> v;
  for (int i = 0; i < 90; ++i) {
    VertexOutput o = screen_vertex(pos(rng), pos(rng), W, H, static_cast<float>(0.5 + col(rng)));
    o.color[0] = {static_cast<float>(col(rng)), static_cast<float>(col(rng)),
                  static_cast<float>(col(rng)), 0.5f};
    v.push_back(o);
  }
  Pass p;
  p.transformed = v;
  p.blend = BlendMode::SrcAlphaInvSrcAlpha;
  img::Image one(W, H, img::Format::RGBA32F), many(W, H, img::Format::RGBA32F),
      all(W, H, img::Format::RGBA32F);
  ASSERT_TRUE(draw(p, one, 1).ok());
  ASSERT_TRUE(draw(p, many, 3).ok());
  ASSERT_TRUE(draw(p, all, 0).ok());
  ASSERT_EQ(std::memcmp(one.rgba.data(), many.rgba.data(), one.rgba.size() * sizeof(float)), 0);
  ASSERT_EQ(std::memcmp(one.rgba.data(), all.rgba.data(), one.rgba.size() * sizeof(float)), 0);
  double sum = 0;
  for (float f : one.rgba) sum += f;
  EXPECT_GT(sum, 0.0); // something was drawn
}

TEST(DrawErrors, BadRequestsAreRefusedNotCrashed) {
  Pass p;
  p.transformed.resize(3);
  p.triangles = {{0, 1, 7}};
  img::Image im(4, 4, img::Format::RGBA32F);
  ir::Result<DrawStats> s = draw(p, im, 1);
  EXPECT_FALSE(s.ok());
  EXPECT_FALSE(s.message().empty());
  img::Image broken;
  broken.width = 5; // buffer (empty) does not match 5×2
  broken.height = 2;
  EXPECT_FALSE(draw(Pass{}, broken, 1).ok());
}

} // namespace
} // namespace tierlift::cpu

namespace tierlift::cpu {
namespace {

// texkill discards pixels whose t0 has a negative component. t0.x = u − 0.45 with D3D9
// centres on an 8-wide quad is i/8 − 0.45: pixels 0..3 are killed (≤ −0.075), 4..7 drawn.
TEST(PixelStage, TexkillDiscards) {
  auto parsed =
      assembly::parse_text("ps_2_0\ndef c0, 1, 1, 1, 1\ndcl t0\ntexkill t0\nmov oC0, c0\n");
  ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  ASSERT_TRUE(assembly::validate(*parsed.program, parsed.diags))
      << ir::render_text(parsed.diags, parsed.sources);
  Pass p;
  p.pixel_program = std::make_shared<const ir::Program>(*parsed.program);
  for (const auto& tri : kQuadTriangles)
    for (uint32_t k : tri) {
      VertexOutput o;
      o.pos = kQuadCorners[k];
      o.tex[0] = {kQuadUV[k][0] - 0.45f, 0, 0, 1};
      p.transformed.push_back(o);
    }
  img::Image im(8, 3, img::Format::RGBA32F);
  ir::Result<DrawStats> s = draw(p, im, 2);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(s->pixels_shaded, 24u);
  EXPECT_EQ(s->pixels_killed, 12u);
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 8; ++x) EXPECT_EQ(im.at(x, y)[0], x < 4 ? 0.0f : 1.0f) << x;
}

} // namespace
} // namespace tierlift::cpu
