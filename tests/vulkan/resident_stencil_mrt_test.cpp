// The Vulkan device's output merger beyond one target (TextureSet with RenderTargets): a
// ps_2_0 pass writing oC0 and oC1 into two textures, and D3D9's stencil test and operations on
// an 8-bit stencil buffer. Expected values are the D3DCMPFUNC / D3DSTENCILOP definitions
// worked out by hand in the comments (the same table tests/cpu_draw/stencil_mrt_test.cpp
// checks the CPU device against); the device runs with validation and synchronization
// validation on, so a missing barrier between the stencil's uses fails the test too.
#include <optional>

#include "resident_fixture.h"

namespace tierlift::vulkan::test {
namespace {

constexpr uint32_t kW = 8, kH = 2;

// A pass without programs: the full-screen quad with oD0 = c at every pixel, limited to the
// columns x0..x0+w−1 by its viewport (the scissor is the viewport: edges are exact).
cpu::Pass columns(cpu::Vec4 c, int32_t x0, uint32_t w) {
  cpu::Pass p;
  p.constant_inputs.color[0] = c;
  p.viewport.x = x0;
  p.viewport.width = w;
  p.viewport.height = kH;
  return p;
}

// The stencil value of column x, read back (red channel; the other channels are 0).
uint32_t stencil_at(const img::Image& s, uint32_t x, uint32_t y = 0) {
  return static_cast<uint32_t>(s.at(x, y)[0]);
}

TEST_F(ResidentTest, TwoRenderTargetsReceiveOC0AndOC1) {
  TextureSet set(*dev);
  TextureId a{}, b{};
  ASSERT_TRUE(succeeded(set.create(kW, kH, img::Format::RGBA32F), a));
  ASSERT_TRUE(succeeded(set.create(kW, kH, img::Format::RGBA8), b));
  cpu::Pass p;
  p.vertex_program = parse_listing("vs_2_0\ndcl_position v0\nmov oPos, v0\n", "pos.vsh");
  p.pixel_program = parse_listing("ps_2_0\nmov oC0, c0\nmov oC1, c1\n", "mrt.psh");
  cpu::set_full_screen_quad(p, 0);
  p.ps_constants.f = {cpu::Vec4{0.25f, 0.5f, 0.75f, 1}, cpu::Vec4{1, 0, 0.5f, 0.125f}};
  p.color_targets = 2;
  RenderTargets t;
  t.color = {a, b, TextureId::None, TextureId::None};
  ir::Result<pass::DrawReport> r = set.draw(p, StageTextures{}, t);
  ASSERT_TRUE(r.ok()) << r.message();
  img::Image out_a, out_b;
  ASSERT_TRUE(succeeded(set.read(a), out_a));
  ASSERT_TRUE(succeeded(set.read(b), out_b));
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      const float* pa = out_a.at(x, y);
      const float* pb = out_b.at(x, y);
      EXPECT_EQ((cpu::Vec4{pa[0], pa[1], pa[2], pa[3]}), (cpu::Vec4{0.25f, 0.5f, 0.75f, 1}));
      // RGBA8 stores round(v·255): 0.5 → 127.5 → 128, 0.125 → 31.875 → 32.
      EXPECT_EQ((cpu::Vec4{pb[0], pb[1], pb[2], pb[3]}),
                (cpu::Vec4{1, 0, 128.0f / 255, 32.0f / 255}));
    }
}

TEST_F(ResidentTest, MrtPassesThatCannotBeDrawnAreRefused) {
  TextureSet set(*dev);
  TextureId a{}, b{}, small{};
  ASSERT_TRUE(succeeded(set.create(kW, kH, img::Format::RGBA32F), a));
  ASSERT_TRUE(succeeded(set.create(kW, kH, img::Format::RGBA32F), b));
  ASSERT_TRUE(succeeded(set.create(kW, kH + 1, img::Format::RGBA32F), small));
  cpu::Pass p;
  p.vertex_program = parse_listing("vs_2_0\ndcl_position v0\nmov oPos, v0\n", "pos.vsh");
  p.pixel_program = parse_listing("ps_2_0\nmov oC0, c0\n", "one.psh");
  cpu::set_full_screen_quad(p, 0);
  p.color_targets = 2;
  RenderTargets t;
  t.color = {a, b, TextureId::None, TextureId::None};
  // Two targets, but the program writes oC0 only: Vulkan would leave target 1 undefined.
  ir::Result<pass::DrawReport> r = set.draw(p, StageTextures{}, t);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("does not write oC1"), std::string::npos) << r.message();
  // Target 1 missing; targets of two sizes.
  p.pixel_program = parse_listing("ps_2_0\nmov oC0, c0\nmov oC1, c0\n", "two.psh");
  t.color[1] = TextureId::None;
  r = set.draw(p, StageTextures{}, t);
  EXPECT_NE(r.message().find("render target 1 (oC1) is not bound"), std::string::npos)
      << r.message();
  t.color[1] = small;
  r = set.draw(p, StageTextures{}, t);
  EXPECT_NE(r.message().find("one size"), std::string::npos) << r.message();
  // A stencil test without a stencil buffer.
  p.color_targets = 1;
  t.color[1] = TextureId::None;
  p.depth_stencil.stencil_test = true;
  r = set.draw(p, StageTextures{}, t);
  EXPECT_NE(r.message().find("no stencil buffer"), std::string::npos) << r.message();
  img::Image out;
  ASSERT_TRUE(succeeded(set.read(a), out));
  EXPECT_EQ(out.rgba, std::vector<float>(kW * kH * 4, 0.0f)); // nothing was drawn
}

TEST_F(ResidentTest, StencilBufferStartsAtZeroAndIsNeverUploaded) {
  TextureSet set(*dev);
  TextureId s{};
  ASSERT_TRUE(succeeded(set.create_stencil(kW, kH), s));
  img::Image out;
  ASSERT_TRUE(succeeded(set.read(s), out));
  EXPECT_EQ(out.format, img::Format::RGBA32F);
  EXPECT_EQ(out.rgba, std::vector<float>(kW * kH * 4, 0.0f));
  EXPECT_NE(set.upload(s, img::Image(kW, kH)).message().find("stencil buffer"), std::string::npos);
}

// Marks columns 0..3 with REPLACE ref 7, then draws everywhere with EQUAL 0: colour reaches
// columns 4..7 only, and INCRSAT on pass counts the passes that reached a pixel there.
TEST_F(ResidentTest, StencilMarksThenMasks) {
  TextureSet set(*dev);
  TextureId color{}, s{};
  ASSERT_TRUE(succeeded(set.create(kW, kH, img::Format::RGBA32F), color));
  ASSERT_TRUE(succeeded(set.create_stencil(kW, kH), s));
  RenderTargets t;
  t.color[0] = color;
  t.stencil = s;
  cpu::Pass mark = columns({0.5f, 0.5f, 0.5f, 1}, 0, 4);
  mark.depth_stencil.stencil_test = true;
  mark.depth_stencil.stencil_func = pass::CompareFunc::Always;
  mark.depth_stencil.stencil_pass = pass::StencilOp::Replace;
  mark.depth_stencil.stencil_ref = 7;
  ASSERT_TRUE(set.draw(mark, StageTextures{}, t).ok());
  cpu::Pass masked = columns({1, 1, 1, 1}, 0, kW);
  masked.depth_stencil.stencil_test = true;
  masked.depth_stencil.stencil_func = pass::CompareFunc::Equal;
  masked.depth_stencil.stencil_ref = 0;
  masked.depth_stencil.stencil_pass = pass::StencilOp::IncrSat;
  ASSERT_TRUE(set.draw(masked, StageTextures{}, t).ok());
  img::Image c, st;
  ASSERT_TRUE(succeeded(set.read(color), c));
  ASSERT_TRUE(succeeded(set.read(s), st));
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      EXPECT_EQ(c.at(x, y)[0], x < 4 ? 0.5f : 1.0f) << x;
      EXPECT_EQ(stencil_at(st, x, y), x < 4 ? 7u : 1u) << x;
    }
}

// Each operation and each comparison on one stored value per column (columns set up by
// REPLACE draws), checked against the values worked out from the definitions.
TEST_F(ResidentTest, StencilOperationsAndComparisonsFollowD3D9) {
  // Stored values per column: 0, 1, 5, 0x5a, 0xfe, 0xff, 0x12, 0x13.
  const uint32_t stored[kW] = {0, 1, 5, 0x5a, 0xfe, 0xff, 0x12, 0x13};
  auto fresh = [&](TextureSet& set, RenderTargets& t) {
    TextureId color{}, s{};
    EXPECT_TRUE(succeeded(set.create(kW, kH, img::Format::RGBA32F), color));
    EXPECT_TRUE(succeeded(set.create_stencil(kW, kH), s));
    t.color[0] = color;
    t.stencil = s;
    for (uint32_t x = 0; x < kW; ++x) {
      cpu::Pass p = columns({0, 0, 0, 1}, int32_t(x), 1);
      p.depth_stencil.stencil_test = true;
      p.depth_stencil.stencil_pass = pass::StencilOp::Replace;
      p.depth_stencil.stencil_ref = stored[x];
      EXPECT_TRUE(set.draw(p, StageTextures{}, t).ok());
    }
  };
  // One full-width draw over freshly stored columns, its stencil state set by `state`, and
  // then the stencil (or the colour) target read back; nothing when the draw or read failed.
  auto draw_and_read = [&](auto state, bool stencil) -> std::optional<img::Image> {
    TextureSet set(*dev);
    RenderTargets t;
    fresh(set, t);
    cpu::Pass p = columns({1, 1, 1, 1}, 0, kW);
    p.depth_stencil.stencil_test = true;
    state(p.depth_stencil);
    img::Image out;
    if (!set.draw(p, StageTextures{}, t).ok() ||
        !succeeded(set.read(stencil ? t.stencil : t.color[0]), out))
      return std::nullopt;
    return out;
  };
  struct OpCase {
    pass::StencilOp op;
    uint32_t write_mask;
    uint32_t want[kW];
  };
  // ref = 0x3c. INCRSAT/DECRSAT clamp at 255/0, INCR/DECR wrap, INVERT flips all 8 bits;
  // with write mask 0x0f only the low nibble changes: INVERT of 0x5a → 0x55.
  const OpCase ops[] = {
      {pass::StencilOp::Keep, 0xff, {0, 1, 5, 0x5a, 0xfe, 0xff, 0x12, 0x13}},
      {pass::StencilOp::Zero, 0xff, {0, 0, 0, 0, 0, 0, 0, 0}},
      {pass::StencilOp::Replace, 0xff, {0x3c, 0x3c, 0x3c, 0x3c, 0x3c, 0x3c, 0x3c, 0x3c}},
      {pass::StencilOp::IncrSat, 0xff, {1, 2, 6, 0x5b, 0xff, 0xff, 0x13, 0x14}},
      {pass::StencilOp::DecrSat, 0xff, {0, 0, 4, 0x59, 0xfd, 0xfe, 0x11, 0x12}},
      {pass::StencilOp::Invert, 0xff, {0xff, 0xfe, 0xfa, 0xa5, 0x01, 0x00, 0xed, 0xec}},
      {pass::StencilOp::Incr, 0xff, {1, 2, 6, 0x5b, 0xff, 0x00, 0x13, 0x14}},
      {pass::StencilOp::Decr, 0xff, {0xff, 0, 4, 0x59, 0xfd, 0xfe, 0x11, 0x12}},
      {pass::StencilOp::Invert, 0x0f, {0x0f, 0x0e, 0x0a, 0x55, 0xf1, 0xf0, 0x1d, 0x1c}},
  };
  for (const OpCase& oc : ops) {
    SCOPED_TRACE(testing::Message() << "op " << int(oc.op) << " mask " << oc.write_mask);
    const std::optional<img::Image> st = draw_and_read(
        [&](auto& ds) {
          ds.stencil_pass = oc.op;
          ds.stencil_ref = 0x3c;
          ds.stencil_write_mask = oc.write_mask;
        },
        true);
    ASSERT_TRUE(st);
    for (uint32_t x = 0; x < kW; ++x) EXPECT_EQ(stencil_at(*st, x), oc.want[x]) << "column " << x;
  }
  struct FuncCase {
    pass::CompareFunc f;
    uint32_t read_mask;
    bool want[kW];
  };
  // ref = 5 on the left: LESS passes where 5 < stored. Read mask 0x0f: 0x12 & 0x0f = 2,
  // 0x13 & 0x0f = 3, 0x5a & 0x0f = 0xa, 0xfe & 0x0f = 0xe, 0xff & 0x0f = 0xf.
  const FuncCase funcs[] = {
      {pass::CompareFunc::Never, 0xff, {0, 0, 0, 0, 0, 0, 0, 0}},
      {pass::CompareFunc::Less, 0xff, {0, 0, 0, 1, 1, 1, 1, 1}},
      {pass::CompareFunc::Equal, 0xff, {0, 0, 1, 0, 0, 0, 0, 0}},
      {pass::CompareFunc::LessEqual, 0xff, {0, 0, 1, 1, 1, 1, 1, 1}},
      {pass::CompareFunc::Greater, 0xff, {1, 1, 0, 0, 0, 0, 0, 0}},
      {pass::CompareFunc::NotEqual, 0xff, {1, 1, 0, 1, 1, 1, 1, 1}},
      {pass::CompareFunc::GreaterEqual, 0xff, {1, 1, 1, 0, 0, 0, 0, 0}},
      {pass::CompareFunc::Always, 0xff, {1, 1, 1, 1, 1, 1, 1, 1}},
      {pass::CompareFunc::Greater, 0x0f, {1, 1, 0, 0, 0, 0, 1, 1}},
  };
  for (const FuncCase& fc : funcs) {
    SCOPED_TRACE(testing::Message() << "func " << int(fc.f) << " read mask " << fc.read_mask);
    const std::optional<img::Image> c = draw_and_read(
        [&](auto& ds) {
          ds.stencil_func = fc.f;
          ds.stencil_ref = 5;
          ds.stencil_read_mask = fc.read_mask;
        },
        false);
    ASSERT_TRUE(c);
    for (uint32_t x = 0; x < kW; ++x)
      EXPECT_EQ(c->at(x, 1)[0], fc.want[x] ? 1.0f : 0.0f) << "column " << x;
  }
}

} // namespace
} // namespace tierlift::vulkan::test
