// Following one pixel (effects/pixel_trace.h): each instruction's destination at a pixel on
// the interpreter (cpu::trace_pixel) and on Vulkan (the instrumented module), against values
// computed here from the D3D9 pixel-centre rule; a difference planted on one side is named
// at the instruction where it starts; the comparison rules of the table on made-up columns.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/graph/pixel_trace.h"
#include "tierlift/pass/setup.h"

namespace tierlift::effects {
namespace {

using vulkan::test::parse_listing;
using Vec = std::array<float, 4>;

// The quad's uv reaches t0: at pixel (i, j) of a W×H target with D3D9 centres the sample
// point is (i, j) itself, so t0 = (i/W, j/H, 0, 1) (the quad carries uv (0,0)..(1,1), z 0,
// w 1 at its corners).
const char* kVs = "vs_2_0\n"
                  "dcl_position v0\n"
                  "dcl_texcoord v3\n"
                  "mov oPos, v0\n"
                  "mov oT0, v3\n";

// Line numbers of the instructions below: 5 mov, 6 mul, 7 add (reads c2, the planted
// constant), 8 mad, 9 mov, 10 add (.xy), 11 mov.
const char* kPs = "ps_2_0\n"
                  "def c0, 2, 4, 0.5, 1\n"
                  "def c1, 0.25, -1, 3, 0\n"
                  "dcl t0\n"
                  "mov r0, c0\n"
                  "mul r1, t0, r0\n"
                  "add r1, r1, c2\n"
                  "mad r2, r1, c1, c0\n"
                  "mov r3, c1\n"
                  "add r3.xy, r2, -t0\n"
                  "mov oC0, r3\n";

constexpr uint32_t kW = 8, kH = 4, kX = 3, kY = 2;

pass::Pass traced_pass(Vec c2) {
  pass::RunRequest r;
  r.vs = parse_listing(kVs, "uv.vsh");
  r.ps = parse_listing(kPs, "math.psh");
  r.width = kW;
  r.height = kH;
  r.format = img::Format::RGBA32F;
  r.attrs.push_back({ir::RegFile::Input, 3, {0, 0, 0, 1}, true}); // v3 = the quad's uv
  r.constants.push_back({pass::StageMask::Pixel, ir::RegFile::Const, 2, c2});
  ir::Result<pass::Pass> p = pass::prepare_pass(r);
  EXPECT_TRUE(p) << p.message();
  return p ? std::move(p).value() : pass::Pass{};
}

// What each instruction leaves in its destination at (kX, kY) with c2 = 0, by hand: t0 =
// (3/8, 2/4, 0, 1) = (0.375, 0.5, 0, 1), every step exact in binary.
std::vector<Vec> expected_values() {
  const Vec t0{0.375f, 0.5f, 0, 1};
  const Vec r0{2, 4, 0.5f, 1};
  const Vec r1{t0[0] * 2, t0[1] * 4, t0[2] * 0.5f, t0[3] * 1}; // (0.75, 2, 0, 1); + c2 = 0
  const Vec r2{r1[0] * 0.25f + 2, r1[1] * -1 + 4, r1[2] * 3 + 0.5f, r1[3] * 0 + 1};
  const Vec c1{0.25f, -1, 3, 0};
  const Vec r3{r2[0] - t0[0], r2[1] - t0[1], c1[2], c1[3]}; // .zw kept from the mov
  EXPECT_EQ(r2, (Vec{2.1875f, 2, 0.5f, 1}));
  EXPECT_EQ(r3, (Vec{1.8125f, 1.5f, 3, 0}));
  return {r0, r1, r1, r2, c1, r3, r3};
}

void expect_column(const PixelTraceTable& t, bool vulkan) {
  const std::vector<Vec> want = expected_values();
  ASSERT_EQ(t.rows.size(), want.size());
  const uint32_t lines[] = {5, 6, 7, 8, 9, 10, 11};
  for (size_t i = 0; i < want.size(); ++i) {
    const TraceRow& row = t.rows[i];
    EXPECT_EQ(row.line, lines[i]);
    const std::optional<TraceCell>& cell = vulkan ? row.vulkan : row.interpreter;
    ASSERT_TRUE(cell) << "row " << i;
    EXPECT_EQ(cell->runs, 1u) << "row " << i;
    EXPECT_EQ(cell->value, want[i]) << "row " << i << " " << row.text;
  }
  EXPECT_EQ(t.rows[3].text, "mad r2, r1, c1, c0");
  EXPECT_EQ(t.rows[5].dest, "r3");
  EXPECT_EQ(t.rows[5].mask, 0x3);
  EXPECT_EQ(t.rows[6].dest, "oC0");
}

TEST(PixelTrace, InterpreterColumnHoldsTheHandComputedValues) {
  const pass::Pass p = traced_pass({0, 0, 0, 0});
  ir::Result<cpu::PixelTrace> cpu = cpu::trace_pixel(p, kW, kH, kX, kY);
  ASSERT_TRUE(cpu) << cpu.message();
  EXPECT_TRUE(cpu->covered);
  const PixelTraceTable t = make_trace_table(*p.pixel_program, kX, kY, &*cpu, nullptr);
  expect_column(t, false);
  EXPECT_FALSE(t.has_vulkan);
  EXPECT_FALSE(t.first_difference);
  for (const TraceRow& r : t.rows) EXPECT_FALSE(r.vulkan);
  // The traced invocation is the draw's: its output is the image's pixel.
  img::Image image(kW, kH, img::Format::RGBA32F);
  ASSERT_TRUE(cpu::draw(p, image, 1));
  const float* px = image.at(kX, kY);
  EXPECT_EQ((Vec{px[0], px[1], px[2], px[3]}), expected_values().back());
}

TEST(PixelTrace, InterpreterOutsideTheTargetIsRefused) {
  const pass::Pass p = traced_pass({0, 0, 0, 0});
  EXPECT_FALSE(cpu::trace_pixel(p, kW, kH, kW, 0));
  EXPECT_FALSE(cpu::trace_pixel(p, kW, kH, 0, kH));
}

class PixelTraceVulkan : public vulkan::test::VulkanTest {};

TEST_F(PixelTraceVulkan, BothColumnsHoldTheHandComputedValues) {
  const pass::Pass p = traced_pass({0, 0, 0, 0});
  ir::Result<cpu::PixelTrace> cpu = cpu::trace_pixel(p, kW, kH, kX, kY);
  ASSERT_TRUE(cpu) << cpu.message();
  ir::Result<vulkan::ShaderTrace> vk =
      trace_on_vulkan(*dev, p, kW, kH, img::Format::RGBA32F, kX, kY);
  ASSERT_TRUE(vk) << vk.message();
  EXPECT_EQ(vk->points, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6}));
  const PixelTraceTable t = make_trace_table(*p.pixel_program, kX, kY, &*cpu, &*vk);
  expect_column(t, false);
  expect_column(t, true);
  EXPECT_TRUE(t.vulkan_covered);
  EXPECT_FALSE(t.first_difference);
  EXPECT_NE(format_trace_table(t).find("no difference: the 7 recorded instructions agree"),
            std::string::npos);
}

// Only the traced pixel records: a pixel beside it leaves other values, and the module at
// the pixel (kX + 1, kY) records t0.x = 4/8.
TEST_F(PixelTraceVulkan, OnlyTheTracedPixelRecords) {
  const pass::Pass p = traced_pass({0, 0, 0, 0});
  ir::Result<vulkan::ShaderTrace> vk =
      trace_on_vulkan(*dev, p, kW, kH, img::Format::RGBA32F, kX + 1, kY);
  ASSERT_TRUE(vk) << vk.message();
  ASSERT_EQ(vk->hits.size(), 7u);
  for (uint32_t h : vk->hits) EXPECT_EQ(h, 1u); // one invocation, not the whole quad
  EXPECT_EQ(vk->value[1], (Vec{0.5f * 2, 0.5f * 4, 0, 1}));
}

// A difference planted on the Vulkan side: c2.z = 0.25 there, 0 on the interpreter. It first
// shows at line 7 (add r1, r1, c2: r1.z), spreads to line 8 (mad r2: r2.z), and no further:
// line 10 writes r3.xy only, from r2.xy.
TEST_F(PixelTraceVulkan, APlantedDifferenceIsNamedWhereItStarts) {
  const pass::Pass cpu_pass = traced_pass({0, 0, 0, 0});
  const pass::Pass vk_pass = traced_pass({0, 0, 0.25f, 0});
  ir::Result<cpu::PixelTrace> cpu = cpu::trace_pixel(cpu_pass, kW, kH, kX, kY);
  ASSERT_TRUE(cpu) << cpu.message();
  ir::Result<vulkan::ShaderTrace> vk =
      trace_on_vulkan(*dev, vk_pass, kW, kH, img::Format::RGBA32F, kX, kY);
  ASSERT_TRUE(vk) << vk.message();
  const PixelTraceTable t = make_trace_table(*cpu_pass.pixel_program, kX, kY, &*cpu, &*vk);
  ASSERT_TRUE(t.first_difference);
  EXPECT_EQ(*t.first_difference, 2u);
  const TraceRow& first = t.rows[2];
  EXPECT_EQ(first.line, 7u);
  EXPECT_EQ(first.text, "add r1, r1, c2");
  EXPECT_EQ(first.vulkan->value, (Vec{0.75f, 2, 0.25f, 1}));
  EXPECT_EQ(first.interpreter->value, (Vec{0.75f, 2, 0, 1}));
  const std::vector<bool> differs{false, false, true, true, false, false, false};
  for (size_t i = 0; i < t.rows.size(); ++i) EXPECT_EQ(t.rows[i].differs, differs[i]) << i;
  EXPECT_EQ(t.rows[3].vulkan->value[2], 0.25f * 3 + 0.5f);
  const std::string text = format_trace_table(t);
  EXPECT_NE(text.find("first difference: line 7 `add r1, r1, c2`: interpreter r1 = (0.75 "
                      "0x3f400000, 2 0x40000000, 0 0x00000000, 1 0x3f800000), Vulkan r1 = "
                      "(0.75 0x3f400000, 2 0x40000000, 0.25 0x3e800000, 1 0x3f800000)"),
            std::string::npos)
      << text;
}

// The comparison rules on columns made here: bits in the written components, NaN equal to
// NaN, -0 not +0, a different number of runs, the first such row.
TEST(PixelTraceTable, FirstDifferenceFollowsTheComparisonRules) {
  ir::Program prog;
  prog.profile = ir::Profile::ps_2_0;
  for (int i = 0; i < 5; ++i) {
    ir::Instruction ins;
    ins.op = ir::Opcode::Mov;
    ins.dst = ir::DstOperand{ir::RegFile::Temp, static_cast<uint32_t>(i), 0xF, {}};
    ins.src.push_back(ir::SrcOperand{});
    ins.loc.line = static_cast<uint32_t>(10 + i);
    prog.code.push_back(ins);
  }
  prog.code[0].dst->mask = 0x1; // .x: the y difference below is not compared
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float other_nan = std::bit_cast<float>(0x7fc00123u);
  cpu::PixelTrace cpu;
  cpu.covered = true;
  cpu.trace.value = {{1, 2, 0, 0}, {nan, 0, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {5, 5, 5, 5}};
  cpu.trace.hits = {1, 1, 2, 1, 1};
  vulkan::ShaderTrace vk;
  vk.points = {0, 1, 2, 3, 4};
  vk.value = {{1, 3, 0, 0}, {other_nan, 0, 0, 0}, {1, 1, 1, 1}, {-0.0f, 0, 0, 0}, {5, 5, 5, 6}};
  vk.hits = {1, 1, 2, 1, 1};
  PixelTraceTable t = make_trace_table(prog, 0, 0, &cpu, &vk);
  ASSERT_TRUE(t.first_difference);
  EXPECT_EQ(*t.first_difference, 3u); // -0 vs +0; rows 0 (y unwritten), 1 (NaNs), 2 agree
  EXPECT_TRUE(t.rows[4].differs);
  vk.hits[2] = 3; // ran three times on Vulkan, twice on the interpreter
  t = make_trace_table(prog, 0, 0, &cpu, &vk);
  ASSERT_TRUE(t.first_difference);
  EXPECT_EQ(*t.first_difference, 2u);
  vk.points = {0, 1, 3, 4}; // instruction 2 not in the module: not compared
  t = make_trace_table(prog, 0, 0, &cpu, &vk);
  EXPECT_FALSE(t.rows[2].vulkan);
  ASSERT_TRUE(t.first_difference);
  EXPECT_EQ(*t.first_difference, 3u);
}

TEST(PixelTraceTable, ValuesPrintSoThatDifferentBitsShow) {
  EXPECT_EQ(format_value({1, 0.1f, -0.0f, 16777217.0f}), "(1, 0.100000001, -0, 16777216)");
  EXPECT_EQ(format_value({1, 0, 0, 0}, true),
            "(1 0x3f800000, 0 0x00000000, 0 0x00000000, 0 0x00000000)");
  // 1 and the next float up print differently at 9 digits.
  EXPECT_NE(format_value({1, 0, 0, 0}), format_value({std::nextafter(1.0f, 2.0f), 0, 0, 0}));
}

} // namespace
} // namespace tierlift::effects

namespace tierlift::effects {
namespace {

// A pixel program with gradients is traced in its 2x2 quad, as the draw shades it (NUMERICS.md
// rule F8): at pixel (3, 1) of x²y of vPos, dsx = (2·2 + 1)·1 = 5 (the quad's columns are 2
// and 3) and dsy = 3² = 9, on both columns, where a pixel traced alone would read 0.
TEST_F(PixelTraceVulkan, GradientsAreTracedInTheirQuad) {
  pass::RunRequest r;
  r.vs = parse_listing(kVs, "uv.vsh");
  r.ps = parse_listing("ps_3_0\ndcl vPos.xy\nmul r0, vPos.x, vPos.x\nmul r0, r0, vPos.y\n"
                       "dsx r1, r0\ndsy r2, r0\nadd oC0, r1, r2\n",
                       "g.psh");
  r.width = kW;
  r.height = kH;
  r.format = img::Format::RGBA32F;
  r.attrs.push_back({ir::RegFile::Input, 3, {0, 0, 0, 1}, true});
  ir::Result<pass::Pass> p = pass::prepare_pass(r);
  ASSERT_TRUE(p) << p.message();
  ir::Result<cpu::PixelTrace> cpu = cpu::trace_pixel(*p, kW, kH, 3, 1);
  ASSERT_TRUE(cpu) << cpu.message();
  ir::Result<vulkan::ShaderTrace> vk =
      trace_on_vulkan(*dev, *p, kW, kH, img::Format::RGBA32F, 3, 1);
  ASSERT_TRUE(vk) << vk.message();
  const PixelTraceTable t = make_trace_table(*p->pixel_program, 3, 1, &*cpu, &*vk);
  ASSERT_EQ(t.rows.size(), 5u);
  for (const auto& cell : {t.rows[2].interpreter, t.rows[2].vulkan}) {
    ASSERT_TRUE(cell);
    EXPECT_EQ(cell->value, (Vec{5, 5, 5, 5}));
  }
  for (const auto& cell : {t.rows[3].interpreter, t.rows[3].vulkan}) {
    ASSERT_TRUE(cell);
    EXPECT_EQ(cell->value, (Vec{9, 9, 9, 9}));
  }
  EXPECT_FALSE(t.first_difference);
  EXPECT_EQ(cpu->output.color[0][0], 14.0f);
}

} // namespace
} // namespace tierlift::effects
