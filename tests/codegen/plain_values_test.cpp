// ir::plain_values: which values of a pixel program are plain (+0 or a positive normal
// number, bounded), checked against facts worked out by hand; and what the code generator
// leaves out with them (CodegenOptions::plain_values). That the images stay the
// interpreter's, on values at each edge of the facts, is tests/vulkan/plain_values_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <limits>
#include <string>
#include <vector>

#include "compile_valid.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/ir/plain_values.h"

using namespace tierlift;

namespace {

using Bank = std::vector<std::array<float, 4>>;

ir::Program parse(const std::string& text) {
  return test::parse_program(text);
}

ir::PlainValueFacts facts(const ir::Program& p, const Bank& bank, uint32_t unorm8 = 1,
                          float max = FLT_MAX) {
  ir::PlainValueInputs in;
  in.constants = bank;
  in.unorm8_stages = unorm8;
  in.ps1x_max = max;
  return ir::plain_values(p, in);
}

// Listing 2's shape, two taps, then a product of the sum with c2.
constexpr const char* kTwoTaps = "ps_2_0\ndcl t0.xy\ndcl t1.xy\ndcl_2d s0\n"
                                 "texld r0, t0, s0\ntexld r1, t1, s0\nmul r0, r0, c0\n"
                                 "mad r0, r1, c1, r0\nmul r0, r0, c2\nmov oC0, r0\n";

TEST(PlainValues, DecodedTexelsTimesPositiveWeightsArePlain) {
  const ir::Program p = parse(kTwoTaps);
  const Bank bank = {{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 1, 2, 3}, {4, 4, 4, 4}};
  const ir::PlainValueFacts f = facts(p, bank);
  ASSERT_EQ(f.sources.size(), 6u);
  // texld r0, t0, s0: its sources are a coordinate and a sampler, nothing known.
  EXPECT_EQ(f.sources[0][0], 0);
  // mul r0, r0, c0: the texel (0 or 1/255 .. 1) and a positive weight.
  EXPECT_EQ(f.sources[2][0], 0xF);
  EXPECT_EQ(f.sources[2][1], 0xF);
  // mad r0, r1, c1, r0: the addend is the product above, at most 0.5.
  EXPECT_EQ(f.sources[3][0], 0xF);
  EXPECT_EQ(f.sources[3][2], 0xF);
  // mul r0, r0, c2: the sum is at most 0.5 + 3 = 3.5.
  EXPECT_EQ(f.sources[4][0], 0xF);
  EXPECT_EQ(f.sources[4][1], 0xF);
}

TEST(PlainValues, WhatIsNotPlain) {
  const ir::Program p = parse(kTwoTaps);
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // c0: −0.5, −0, a denormal, +0 (the last is plain: +0 times anything plain is +0).
  // c1: NaN, ∞, FLT_MAX, 1. c2: 1.
  const Bank bank = {{-0.5f, -0.0f, 1e-40f, 0}, {nan, inf, FLT_MAX, 1}, {1, 1, 1, 1}};
  const ir::PlainValueFacts f = facts(p, bank);
  EXPECT_EQ(f.sources[2][1], 0b1000);
  EXPECT_EQ(f.sources[3][1], 0b1100);
  // r0 after the mad: x, y unknown (the products with c0 were); z: texel · FLT_MAX + the
  // denormal product (unknown) is unknown; w: 0 + texel · 1 is plain.
  EXPECT_EQ(f.sources[4][0], 0b1000);
  // A texture that is not decoded RGBA8 (a float texture): nothing known of its texels.
  const ir::PlainValueFacts g = facts(p, {{0.5f, 0.5f, 0.5f, 0.5f}}, /*unorm8=*/0);
  EXPECT_EQ(g.sources[2][0], 0);
  EXPECT_EQ(g.sources[2][1], 0xF);
}

TEST(PlainValues, BoundsFollowTheArithmetic) {
  // A sum that reaches ∞ is not plain; a product whose smallest non-zero value would be a
  // denormal is not either (two levels of tiny weights).
  const ir::Program p = parse("ps_2_0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\n"
                              "mad r1, r0, c0, c0\nmad r1, r0, c0, r1\nmul r2, r0, c1\n"
                              "mul r2, r2, c1\nadd r3, r2, r1\nmov oC0, r3\n");
  const Bank bank = {{1e38f, 1e38f, 3e38f, 3e38f}, {1e-15f, 1e-15f, 1e-20f, 1e-20f}};
  const ir::PlainValueFacts f = facts(p, bank);
  // r1 = texel·c0 + c0: at most 2e38 in x, y; 6e38 rounds to ∞ in z, w.
  EXPECT_EQ(f.sources[2][2], 0b0011);
  // r2 = texel·c1: at least 1e-15/255 (x, y) or 1e-20/255 (z, w), plain.
  EXPECT_EQ(f.sources[4][0], 0xF);
  // r2·c1: at least 3.9e-33 (x, y: normal) or 3.9e-43 (z, w: a denormal). r1 after the
  // second mad: x, y at most 1e38 + 2e38 = 3e38 < FLT_MAX.
  EXPECT_EQ(f.sources[5][0], 0b0011);
  EXPECT_EQ(f.sources[5][1], 0b0011);
}

TEST(PlainValues, ModifiersAndSwizzles) {
  // c0 = (0.5, −0.5, 2, 0.25); c0.wzyx = (0.25, 2, −0.5, 0.5); −r0 is not plain.
  const ir::Program p = parse("ps_2_0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\n"
                              "mul r1, r0, c0.wzyx\nmul r1, -r0, c0\nmul r1, r0, -c0\n"
                              "mov oC0, r1\n");
  const ir::PlainValueFacts f = facts(p, {{0.5f, -0.5f, 2, 0.25f}});
  EXPECT_EQ(f.sources[1][0], 0xF);
  EXPECT_EQ(f.sources[1][1], 0b1011);
  EXPECT_EQ(f.sources[2][0], 0);
  EXPECT_EQ(f.sources[2][1], 0b1101);
  EXPECT_EQ(f.sources[3][1], 0); // negation is not taken, even where it makes −0.5 plain
}

TEST(PlainValues, Ps1xConstantsAndCoissue) {
  // ps_1_3 reads c0 = (0.5, 2, 0.25, 0.5) clamped to [−1, 1]: (0.5, 1, 0.25, 0.5), plain.
  // t0_bx2 is not plain. The co-issued alpha reads r0 as the first mul left it (plain), not
  // as the rgb half of its own pair writes it (−t0: not plain).
  const ir::Program p = parse("ps.1.3\ntex t0\nmul r0, t0, c0\nmul r1, t0_bx2, c0\n"
                              "mul r0.rgb, -t0, c0\n+mul r0.a, r0, c0\n");
  const ir::PlainValueFacts f = facts(p, {{0.5f, 2, 0.25f, 0.5f}});
  EXPECT_EQ(f.sources[1][0], 0xF);
  EXPECT_EQ(f.sources[1][1], 0xF);
  EXPECT_EQ(f.sources[2][0], 0);
  EXPECT_EQ(f.sources[3][0], 0);
  EXPECT_EQ(f.sources[4][0], 0xF);
}

TEST(PlainValues, TheRangeClampIsANoOpOnlyBelowMax) {
  // ps_1_3 with the ps_1_x range ±1 (a GeForce3): t0·0.5 fits; _x4 makes it up to 2.
  const ir::Program p = parse("ps.1.3\ntex t0\nmul r0, t0, c0\nmul_x4 r1, t0, c0\n"
                              "mul r0, t0, c1\nmov r0, v0\n");
  const Bank bank = {{0.5f, 0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f, 0.5f}};
  const ir::PlainValueFacts f = facts(p, bank, 1, 1.0f);
  EXPECT_TRUE(f.within_ps1x_range[0]);  // tex t0: 0 .. 1
  EXPECT_TRUE(f.within_ps1x_range[1]);  // up to 0.5
  EXPECT_FALSE(f.within_ps1x_range[2]); // up to 2
  EXPECT_FALSE(f.within_ps1x_range[3]); // x may be −0 (a negative weight)
  EXPECT_FALSE(f.within_ps1x_range[4]); // a colour input: not known
  // With the D3D9 range (FLT_MAX) the _x4 product fits too.
  EXPECT_TRUE(facts(p, bank, 1, FLT_MAX).within_ps1x_range[2]);
  // A ps_2_0 program has no range clamp.
  EXPECT_FALSE(facts(parse(kTwoTaps), bank).within_ps1x_range[2]);
}

TEST(PlainValues, FlowControlForgetsEverything) {
  // ps_1_4: after the phase marker nothing written before it is known.
  const ir::Program p = parse("ps.1.4\ntexld r0, t0\nmul r1, r0, c0\nphase\n"
                              "texld r2, t1\nmul r0, r1, c0\n");
  const Bank bank = {{0.5f, 0.5f, 0.5f, 0.5f}};
  const ir::PlainValueFacts f = facts(p, bank);
  EXPECT_EQ(f.sources[1][0], 0xF);
  EXPECT_EQ(f.sources[4][0], 0);
}

size_t count(const std::string& text, const std::string& what) {
  return test::count_occurrences(text, what);
}

std::string pixel_spirv_text(const ir::Program& ps, const codegen::CodegenOptions& o) {
  ir::DiagnosticSink diags;
  const ir::Program vs = parse("vs_2_0\ndcl_position v0\nmov oPos, v0\nmov oT0, v0\nmov oT1, v0\n");
  auto pair = codegen::compile_pair(vs, ps, o, diags);
  EXPECT_TRUE(pair);
  if (!pair) return {};
  ir::Result<std::string> text = codegen::disassemble(pair->ps.words);
  EXPECT_TRUE(text);
  return text ? *text : std::string{};
}

TEST(PlainValues, TheCodeGeneratorLeavesOutTheZeroTests) {
  const ir::Program ps = parse(kTwoTaps);
  codegen::CodegenOptions o;
  o.stage_fetch_unorm8[0] = true;
  const std::string full = pixel_spirv_text(ps, o);
  o.known_ps_constants = {{{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f, 0.25f}, {2, 2, 2, 2}}};
  const std::string plain = pixel_spirv_text(ps, o);
  // Three products, each with two compares against zero, an OR and a select.
  EXPECT_EQ(count(full, "OpFOrdEqual"), 6u);
  EXPECT_EQ(count(plain, "OpFOrdEqual"), 0u);
  EXPECT_EQ(count(plain, "OpFMul"), count(full, "OpFMul"));
  // A negative weight keeps its product's test: one compare, of the other factor (the
  // weight itself never compares equal to zero).
  (*o.known_ps_constants)[2] = {-2, 2, 2, 2};
  EXPECT_EQ(count(pixel_spirv_text(ps, o), "OpFOrdEqual"), 1u);
}

} // namespace
