// Vertex texture fetch (NUMERICS.md F14): a vs_3_0's texldl reads the pass's vertex samplers
// (pass::Pass::vertex_textures, Direct3D 9's D3DVERTEXTEXTURESAMPLER0..3) on the CPU device
// and on lavapipe, with the pixel stage's filtering, addressing and mip rules at the lod src.w
// gives. Every expected value is worked out by hand from the texels in the comments; both
// devices must meet it exactly.
#include <array>

#include "tierlift/pass/mip_chain.h"
#include "vk_test_util.h"

namespace tierlift::vulkan::test {
namespace {

constexpr uint32_t kW = 8, kH = 8;

// A w × h RGBA32F image whose texel (i, j) is f(i, j).
template <class F> std::shared_ptr<const img::Image> image(uint32_t w, uint32_t h, F f) {
  auto im = std::make_shared<img::Image>(w, h, img::Format::RGBA32F);
  for (uint32_t j = 0; j < h; ++j)
    for (uint32_t i = 0; i < w; ++i) {
      const std::array<float, 4> t = f(static_cast<float>(i), static_cast<float>(j));
      for (int c = 0; c < 4; ++c) im->rgba[(size_t{j} * w + i) * 4 + c] = t[c];
    }
  return im;
}

// The full-screen quad with a pass-through position; the vertex listing reads vertex sampler
// `sampler` at c0 with texldl and hands the texel to the pixel stage through texcoord0,
// which the pixel listing writes out. Every vertex reads the same texel, so the (equal)
// outputs reach every pixel unchanged.
cpu::Pass read_pass(const std::string& sampler) {
  cpu::Pass pass;
  pass.vertex_program = parse_listing("vs_3_0\n"
                                      "dcl_position v0\n"
                                      "dcl_2d s0\n"
                                      "dcl_2d s1\n"
                                      "dcl_position o0\n"
                                      "dcl_texcoord0 o1\n"
                                      "mov o0, v0\n"
                                      "texldl r0, c0, " +
                                          sampler + "\nmov o1, r0\n",
                                      "vtf.vsh");
  pass.pixel_program = parse_listing("ps_3_0\ndcl_texcoord0 v0\nmov oC0, v0\n", "vtf.psh");
  pass::set_full_screen_quad(pass, 0);
  pass.conventions.pixel_center = ir::PixelCenter::Modern;
  return pass;
}

// Texel (i, j) of level 0: (i + 1, 10(j + 1), −(i + 1), i/2), a 4 × 2 texture.
std::shared_ptr<const img::Image> level0() {
  return image(4, 2, [](float i, float j) {
    return std::array<float, 4>{i + 1, 10 * (j + 1), -(i + 1), 0.5f * i};
  });
}

struct ReadCase {
  const char* name;
  pass::Filter filter;
  std::array<float, 4> c0; // u, v, (unused), lod
  std::array<float, 4> want;
};

// Level 0 only: the lod changes nothing (one level, rule F11), whatever its value.
//   POINT (0.625, 0.75): u·4 = 2.5 → texel 2, v·2 = 1.5 → row 1: (3, 20, −3, 1).
//   LINEAR (0.5, 0.75): u·4 − 0.5 = 1.5 → texels 1 and 2 half each; v·2 − 0.5 = 1 → row 1
//     alone: (2.5, 20, −2.5, 0.75).
//   LINEAR (0.5, 0.5): v·2 − 0.5 = 0.5 → rows 0 and 1 half each: (2.5, 15, −2.5, 0.75).
//   POINT far outside, CLAMP: u = 1e10 or 1e30 → the last column, texel 3: (4, 20, −4, 1.5);
//     u = −1e10 → texel 0: (1, 20, −1, 0); v = 1e10 → the last row, 1. (u·4 beyond the int
//     range read texel 0 on lavapipe until its vertex stage clamped the coordinate too,
//     CodegenOptions::vertex_point_clamped: generated vs_3_0 case 00071 of seed 1.)
const ReadCase kReads[] = {
    {"point", pass::Filter::Point, {0.625f, 0.75f, 0, 3}, {3, 20, -3, 1}},
    {"point_negative_lod", pass::Filter::Point, {0.625f, 0.75f, 0, -5}, {3, 20, -3, 1}},
    {"linear_between_columns", pass::Filter::Linear, {0.5f, 0.75f, 0, 0}, {2.5f, 20, -2.5f, 0.75f}},
    {"linear_between_four", pass::Filter::Linear, {0.5f, 0.5f, 0, 7}, {2.5f, 15, -2.5f, 0.75f}},
    {"point_clamp_far_right", pass::Filter::Point, {1e10f, 0.75f, 0, 0}, {4, 20, -4, 1.5f}},
    {"point_clamp_farther_right", pass::Filter::Point, {1e30f, 0.75f, 0, 0}, {4, 20, -4, 1.5f}},
    {"point_clamp_far_left", pass::Filter::Point, {-1e10f, 0.75f, 0, 0}, {1, 20, -1, 0}},
    {"point_clamp_far_down", pass::Filter::Point, {0.625f, 1e10f, 0, 0}, {3, 20, -3, 1}},
};

void expect_every_pixel(const img::Image& im, const std::array<float, 4>& want,
                        const std::string& what) {
  for (uint32_t p = 0; p < im.width * im.height; ++p)
    for (int c = 0; c < 4; ++c)
      ASSERT_EQ(im.rgba[p * 4 + c], want[c]) << what << " pixel " << p << " channel " << c;
}

TEST_F(VulkanTest, VertexTextureFetchReadsTheTexelByFilter) {
  for (const ReadCase& rc : kReads) {
    cpu::Pass pass = read_pass("s1");
    pass.vs_constants.f = {{rc.c0[0], rc.c0[1], rc.c0[2], rc.c0[3]}};
    pass::TextureBinding& b = pass.vertex_textures[1];
    b.image = level0();
    b.sampler.filter = rc.filter;
    b.sampler.address_u = b.sampler.address_v = pass::AddressMode::Clamp;
    const TwoWays t = draw_both(*dev, pass, kW, kH, img::Format::RGBA32F);
    ASSERT_TRUE(t.ok) << rc.name;
    expect_every_pixel(t.cpu, rc.want, std::string("cpu ") + rc.name);
    expect_every_pixel(t.vk, rc.want, std::string("vulkan ") + rc.name);
  }
}

TEST_F(VulkanTest, VertexTextureFetchOfAnUnboundSamplerIsOpaqueBlack) {
  // s0 has no texture (s1 has one): (0, 0, 0, 1) on both devices, as an unbound pixel stage.
  cpu::Pass pass = read_pass("s0");
  pass.vs_constants.f = {{0.625f, 0.75f, 0, 0}};
  pass.vertex_textures[1].image = level0();
  const TwoWays t = draw_both(*dev, pass, kW, kH, img::Format::RGBA32F);
  ASSERT_TRUE(t.ok);
  expect_every_pixel(t.cpu, {0, 0, 0, 1}, "cpu");
  expect_every_pixel(t.vk, {0, 0, 0, 1}, "vulkan");
}

TEST_F(VulkanTest, VertexTextureFetchTakesTheMipLevelOfItsLod) {
  // A chain of three levels, MIPFILTER POINT: 4 × 2 (level0() above), 2 × 1 with texel i =
  // (100(i + 1), 0, 0, 1), 1 × 1 (500, 0, 0, 1). POINT at (0.75, 0.25): level 0 → texel
  // (3, 0) = (4, 10, −4, 1.5); lod 1 → level 1, u·2 = 1.5 → texel 1 = (200, 0, 0, 1); lod 9
  // → clamped to the last level, (500, 0, 0, 1); lod −3 → level 0 (rules M1, M2).
  std::vector<std::shared_ptr<const img::Image>> levels = {
      level0(),
      image(2, 1,
            [](float i, float) {
              return std::array<float, 4>{100 * (i + 1), 0, 0, 1};
            }),
      image(1, 1, [](float, float) {
        return std::array<float, 4>{500, 0, 0, 1};
      })};
  ir::Result<pass::TextureBinding> chain = pass::mipmapped_binding(levels);
  ASSERT_TRUE(chain) << chain.message();
  const std::pair<float, std::array<float, 4>> cases[] = {{0.0f, {4, 10, -4, 1.5f}},
                                                          {1.0f, {200, 0, 0, 1}},
                                                          {9.0f, {500, 0, 0, 1}},
                                                          {-3.0f, {4, 10, -4, 1.5f}}};
  for (const auto& [lod, want] : cases) {
    cpu::Pass pass = read_pass("s1");
    pass.vs_constants.f = {{0.75f, 0.25f, 0, lod}};
    pass::TextureBinding& b = pass.vertex_textures[1];
    b = *chain;
    b.sampler.mip.filter = pass::MipFilter::Point;
    b.sampler.address_u = b.sampler.address_v = pass::AddressMode::Clamp;
    const TwoWays t = draw_both(*dev, pass, kW, kH, img::Format::RGBA32F);
    ASSERT_TRUE(t.ok) << "lod " << lod;
    expect_every_pixel(t.cpu, want, "cpu lod " + std::to_string(lod));
    expect_every_pixel(t.vk, want, "vulkan lod " + std::to_string(lod));
  }
}

// A height field, as bgfx's terrain sample draws it: the quad's top vertices are lifted by
// the height their texldl reads, y = −1 + 2h; the bottom ones stay at y = −1. The 2 × 1 height
// texture holds h = 0.125 and 0.875; the top-left vertex reads it at u = 0.375, the top-right
// at u = 0.625. POINT: u·2 = 0.75 → 0.125, 1.25 → 0.875. LINEAR: u·2 − 0.5 = 0.25 and 0.75 →
// 0.125 + 0.25·0.75 = 0.3125 and 0.125 + 0.75·0.75 = 0.6875.
// The top edge then runs from y_l to y_r across the 8 × 8 target, at row (1 − y)/2·8 of pixel
// space; a pixel is drawn white where its centre lies below it (no centre lies on it: each
// row there is a multiple of 1/16 off k + ½). Independent of the sampler code: the heights
// are the hand-computed ones.
TEST_F(VulkanTest, VertexTextureFetchDisplacesTheGeometryByAHeightTexture) {
  const char* vs = "vs_3_0\n"
                   "def c0, 0, 2, 0, 0\n"
                   "dcl_position v0\n"
                   "dcl_texcoord0 v1\n"
                   "dcl_2d s0\n"
                   "dcl_position o0\n"
                   "texldl r0, v1, s0\n"    // (u, 0.5, top, lod 0)
                   "mul r0.x, r0.x, v1.z\n" // h at the top vertices, 0 at the bottom ones
                   "mul r0.x, r0.x, c0.y\n" // 2h
                   "mov r1, v0\n"
                   "add r1.y, r1.y, r0.x\n"
                   "mov o0, r1\n";
  const char* ps = "ps_3_0\ndef c0, 1, 1, 1, 1\nmov oC0, c0\n";
  const auto heights = image(2, 1, [](float i, float) {
    return std::array<float, 4>{i == 0 ? 0.125f : 0.875f, 0, 0, 1};
  });
  struct Case {
    pass::Filter filter;
    float h_left, h_right;
  };
  for (const Case& c :
       {Case{pass::Filter::Point, 0.125f, 0.875f}, Case{pass::Filter::Linear, 0.3125f, 0.6875f}}) {
    cpu::Pass pass;
    pass.vertex_program = parse_listing(vs, "terrain.vsh");
    pass.pixel_program = parse_listing(ps, "terrain.psh");
    pass.conventions.pixel_center = ir::PixelCenter::Modern;
    pass.vertices.assign(4, cpu::VertexInput{});
    const float u[4] = {0.375f, 0.625f, 0.375f, 0.625f}; // TL, TR, BL, BR
    for (int k = 0; k < 4; ++k) {
      pass.vertices[k].v[0] = {pass::kQuadCorners[k][0], -1, 0, 1};
      pass.vertices[k].v[1] = {u[k], 0.5f, k < 2 ? 1.0f : 0.0f, 0};
    }
    pass.triangles.assign(pass::kQuadTriangles.begin(), pass::kQuadTriangles.end());
    pass::TextureBinding& b = pass.vertex_textures[0];
    b.image = heights;
    b.sampler.filter = c.filter;
    b.sampler.address_u = b.sampler.address_v = pass::AddressMode::Clamp;
    const TwoWays t = draw_both(*dev, pass, kW, kH, img::Format::RGBA32F);
    ASSERT_TRUE(t.ok);
    const float y_l = -1 + 2 * c.h_left, y_r = -1 + 2 * c.h_right;
    size_t drawn = 0;
    for (uint32_t py = 0; py < kH; ++py)
      for (uint32_t px = 0; px < kW; ++px) {
        const float x = (static_cast<float>(px) + 0.5f) / kW; // 0..1 across
        const float edge_row = (1 - (y_l + (y_r - y_l) * x)) / 2 * kH;
        const bool covered = static_cast<float>(py) + 0.5f > edge_row;
        drawn += covered;
        const float want = covered ? 1.0f : 0.0f;
        for (const img::Image* im : {&t.cpu, &t.vk})
          for (int ch = 0; ch < 4; ++ch)
            ASSERT_EQ(im->at(px, py)[ch], want)
                << (im == &t.cpu ? "cpu" : "vulkan") << " pixel " << px << "," << py
                << (c.filter == pass::Filter::Point ? " point" : " linear");
      }
    // POINT: the edge rises 0.75 rows a column from row 7, columns hold 1, 2, 3, 4, 4, 5, 6, 7
    // drawn rows; LINEAR: 0.375 a column from row 5.5, 3, 3, 3, 4, 4, 5, 5, 5. 32 either way.
    EXPECT_EQ(drawn, 32u);
  }
}

} // namespace
} // namespace tierlift::vulkan::test
