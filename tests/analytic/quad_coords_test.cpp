// analytic::QuadCoords and the corner values extract_taps reads off a vertex listing: the model's
// fp32 texture coordinates. Checked three ways: values worked out by hand where the float
// arithmetic is exact (power-of-two sizes, offsets that are multiples of 2^-k); the
// diagonal's owner; and, at sizes that are not powers of two, every pixel of a full-screen
// pass that writes its interpolated coordinate, drawn by the interpreter (cpu::draw, whose
// Rounding::Llvmpipe interpolation is measured bit-exact against lavapipe).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "tierlift/analytic/quad_coords.h"
#include "tierlift/analytic/taps.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/cpu/draw.h"

namespace analytic = tierlift::analytic;
namespace cpu = tierlift::cpu;
namespace img = tierlift::img;
namespace ir = tierlift::ir;
namespace assembly = tierlift::assembly;

namespace {

std::shared_ptr<const ir::Program> parse(const std::string& text) {
  auto r = assembly::parse_text(text, "listing");
  EXPECT_TRUE(r.program.has_value()) << render_text(r.diags, r.sources);
  return r.program ? std::make_shared<const ir::Program>(*r.program) : nullptr;
}

constexpr const char* kCoordsVs = "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                                  "mad oT0, v3, c1, c0\n";
constexpr const char* kShowPs = "ps_2_0\ndcl t0\nmov oC0, t0\n";

} // namespace

// W = 4, H = 2, uv 0..1: every step is exact in fp32, so u = i/4 and v = j/2 (D3D9 centres)
// and u = (i + ½)/4, v = (j + ½)/2 (modern centres), on both sides of the diagonal.
TEST(QuadCoords, PowerOfTwoSizesGiveExactCentres) {
  const analytic::QuadCorners uv{{{0, 0}, {1, 0}, {0, 1}, {1, 1}}};
  const analytic::QuadCoords d3d9(uv, 4, 2, ir::PixelCenter::D3D9);
  const analytic::QuadCoords modern(uv, 4, 2, ir::PixelCenter::Modern);
  for (uint32_t j = 0; j < 2; ++j)
    for (uint32_t i = 0; i < 4; ++i) {
      EXPECT_EQ(d3d9.at(i, j)[0], float(i) / 4) << i << "," << j;
      EXPECT_EQ(d3d9.at(i, j)[1], float(j) / 2) << i << "," << j;
      EXPECT_EQ(modern.at(i, j)[0], (float(i) + 0.5f) / 4) << i << "," << j;
      EXPECT_EQ(modern.at(i, j)[1], (float(j) + 0.5f) / 2) << i << "," << j;
    }
}

// An offset quad (u from 1/8 to 1 + 1/8): still exact at W = 8.
TEST(QuadCoords, OffsetCornersShiftEveryPixel) {
  const analytic::QuadCorners uv{{{0.125f, 0}, {1.125f, 0}, {0.125f, 1}, {1.125f, 1}}};
  const analytic::QuadCoords q(uv, 8, 8, ir::PixelCenter::D3D9);
  for (uint32_t i = 0; i < 8; ++i) EXPECT_EQ(q.at(i, 5)[0], 0.125f + float(i) / 8) << i;
}

// extract_taps evaluates the vertex listing at the corners in fp32, one rounding per
// instruction: mad oT0, v3, c1, c0 with c1 = 3, c0 = 0.1 gives fl(fl(1·3) + fl(0.1)) at u = 1
// and fl(0.1) (0·3 is +0) at u = 0.
TEST(QuadCoords, ExtractTapsReadsCornerValuesInFp32) {
  auto vs = parse(kCoordsVs);
  auto ps = parse("ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n");
  ASSERT_TRUE(vs && ps);
  auto ex = analytic::extract_taps(*vs, {{0.1f, -0.2f, 0, 0}, {3, 0.5f, 0, 0}}, *ps, {});
  ASSERT_TRUE(ex) << ex.message();
  ASSERT_EQ(ex->taps.size(), 1u);
  ASSERT_TRUE(ex->taps[0].corners.has_value());
  const analytic::QuadCorners& c = *ex->taps[0].corners;
  EXPECT_EQ(c[0][0], 0.1f);
  EXPECT_EQ(c[0][1], -0.2f);
  EXPECT_EQ(c[1][0], 3.0f + 0.1f);
  EXPECT_EQ(c[2][1], 0.5f + -0.2f);
  EXPECT_EQ(c[3][0], 3.0f + 0.1f);
  EXPECT_EQ(c[3][1], 0.5f + -0.2f);
}

// Every pixel of the pass that writes its coordinate equals the model's, float for float,
// at sizes whose reciprocals are not floats, with the quad's uv offset and scaled, for both
// pixel-centre conventions.
TEST(QuadCoords, EqualsTheInterpretersInterpolationAtEveryPixel) {
  auto vs = parse(kCoordsVs);
  auto ps = parse(kShowPs);
  ASSERT_TRUE(vs && ps);
  struct Size {
    uint32_t w, h;
  };
  for (Size s : {Size{37, 23}, Size{641, 359}, Size{1280, 720}, Size{3, 1000}})
    for (ir::PixelCenter center : {ir::PixelCenter::D3D9, ir::PixelCenter::Modern})
      for (float offset : {0.0f, 0.5f / 37, -1.0f / 3}) {
        const std::vector<cpu::Vec4> consts{{offset, -offset, 0, 0}, {1, 0.99f, 0, 0}};
        cpu::Pass pass;
        pass.vertex_program = vs;
        pass.pixel_program = ps;
        pass.vs_constants.f = consts;
        pass.conventions.pixel_center = center;
        cpu::set_full_screen_quad(pass, 0);
        for (size_t k = 0; k < 4; ++k) pass.vertices[k].v[3] = cpu::kQuadUV[k];
        img::Image target(s.w, s.h, img::Format::RGBA32F);
        auto stats = cpu::draw(pass, target, 1);
        ASSERT_TRUE(stats.ok()) << stats.message();
        auto ex = analytic::extract_reads(*vs, {consts[0], consts[1]},
                                          *parse("ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\n"
                                                 "mov oC0, r0\n"));
        ASSERT_TRUE(ex) << ex.message();
        ASSERT_TRUE(ex->at(0).corners.has_value());
        const analytic::QuadCoords model(*(*ex)[0].corners, s.w, s.h, center);
        size_t differ = 0;
        for (uint32_t j = 0; j < s.h; ++j)
          for (uint32_t i = 0; i < s.w; ++i) {
            const auto uv = model.at(i, j);
            differ += uv[0] != target.at(i, j)[0] || uv[1] != target.at(i, j)[1];
          }
        EXPECT_EQ(differ, 0u) << s.w << "x" << s.h << " offset " << offset << " modern "
                              << (center == ir::PixelCenter::Modern);
      }
}
