// ir::zero_constant_products: a mul/mad factor reading a constant that is ±0 in every
// component the destination keeps replaces the other factor (rule 8 makes the product +0
// whatever that factor holds); liveness then drops the texture reads that only fed it, and
// the code generator's pruning leaves them out of the SPIR-V. The devices' images stay the
// interpreter's (BlockIdentity.* and the Vulkan NonZeroConstants/zero-weight tests compare
// them bit for bit); here, what is rewritten and what is not.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "compile_valid.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/ir/liveness.h"
#include "tierlift/ir/passes.h"

using namespace tierlift;

namespace {

using Bank = std::vector<std::array<float, 4>>;

ir::Program parse(const std::string& text) {
  return test::parse_program(text);
}

// Listing 2's shape, cut to three taps: r1 (tap 1) feeds only the product with c1.
constexpr const char* kThreeTaps = "ps_2_0\ndcl t0.xy\ndcl t1.xy\ndcl t2.xy\ndcl_2d s0\n"
                                   "texld r0, t0, s0\ntexld r1, t1, s0\ntexld r2, t2, s0\n"
                                   "mul r0, r0, c0\nmad r0, r1, c1, r0\nmad r0, r2, c2, r0\n"
                                   "mov oC0, r0\n";

size_t count(const std::string& text, const std::string& what) {
  return test::count_occurrences(text, what);
}

TEST(ZeroConstantProducts, AZeroWeightDropsItsTextureRead) {
  ir::Program ps = parse(kThreeTaps);
  const Bank bank = {{0.5f, 0.5f, 0.5f, 0.5f}, {0, -0.0f, 0, 0}, {0.25f, 0.25f, 0.25f, 0.25f}};
  EXPECT_EQ(ir::zero_constant_products(ps, bank), 1u);
  const ir::Instruction& mad = ps.code[4];
  ASSERT_EQ(mad.op, ir::Opcode::Mad);
  EXPECT_EQ(mad.src[0].file, ir::RegFile::Const); // mad r0, c1, c1, r0
  EXPECT_EQ(mad.src[0].index, 1u);
  EXPECT_EQ(mad.src[1].index, 1u);
  EXPECT_EQ(mad.src[2].file, ir::RegFile::Temp);
  const std::vector<bool> dead = ir::dead_instructions(ps, ir::pixel_live_out(ps));
  EXPECT_EQ(dead, (std::vector<bool>{false, true, false, false, false, false, false}));

  // The code generator then samples twice, not three times.
  ir::Program vs = parse("vs_2_0\ndcl_position v0\nmov oPos, v0\nmov oT0, v0\nmov oT1, v0\n"
                         "mov oT2, v0\n");
  ir::DiagnosticSink diags;
  auto pair = codegen::compile_pair(vs, ps, {}, diags);
  ASSERT_TRUE(pair);
  ir::Result<std::string> text = codegen::disassemble(pair->ps.words);
  ASSERT_TRUE(text);
  EXPECT_EQ(count(*text, "OpImageSampleImplicitLod"), 2u);
}

TEST(ZeroConstantProducts, OnlyZerosWhereTheResultIsKept) {
  // c1 = (0, 0, 0, 1): zero for .xyz only, after the swizzle.
  const Bank bank = {{1, 1, 1, 1}, {0, 0, 0, 1}};
  ir::Program full = parse("ps_2_0\ndcl t0\nmul r0, t0, c1\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(full, bank), 0u);
  ir::Program rgb = parse("ps_2_0\ndcl t0\nmul r0.rgb, t0, c1\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(rgb, bank), 1u);
  ir::Program swizzled = parse("ps_2_0\ndcl t0\nmul r0.x, t0, c1.w\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(swizzled, bank), 0u);
  // Negation keeps a zero; the first factor may be the constant.
  ir::Program first = parse("ps_2_0\ndcl t0\nmad r0.xy, -c1, t0, t0\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(first, bank), 1u);
  EXPECT_EQ(first.code[0].src[1].file, ir::RegFile::Const);
}

TEST(ZeroConstantProducts, WhatItLeavesAlone) {
  const Bank zeros = {{0, 0, 0, 0}, {0, 0, 0, 0}};
  // A def wins over the bank.
  ir::Program def = parse("ps_2_0\ndef c0, 1, 1, 1, 1\ndcl t0\nmul r0, t0, c0\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(def, zeros), 0u);
  // A denormal is not ±0 (Rounding::Exact keeps it: t0 × 1e-40 is not 0 there).
  const Bank tiny = {{1e-40f, 1e-40f, 1e-40f, 1e-40f}};
  ir::Program denormal = parse("ps_2_0\ndcl t0\nmul r0, t0, c0\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(denormal, tiny), 0u);
  // A constant the bank does not hold, a modifier that is not a negation (ps_1_x _bias:
  // 0 − 0.5), and an addend that is zero (not a factor).
  ir::Program missing = parse("ps_2_0\ndcl t0\nmul r0, t0, c5\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(missing, zeros), 0u);
  ir::Program bias = parse("ps_1_1\ntex t0\nmul r0, t0, c0_bias\n");
  EXPECT_EQ(ir::zero_constant_products(bias, zeros), 0u);
  ir::Program addend = parse("ps_2_0\ndcl t0\nmad r0, t0, t0, c0\nmov oC0, r0\n");
  EXPECT_EQ(ir::zero_constant_products(addend, zeros), 0u);
}

} // namespace
