// The CPU device's output merger beyond one target: D3D9's stencil test and operations
// against a table written out by hand from the D3DCMPFUNC / D3DSTENCILOP definitions
// (docs/d3d9-rules.md, "Stencil"), and a ps_2_0 pass writing oC0 and oC1 into two targets.
#include <gtest/gtest.h>

#include "program_helpers.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/pass/pass.h"
#include "tierlift/pass/stencil.h"

namespace tierlift::pass {
namespace {

using cpu::test::parsed;

TEST(Stencil, OperationsMatchTheHandTable) {
  DepthStencilState s;
  s.stencil_ref = 0x3c;
  struct Row {
    StencilOp op;
    uint8_t stored, expected;
  };
  const Row rows[] = {
      {StencilOp::Keep, 0x5a, 0x5a},    {StencilOp::Zero, 0x5a, 0x00},
      {StencilOp::Replace, 0x5a, 0x3c}, {StencilOp::IncrSat, 0x5a, 0x5b},
      {StencilOp::IncrSat, 0xff, 0xff}, {StencilOp::DecrSat, 0x5a, 0x59},
      {StencilOp::DecrSat, 0x00, 0x00}, {StencilOp::Invert, 0x5a, 0xa5},
      {StencilOp::Incr, 0xff, 0x00},    {StencilOp::Incr, 0x00, 0x01},
      {StencilOp::Decr, 0x00, 0xff},    {StencilOp::Decr, 0x01, 0x00},
  };
  for (const Row& r : rows)
    EXPECT_EQ(stencil_update(r.op, s, r.stored), r.expected)
        << int(r.op) << " on " << int(r.stored);
  // Write mask 0x0f: only the low four bits change. 0x5a inverted is 0xa5; keep 0x5_, take _5.
  s.stencil_write_mask = 0x0f;
  EXPECT_EQ(stencil_update(StencilOp::Invert, s, 0x5a), 0x55);
  EXPECT_EQ(stencil_update(StencilOp::Replace, s, 0xf0), 0xfc); // 0x3c's low bits: c
  EXPECT_EQ(stencil_update(StencilOp::Incr, s, 0x2f), 0x20);    // 0x30 & 0x0f = 0
}

TEST(Stencil, TestPutsTheReferenceOnTheLeft) {
  DepthStencilState s;
  s.stencil_ref = 2;
  // (ref FUNC stored) for stored 1, 2, 3.
  struct Row {
    CompareFunc f;
    bool at1, at2, at3;
  };
  const Row rows[] = {
      {CompareFunc::Never, false, false, false},      {CompareFunc::Less, false, false, true},
      {CompareFunc::Equal, false, true, false},       {CompareFunc::LessEqual, false, true, true},
      {CompareFunc::Greater, true, false, false},     {CompareFunc::NotEqual, true, false, true},
      {CompareFunc::GreaterEqual, true, true, false}, {CompareFunc::Always, true, true, true},
  };
  for (const Row& r : rows) {
    s.stencil_func = r.f;
    EXPECT_EQ(stencil_test(s, 1), r.at1) << int(r.f);
    EXPECT_EQ(stencil_test(s, 2), r.at2) << int(r.f);
    EXPECT_EQ(stencil_test(s, 3), r.at3) << int(r.f);
  }
  // Read mask 0x0f: 0x12 and 0x02 compare equal to the reference 2.
  s.stencil_func = CompareFunc::Equal;
  s.stencil_read_mask = 0x0f;
  EXPECT_TRUE(stencil_test(s, 0x12));
  EXPECT_FALSE(stencil_test(s, 0x13));
}

Pass mrt_pass() {
  Pass p;
  p.vertex_program = parsed("vs_2_0\ndcl_position v0\nmov oPos, v0\n");
  p.pixel_program = parsed("ps_2_0\nmov oC0, c0\nmov oC1, c1\n");
  set_full_screen_quad(p, 0);
  p.ps_constants.f = {Vec4{0.25f, 0.5f, 0.75f, 1}, Vec4{1, 0, 0.5f, 0.125f}};
  return p;
}

// mrt_pass drawn into the two colour targets t0 and t1.
ir::Result<cpu::DrawStats> draw_two(img::Image& t0, img::Image& t1) {
  Pass p = mrt_pass();
  p.color_targets = 2;
  cpu::DrawTargets targets;
  targets.color = {&t0, &t1, nullptr, nullptr};
  return cpu::draw(p, targets, 1);
}

TEST(Mrt, EachTargetReceivesItsOwnOutput) {
  img::Image t0(4, 3), t1(4, 3);
  ir::Result<cpu::DrawStats> s = draw_two(t0, t1);
  ASSERT_TRUE(s.ok()) << s.message();
  for (uint32_t y = 0; y < 3; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      EXPECT_EQ((Vec4{t0.at(x, y)[0], t0.at(x, y)[1], t0.at(x, y)[2], t0.at(x, y)[3]}),
                (Vec4{0.25f, 0.5f, 0.75f, 1}));
      EXPECT_EQ((Vec4{t1.at(x, y)[0], t1.at(x, y)[1], t1.at(x, y)[2], t1.at(x, y)[3]}),
                (Vec4{1, 0, 0.5f, 0.125f}));
    }
  // One target: oC1 goes nowhere, as D3D9 drops outputs without a bound target.
  Pass p = mrt_pass();
  p.color_targets = 1;
  img::Image only(4, 3);
  ASSERT_TRUE(cpu::draw(p, only, 1).ok());
  EXPECT_EQ(only.at(3, 2)[0], 0.25f);
}

TEST(Mrt, TargetsOfDifferentSizesAreRefused) {
  img::Image t0(4, 3), t1(4, 4);
  ir::Result<cpu::DrawStats> s = draw_two(t0, t1);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("one size"), std::string::npos) << s.message();
  for (float v : t0.rgba) EXPECT_EQ(v, 0.0f);
}

TEST(Mrt, OC1WithoutOC0IsAPositionedValidatorError) {
  auto r = assembly::parse_text("ps_2_0\nmov oC1, c1\n", "mrt.psh");
  ASSERT_TRUE(r.program);
  ir::DiagnosticSink sink;
  EXPECT_FALSE(assembly::validate(*r.program, sink));
  const std::string text = ir::render_text(sink, r.sources);
  EXPECT_NE(text.find("mrt.psh:"), std::string::npos) << text;
  EXPECT_NE(text.find("oC0"), std::string::npos) << text;
  EXPECT_NE(text.find("error"), std::string::npos) << text;
}

// The left half (x < 2 of 4) is marked with REPLACE ref 7, then a full-screen pass with
// EQUAL 0 writes colour only on the right, and INCRSAT counts the passes that reached a pixel.
TEST(Stencil, MarkThenMaskOnTheCpuDevice) {
  Pass mark;
  mark.transformed.resize(3);
  // A triangle covering pixels x = 0, 1 of a 4×2 target (D3D9 centres at integer x): the
  // edge x_s = 1.5 lies between sample points 1 and 2.
  const float xe = 2.0f * 1.5f / 4.0f - 1.0f; // clip x of screen x 1.5
  mark.transformed[0].pos = {-2, 3, 0, 1};
  mark.transformed[1].pos = {xe, 3, 0, 1};
  mark.transformed[2].pos = {xe, -3, 0, 1};
  mark.transformed.push_back({});
  mark.transformed[3].pos = {-2, -3, 0, 1};
  mark.triangles = {{0, 1, 2}, {0, 2, 3}};
  mark.depth_stencil.stencil_test = true;
  mark.depth_stencil.stencil_func = CompareFunc::Always;
  mark.depth_stencil.stencil_pass = StencilOp::Replace;
  mark.depth_stencil.stencil_ref = 7;
  img::Image color(4, 2);
  std::vector<uint8_t> stencil(8, 0);
  cpu::DrawTargets targets;
  targets.color[0] = &color;
  targets.stencil = stencil.data();
  ASSERT_TRUE(cpu::draw(mark, targets, 1).ok());
  EXPECT_EQ(stencil, (std::vector<uint8_t>{7, 7, 0, 0, 7, 7, 0, 0}));

  Pass masked;
  masked.constant_inputs.color[0] = {1, 1, 1, 1};
  masked.depth_stencil.stencil_test = true;
  masked.depth_stencil.stencil_func = CompareFunc::Equal;
  masked.depth_stencil.stencil_ref = 0;
  masked.depth_stencil.stencil_pass = StencilOp::IncrSat;
  masked.depth_stencil.stencil_fail = StencilOp::Keep;
  img::Image out(4, 2);
  targets.color[0] = &out;
  ASSERT_TRUE(cpu::draw(masked, targets, 1).ok());
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 4; ++x) EXPECT_EQ(out.at(x, y)[0], x < 2 ? 0.0f : 1.0f) << x;
  EXPECT_EQ(stencil, (std::vector<uint8_t>{7, 7, 1, 1, 7, 7, 1, 1}));
}

} // namespace
} // namespace tierlift::pass
