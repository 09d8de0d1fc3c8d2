// draw() with the block executor (Executor::Auto) against draw() with the per-pixel VM
// (Executor::Scalar, the reference): the glow's and the article's passes over random textures,
// in every conventions mode (lavapipe and exact rounding, both pixel centres, ps_1_x clamp and
// fixed-point modes), every target format and blend mode, every address mode, both filters,
// one and two threads, odd sizes (partial blocks) and random perspective triangles: the two
// images must be identical byte for byte, and the block path must really have run.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "draw_helpers.h"
#include "program_helpers.h"
#include "random_passes.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/cpu/draw.h"

namespace tierlift::cpu {
namespace {

using test::listing_file;

std::shared_ptr<const img::Image> random_image(uint32_t w, uint32_t h, std::mt19937& rng, float lo,
                                               float hi) {
  auto im = std::make_shared<img::Image>(w, h, img::Format::RGBA32F);
  std::uniform_real_distribution<float> u(lo, hi);
  for (float& v : im->rgba) v = u(rng);
  return im;
}

struct PassCase {
  const char* vs;
  const char* ps;
  int stages; // sampler stages bound
};

const PassCase kCases[] = {
    {"gpugems21/listing1_blur8_coords.vsh", "gpugems21/listing2_blur8_weighted_sum.psh", 1},
    {"gpugems21/listing3_blur4_coords.vsh", "gpugems21/listing4_blur4_weighted_sum.psh", 4},
    {"glow/quad4_coords.vsh", "glow/downsample4.psh", 1},
    {"glow/quad4_coords.vsh", "glow/extract_sources.psh", 1},
    {"glow/quad4_coords.vsh", "glow/composite_add.psh", 2},
    {"glow/quad4_coords_vs11.vsh", "glow/downsample4_ps13.psh", 4},
    {"glow/quad4_coords_vs11.vsh", "glow/extract_sources_ps11.psh", 1},
    {"glow/quad4_coords_vs11.vsh", "glow/composite_add_x4_ps13.psh", 2},
};

// Draws `pass` into copies of `start` with both executors; they must match byte for byte.
void expect_identical(Pass pass, const img::Image& start, unsigned threads,
                      const std::string& what) {
  SCOPED_TRACE(what);
  img::Image block = start, scalar = start;
  pass.executor = Executor::Auto;
  const ir::Result<DrawStats> a = draw(pass, block, threads);
  pass.executor = Executor::Scalar;
  const ir::Result<DrawStats> b = draw(pass, scalar, threads);
  ASSERT_TRUE(a.ok()) << a.message();
  ASSERT_TRUE(b.ok()) << b.message();
  EXPECT_GT(a->pixels_shaded, 0u);
  EXPECT_EQ(a->pixels_block, a->pixels_shaded); // the block path ran every pixel
  EXPECT_EQ(b->pixels_block, 0u);
  EXPECT_EQ(a->pixels_shaded, b->pixels_shaded);
  EXPECT_EQ(a->pixels_killed, b->pixels_killed);
  ASSERT_EQ(block.rgba.size(), scalar.rgba.size());
  size_t differ = 0;
  for (size_t i = 0; i < block.rgba.size(); ++i)
    if (std::memcmp(&block.rgba[i], &scalar.rgba[i], sizeof(float)) != 0) ++differ;
  EXPECT_EQ(differ, 0u) << "values that differ between the executors";
}

ir::Conventions mode(int m) {
  ir::Conventions c;
  switch (m) {
  case 1: c.rounding = ir::Rounding::Exact; break;
  case 2: c.pixel_center = ir::PixelCenter::Modern; break;
  case 3: c.ps1x_max_value = 8.0f; break;
  case 4: c.ps1x_fixed_bits = 8; break;
  case 5:
    c.rounding = ir::Rounding::Exact;
    c.subtexel_bits = 8;
    break;
  default: break;
  }
  return c;
}

// The case's quad pass with random constants: vs c0..c3 small texcoord offsets, c4..c7
// near one, ps c0..c7 weights in [-0.5, 1.5) passed through `weight` (which may swap one for
// a denormal).
template <class Weight>
Pass random_quad_pass(const std::shared_ptr<const ir::Program>& vs,
                      const std::shared_ptr<const ir::Program>& ps, std::mt19937& rng,
                      Weight weight) {
  Pass pass;
  pass.vertex_program = vs;
  pass.pixel_program = ps;
  set_full_screen_quad(pass, 0);
  for (auto& v : pass.vertices) v.v[3] = {0, 0, 0, 1};
  for (size_t c = 0; c < 4; ++c) pass.vertices[c].v[3] = kQuadUV[c];
  std::uniform_real_distribution<float> off(-0.05f, 0.05f), wt(-0.5f, 1.5f);
  for (int k = 0; k < 8; ++k) {
    pass.vs_constants.f.push_back({off(rng), off(rng), 0, 0});
    pass.ps_constants.f.push_back(
        {weight(wt(rng)), weight(wt(rng)), weight(wt(rng)), weight(wt(rng))});
  }
  for (int k = 4; k < 8; ++k) pass.vs_constants.f[k] = {1 + off(rng), 1 + off(rng), 1, 1};
  return pass;
}

TEST(ExecutorIdentity, GlowAndArticlePassesInEveryMode) {
  std::mt19937 rng(7);
  const img::Format formats[] = {img::Format::RGBA8, img::Format::RGBA16F, img::Format::RGBA32F};
  const BlendMode blends[] = {BlendMode::Replace, BlendMode::OneOne, BlendMode::SrcAlphaOne,
                              BlendMode::SrcAlphaInvSrcAlpha};
  const AddressMode addresses[] = {AddressMode::Clamp, AddressMode::Wrap, AddressMode::Mirror,
                                   AddressMode::Border, AddressMode::MirrorOnce};
  int run = 0;
  for (const PassCase& pc : kCases) {
    auto vs = listing_file(pc.vs);
    auto ps = listing_file(pc.ps);
    ASSERT_TRUE(vs && ps);
    for (int m = 0; m < 6; ++m) {
      ++run;
      const uint32_t w = 37 + static_cast<uint32_t>(run % 5) * 7,
                     h = 23 + static_cast<uint32_t>(run % 3);
      Pass pass = random_quad_pass(vs, ps, rng, [](float x) { return x; });
      // Texture values beyond [0, 1] reach the ps_1_x clamps.
      for (int s = 0; s < pc.stages; ++s) {
        TextureBinding& b = pass.textures[s];
        b.image = random_image(19 + 4 * s, 13 + 3 * s, rng, -0.5f, 1.5f);
        b.sampler.filter = (run + s) % 4 == 0 ? Filter::Point : Filter::Linear;
        b.sampler.address_u = addresses[(run + s) % 5];
        b.sampler.address_v = addresses[(run + 2 * s + 1) % 5];
        b.sampler.border_color = {0.25f, 0.5f, 0.75f, 1.0f};
      }
      pass.conventions = mode(m);
      pass.blend = blends[run % 4];
      const img::Format format = formats[run % 3];
      img::Image start(w, h, format);
      std::uniform_real_distribution<float> u(0.0f, 1.0f);
      for (float& v : start.rgba) v = u(rng);
      img::quantize_in_place(start);
      expect_identical(pass, start, 1 + static_cast<unsigned>(run % 2),
                       std::string(pc.ps) + " mode " + std::to_string(m));
      if (HasFatalFailure()) return;
    }
  }
}

// Perspective triangles (w ≠ 1, partly off screen, both windings) with a program that reads
// colours and coordinates and kills some pixels: partial blocks at every edge, blocks with
// killed lanes among written ones, perspective-correct inputs, onto RGBA32F and RGBA8
// targets that start with random content (each blend mode reads it).
TEST(ExecutorIdentity, RandomPerspectiveTriangles) {
  std::mt19937 rng(11);
  const BlendMode blends[] = {BlendMode::SrcAlphaInvSrcAlpha, BlendMode::Replace, BlendMode::OneOne,
                              BlendMode::SrcAlphaOne};
  for (int m = 0; m < 3; ++m)
    for (int f = 0; f < 2; ++f) {
      Pass pass = test::random_perspective_pass(rng, 24, 71, 53);
      pass.conventions = mode(m);
      pass.blend = blends[(m + 3 * f) % 4];
      img::Image start = *random_image(71, 53, rng, -0.25f, 1.25f);
      start.format = f ? img::Format::RGBA8 : img::Format::RGBA32F;
      img::quantize_in_place(start);
      expect_identical(pass, start, 2,
                       "mode " + std::to_string(m) + " format " + std::to_string(f));
    }
}

// Half the texels, constants and vertex attributes denormals of both signs, or normals so near
// 2^-126 that a product with 1/w or a filter weight becomes one (NUMERICS.md rule 13):
// bilinear filtering and llvmpipe interpolation flush them, point sampling and RGBA32F stores
// keep their bits, the shader's operations flush them in lavapipe's mode and keep them in the
// exact one; the block path must do each of these as the per-pixel path does.
// Interpolating between ±2^-122 or ±2^-120 over a triangle crosses the denormal band a few
// pixels from the zero line, where the plane's value or its product with 1/w is denormal.
float tiny(std::mt19937& rng) {
  static const float kTiny[] = {1e-40f,
                                -1e-40f,
                                0x1p-149f,
                                -0x1p-149f,
                                0x1.fffffcp-127f,
                                -0x1.fffffcp-127f,
                                0x1p-126f,
                                -0x1p-126f,
                                0x1p-125f,
                                -0x1p-125f,
                                0x1.8p-125f,
                                -0x1.8p-125f,
                                0x1p-122f,
                                -0x1p-122f,
                                0x1p-120f,
                                -0x1p-120f,
                                -0.0f};
  std::uniform_int_distribution<size_t> pick(0, std::size(kTiny) - 1);
  return kTiny[pick(rng)];
}
float denormal_or(float ordinary, std::mt19937& rng) {
  std::uniform_int_distribution<int> coin(0, 1);
  return coin(rng) ? tiny(rng) : ordinary;
}

std::shared_ptr<const img::Image> denormal_image(uint32_t w, uint32_t h, std::mt19937& rng) {
  auto im = std::make_shared<img::Image>(w, h, img::Format::RGBA32F);
  std::uniform_real_distribution<float> u(-0.5f, 1.5f);
  for (float& v : im->rgba) v = denormal_or(u(rng), rng);
  return im;
}

TEST(ExecutorIdentity, DenormalTexelsConstantsAndAttributes) {
  std::mt19937 rng(13);
  int run = 0;
  for (const PassCase& pc : kCases) {
    auto vs = listing_file(pc.vs);
    auto ps = listing_file(pc.ps);
    ASSERT_TRUE(vs && ps);
    for (int m : {0, 1, 4}) {
      ++run;
      Pass pass = random_quad_pass(vs, ps, rng, [&rng](float x) { return denormal_or(x, rng); });
      for (int s = 0; s < pc.stages; ++s) {
        TextureBinding& b = pass.textures[s];
        b.image = denormal_image(19 + 4 * s, 13 + 3 * s, rng);
        b.sampler.filter = (run + s) % 2 == 0 ? Filter::Point : Filter::Linear;
        b.sampler.address_u = (run + s) % 3 == 0 ? AddressMode::Border : AddressMode::Wrap;
        b.sampler.address_v = AddressMode::Clamp;
        b.sampler.border_color = {1e-40f, -1e-40f, 0x1p-149f, 1.0f};
      }
      pass.conventions = mode(m);
      pass.blend = run % 2 ? BlendMode::Replace : BlendMode::OneOne;
      img::Image start(41, 29, run % 3 ? img::Format::RGBA32F : img::Format::RGBA16F);
      for (float& v : start.rgba) v = denormal_or(0.25f, rng);
      img::quantize_in_place(start);
      expect_identical(pass, start, 1 + static_cast<unsigned>(run % 2),
                       std::string(pc.ps) + " mode " + std::to_string(m) + " with denormals");
      if (HasFatalFailure()) return;
    }
  }
  // Vertex colours and coordinates with denormals reach interpolation and texkill; the second
  // program moves the interpolated coordinates to the RGBA32F target untouched, so a denormal
  // that interpolation should have flushed shows in the image.
  const char* const programs[] = {
      "ps_2_0\ndcl v0\ndcl t0\ndcl t1\ndcl_2d s0\ntexld r0, t0, s0\nmad r0, r0, v0, t1\n"
      "texkill t1\nmov oC0, r0\n",
      "ps_2_0\ndcl t0\ndcl t1\nmov r0, t1\nmov r0.zw, t0\nmov oC0, r0\n"};
  std::uniform_real_distribution<double> pos(-20.0, 90.0);
  std::uniform_real_distribution<float> val(-0.5f, 1.5f), wclip(0.5f, 3.0f);
  for (const char* text : programs)
    for (int m = 0; m < 2; ++m) {
      Pass pass;
      pass.pixel_program =
          std::make_shared<const ir::Program>(*assembly::parse_text(text, "<test>").program);
      for (int i = 0; i < 24; ++i) {
        VertexOutput v = test::screen_vertex(pos(rng), pos(rng), 71, 53, wclip(rng));
        // Every other triangle tiny at all three vertices: its planes and their products
        // with 1/w lie at the denormal boundary.
        const bool all_tiny = (i / 3) % 2 == 0;
        for (int c = 0; c < 4; ++c) {
          v.color[0][c] = all_tiny ? tiny(rng) : denormal_or(val(rng), rng);
          v.tex[0][c] = all_tiny ? tiny(rng) : denormal_or(val(rng), rng);
          v.tex[1][c] = all_tiny ? tiny(rng) : denormal_or(val(rng), rng);
        }
        pass.transformed.push_back(v);
      }
      pass.textures[0].image = denormal_image(17, 11, rng);
      pass.textures[0].sampler.filter = m == 0 ? Filter::Linear : Filter::Point;
      pass.conventions = mode(m);
      img::Image start(71, 53, img::Format::RGBA32F);
      expect_identical(pass, start, 2, std::string(text) + " mode " + std::to_string(m));
    }
}

} // namespace
} // namespace tierlift::cpu
