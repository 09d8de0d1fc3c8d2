// D3D9's depth buffer on both devices (pass/depth.h; NUMERICS.md D1-D5): each pass is drawn by
// the CPU device (cpu::draw with DrawTargets::depth) and by the Vulkan device (TextureSet with a
// D32_SFLOAT depth buffer), and both results are checked against values worked out by hand in
// the comments — the depth buffer bit for bit, and the colour (1 where the pixel passed, the
// target's 0 where it did not). The target is 8x2, so the quad's u at column i is i/8 exactly
// (D3D9 pixel centres) and every expected depth is a short binary fraction.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "resident_fixture.h"
#include "tierlift/pass/depth.h"

namespace tierlift::vulkan::test {
namespace {

constexpr uint32_t kW = 8, kH = 2;
using pass::CompareFunc;

struct Drawn {
  img::Image color;
  std::vector<float> depth; // kW × kH, row by row
};

// `p` drawn by one device into a zeroed RGBA32F target with a depth buffer starting at `start`.
ir::Result<Drawn> draw_cpu(const cpu::Pass& p, const std::vector<float>& start) {
  Drawn out{img::Image(kW, kH, img::Format::RGBA32F), start};
  cpu::DrawTargets t;
  t.color[0] = &out.color;
  t.depth = out.depth.data();
  ir::Result<cpu::DrawStats> s = cpu::draw(p, t, 1);
  if (!s) return std::move(s).failure();
  return out;
}

ir::Result<Drawn> draw_vulkan(Device& dev, const cpu::Pass& p, const std::vector<float>& start) {
  TextureSet set(dev);
  ir::Result<TextureId> color = set.create(kW, kH, img::Format::RGBA32F);
  ir::Result<TextureId> depth = set.create_depth(kW, kH, 0.0f);
  if (!color) return std::move(color).failure();
  if (!depth) return std::move(depth).failure();
  img::Image in(kW, kH);
  for (size_t i = 0; i < start.size(); ++i) in.rgba[4 * i] = start[i];
  if (ir::Status up = set.upload(*depth, in); !up) return std::move(up).failure();
  RenderTargets t;
  t.color[0] = *color;
  t.depth = *depth;
  if (ir::Result<pass::DrawReport> r = set.draw(p, StageTextures{}, t); !r)
    return std::move(r).failure();
  ir::Result<img::Image> c = set.read(*color);
  ir::Result<img::Image> z = set.read(*depth);
  if (!c) return std::move(c).failure();
  if (!z) return std::move(z).failure();
  Drawn out{std::move(*c), {}};
  for (size_t i = 0; i < size_t{kW} * kH; ++i) out.depth.push_back(z->rgba[4 * i]);
  return out;
}

// The quad with uv at t0 (u = i/8 at column i), z per corner (TL, TR, BL, BR), and `ps`.
cpu::Pass depth_pass(const char* ps, CompareFunc func, bool write = true,
                     std::array<float, 4> z = {0, 0, 0, 0}) {
  cpu::Pass p;
  p.vertex_program = parse_listing("vs_2_0\ndcl_position v0\ndcl_texcoord v1\nmov oPos, v0\n"
                                   "mov oT0, v1\n",
                                   "uv.vsh");
  p.pixel_program = parse_listing(ps, "depth.psh");
  pass::set_full_screen_quad_uv(p);
  for (size_t c = 0; c < 4; ++c) p.vertices[c].v[0][2] = z[c];
  p.depth_stencil.depth_test = true;
  p.depth_stencil.depth_write = write;
  p.depth_stencil.depth_func = func;
  p.ps_constants.f = {cpu::Vec4{0.5f, 0, 0, 0}, cpu::Vec4{1, 1, 1, 1}};
  return p;
}

// Both devices draw `p` from `start`; each must give `depth` bit for bit and colour 1 exactly
// where `drawn` says (0 elsewhere).
void expect_both(Device& dev, const cpu::Pass& p, const std::vector<float>& start,
                 const std::vector<float>& depth, const std::vector<bool>& drawn) {
  for (int device = 0; device < 2; ++device) {
    SCOPED_TRACE(device == 0 ? "cpu" : "vulkan");
    ir::Result<Drawn> d = device == 0 ? draw_cpu(p, start) : draw_vulkan(dev, p, start);
    ASSERT_TRUE(d.ok()) << d.message();
    for (size_t i = 0; i < size_t{kW} * kH; ++i) {
      EXPECT_EQ(std::bit_cast<uint32_t>(d->depth[i]), std::bit_cast<uint32_t>(depth[i]))
          << "pixel " << i << ": " << d->depth[i] << ", expected " << depth[i];
      EXPECT_EQ(d->color.rgba[4 * i], drawn[i] ? 1.0f : 0.0f) << "pixel " << i;
    }
  }
}

std::vector<float> filled(float v) {
  return std::vector<float>(size_t{kW} * kH, v);
}

// Column i of both rows holds i/8: 0, 0.125, …, 0.875.
std::vector<float> column_ramp() {
  std::vector<float> z;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) z.push_back(static_cast<float>(x) / 8);
  return z;
}

constexpr const char* kConstantDepth = "ps_2_0\nmov oC0, c1\nmov oDepth, c0.x\n";

TEST_F(ResidentTest, DepthOfAConstantODepthIsStored) {
  // oDepth = c0.x = 0.5 < the clear 1.0 under LESSEQUAL: every pixel passes, stores 0.5.
  expect_both(*dev, depth_pass(kConstantDepth, CompareFunc::LessEqual), filled(1.0f), filled(0.5f),
              std::vector<bool>(kW * kH, true));
}

TEST_F(ResidentTest, DepthOfATexcoordRampIsStored) {
  // oDepth = u = i/8 at column i, ALWAYS: the buffer holds the ramp itself.
  const char* ps = "ps_2_0\ndcl t0.xy\nmov oC0, c1\nmov oDepth, t0.x\n";
  expect_both(*dev, depth_pass(ps, CompareFunc::Always), filled(1.0f), column_ramp(),
              std::vector<bool>(kW * kH, true));
}

TEST_F(ResidentTest, ODepthOutsideTheRangeIsClamped) {
  // −0.5 → 0, 1.5 → 1, NaN → 0 (rule 23's saturate), −0 → +0; ALWAYS stores each.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::pair<float, float> cases[] = {
      {-0.5f, 0.0f}, {1.5f, 1.0f}, {nan, 0.0f}, {-0.0f, 0.0f}, {0.75f, 0.75f}};
  for (const auto& [written, stored] : cases) {
    SCOPED_TRACE(written);
    cpu::Pass p = depth_pass(kConstantDepth, CompareFunc::Always);
    p.ps_constants.f[0] = cpu::Vec4{written, 0, 0, 0};
    expect_both(*dev, p, filled(0.25f), filled(stored), std::vector<bool>(kW * kH, true));
  }
}

TEST_F(ResidentTest, EachZFuncAgainstAVaryingDepthBuffer) {
  // The buffer holds i/8 at column i; every pixel brings 0.5 (column 4's value). Passing
  // columns, worked out from "0.5 FUNC i/8" (i/8 < 0.5 for i < 4, = for i = 4, > for i > 4):
  struct Row {
    CompareFunc func;
    std::array<bool, kW> pass;
  };
  const bool T = true, F = false;
  const Row rows[] = {
      {CompareFunc::Never, {F, F, F, F, F, F, F, F}},
      {CompareFunc::Less, {F, F, F, F, F, T, T, T}},         // 0.5 < i/8: i > 4
      {CompareFunc::Equal, {F, F, F, F, T, F, F, F}},        // i = 4
      {CompareFunc::LessEqual, {F, F, F, F, T, T, T, T}},    // i ≥ 4
      {CompareFunc::Greater, {T, T, T, T, F, F, F, F}},      // i < 4
      {CompareFunc::NotEqual, {T, T, T, T, F, T, T, T}},     // i ≠ 4
      {CompareFunc::GreaterEqual, {T, T, T, T, T, F, F, F}}, // i ≤ 4
      {CompareFunc::Always, {T, T, T, T, T, T, T, T}},
  };
  for (const Row& r : rows)
    for (bool write : {true, false}) {
      SCOPED_TRACE(fmt::format("{} write {}", pass::compare_func_name(r.func), write));
      std::vector<float> depth = column_ramp();
      std::vector<bool> drawn;
      for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
          drawn.push_back(r.pass[x]);
          // ZWRITEENABLE off: the buffer keeps its ramp where the pixel passed too.
          if (r.pass[x] && write) depth[y * kW + x] = 0.5f;
        }
      expect_both(*dev, depth_pass(kConstantDepth, r.func, write), column_ramp(), depth, drawn);
    }
}

TEST_F(ResidentTest, KilledPixelsWriteNoDepth) {
  // texkill of (u − 0.5, v, 0): columns 0..3 (u < 0.5) are killed and keep the clear 1.0 and
  // colour 0; columns 4..7 store oDepth 0.5 under ALWAYS.
  const char* ps = "ps_2_0\ndcl t0\nsub r0, t0, c0\ntexkill r0\nmov oC0, c1\n"
                   "mov oDepth, c0.x\n";
  std::vector<float> depth;
  std::vector<bool> drawn;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      drawn.push_back(x >= 4);
      depth.push_back(x >= 4 ? 0.5f : 1.0f);
    }
  expect_both(*dev, depth_pass(ps, CompareFunc::Always), filled(1.0f), depth, drawn);
}

TEST_F(ResidentTest, Ps14TexdepthWritesItsRatioClamped) {
  // texdepth: r5.r / r5.g = u/v with r5 = (u, v, 0) = (i/8, j/2). Row 0: v = 0, so the depth is
  // 1.0 (rule 30); row 1: (i/8)/(1/2) = i/4, clamped to 1 from column 4 on.
  const char* ps = "ps.1.4\ntexcrd r5.rgb, t0\nphase\ntexdepth r5\nmov r0, c1\n";
  std::vector<float> depth;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x)
      depth.push_back(y == 0 ? 1.0f : std::min(1.0f, static_cast<float>(x) / 4));
  expect_both(*dev, depth_pass(ps, CompareFunc::Always), filled(0.25f), depth,
              std::vector<bool>(kW * kH, true));
}

TEST_F(ResidentTest, InterpolatedDepthWithoutODepth) {
  // No oDepth: the pixel's depth is the interpolated z/w. Corner z 0.25 (left) and 0.75
  // (right) make z = 0.5 + 0.25·x_ndc, and column i samples x_ndc = 2i/8 − 1, so the buffer
  // takes 0.25 + i/16 under ALWAYS.
  const char* ps = "ps_2_0\nmov oC0, c1\n";
  std::vector<float> depth;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) depth.push_back(0.25f + static_cast<float>(x) / 16);
  expect_both(*dev, depth_pass(ps, CompareFunc::Always, true, {0.25f, 0.75f, 0.25f, 0.75f}),
              filled(1.0f), depth, std::vector<bool>(kW * kH, true));
  // LESS against the clear 0.5: columns whose z is below 0.5 (i < 4) pass.
  std::vector<float> less = filled(0.5f);
  std::vector<bool> drawn;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      drawn.push_back(x < 4);
      if (x < 4) less[y * kW + x] = 0.25f + static_cast<float>(x) / 16;
    }
  expect_both(*dev, depth_pass(ps, CompareFunc::Less, true, {0.25f, 0.75f, 0.25f, 0.75f}),
              filled(0.5f), less, drawn);
}

// Interpolated z of random planes, drawn on both devices and compared bit for bit (NUMERICS.md
// D4): 16 quads whose corners take random z in [0, 1] and w in [0.5, 2] (so z/w and 1/w are
// not short fractions and the two triangles of a quad lie in different planes), on a
// 203x117 target, ALWAYS, no oDepth. Under Rounding::Llvmpipe (the default) the CPU device
// must match lavapipe in every bit; under Rounding::Exact (z/w interpolated in double) the
// figure is printed for NUMERICS.md, not asserted.
TEST_F(ResidentTest, InterpolatedDepthOfRandomPlanesBitIdentical) {
  constexpr uint32_t kBigW = 203, kBigH = 117;
  std::mt19937 rng(30);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), wide(0.5f, 2.0f);
  uint64_t pixels = 0;
  std::array<uint64_t, 2> differing{};
  std::array<double, 2> worst{};
  for (int quad = 0; quad < 16; ++quad) {
    cpu::Pass p = depth_pass("ps_2_0\nmov oC0, c1\n", CompareFunc::Always);
    for (size_t c = 0; c < 4; ++c) {
      const float w = wide(rng);
      cpu::Vec4& pos = p.vertices[c].v[0];
      pos = {pos[0] * w, pos[1] * w, unit(rng) * w, w};
    }
    TextureSet set(*dev);
    TextureId color{}, depth{};
    ASSERT_TRUE(succeeded(set.create(kBigW, kBigH, img::Format::RGBA32F), color));
    ASSERT_TRUE(succeeded(set.create_depth(kBigW, kBigH, 1.0f), depth));
    RenderTargets rt;
    rt.color[0] = color;
    rt.depth = depth;
    ASSERT_TRUE(succeeded(set.draw(p, StageTextures{}, rt)));
    img::Image z;
    ASSERT_TRUE(succeeded(set.read(depth), z));
    for (int mode = 0; mode < 2; ++mode) {
      p.conventions.rounding = mode == 0 ? ir::Rounding::Llvmpipe : ir::Rounding::Exact;
      img::Image color_cpu(kBigW, kBigH);
      std::vector<float> depth_cpu(size_t{kBigW} * kBigH, 1.0f);
      cpu::DrawTargets t;
      t.color[0] = &color_cpu;
      t.depth = depth_cpu.data();
      ASSERT_TRUE(cpu::draw(p, t, 1).ok());
      for (size_t i = 0; i < depth_cpu.size(); ++i) {
        const float a = depth_cpu[i], b = z.rgba[4 * i];
        if (std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b)) continue;
        ++differing[mode];
        worst[mode] = std::max(worst[mode], std::abs(double{a} - double{b}));
      }
    }
    pixels += size_t{kBigW} * kBigH;
  }
  std::printf("interpolated depth vs lavapipe over %llu pixels: Llvmpipe %llu differ (max %.3g), "
              "Exact %llu differ (max %.3g)\n",
              static_cast<unsigned long long>(pixels),
              static_cast<unsigned long long>(differing[0]), worst[0],
              static_cast<unsigned long long>(differing[1]), worst[1]);
  EXPECT_EQ(differing[0], 0u) << differing[0] << " of " << pixels << " depths differ, by up to "
                              << worst[0];
}

TEST_F(ResidentTest, DepthPassesWithoutABufferAreRefused) {
  cpu::Pass p = depth_pass(kConstantDepth, CompareFunc::Less);
  TextureSet set(*dev);
  TextureId color{};
  ASSERT_TRUE(succeeded(set.create(kW, kH, img::Format::RGBA32F), color));
  ir::Result<pass::DrawReport> r = set.draw(p, StageTextures{}, color);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("no depth buffer is bound"), std::string::npos) << r.message();
  img::Image target(kW, kH);
  ir::Result<cpu::DrawStats> c = cpu::draw(p, target, 1);
  EXPECT_FALSE(c.ok());
  EXPECT_NE(c.message().find("no depth buffer is bound"), std::string::npos) << c.message();
}

} // namespace
} // namespace tierlift::vulkan::test
