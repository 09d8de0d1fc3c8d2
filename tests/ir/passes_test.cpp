// The IR passes and the structural IR validator, on programs built by hand.
#include <bit>

#include <gtest/gtest.h>

#include "tierlift/ir/passes.h"

using namespace tierlift;
using ir::Opcode;
using ir::Profile;
using ir::RegFile;

namespace {

ir::ConstDef def(uint32_t index, float x) {
  ir::ConstDef d;
  d.index = index;
  d.raw = {std::bit_cast<uint32_t>(x), 0, 0, 0};
  return d;
}

ir::SrcOperand src(RegFile f, uint32_t index) {
  ir::SrcOperand s;
  s.file = f;
  s.index = index;
  return s;
}

// vs_2_0: m4x3 r0.xyz, v0, c4
ir::Program matrix_program(Opcode op = Opcode::M4x3, uint8_t mask = 0x7) {
  ir::Program p;
  p.profile = Profile::vs_2_0;
  ir::Instruction ins;
  ins.op = op;
  ins.dst = ir::DstOperand{RegFile::Temp, 0, mask, {}};
  ins.src = {src(RegFile::Input, 0), src(RegFile::Const, 4)};
  p.code.push_back(ins);
  return p;
}

TEST(FoldDefs, TheLaterDefinitionWins) {
  ir::Program p;
  p.profile = Profile::ps_2_0;
  p.defs = {def(3, 1.0f), def(5, 2.0f), def(3, 7.0f)};
  ir::ConstDef b;
  b.file = RegFile::ConstBool;
  b.index = 3;
  b.raw = {1, 0, 0, 0};
  p.defs.push_back(b);
  const ir::FoldedDefs f = ir::fold_defs(p);
  ASSERT_NE(f.find(RegFile::Const, 3), nullptr);
  EXPECT_EQ(f.find(RegFile::Const, 3)->f(0), 7.0f);
  EXPECT_EQ(f.find(RegFile::Const, 5)->f(0), 2.0f);
  EXPECT_EQ(f.find(RegFile::Const, 4), nullptr);
  EXPECT_EQ(f.floats.size(), 2u);
  ASSERT_NE(f.find(RegFile::ConstBool, 3), nullptr); // b3 is not c3
  EXPECT_TRUE(f.find(RegFile::ConstBool, 3)->b());
  EXPECT_EQ(f.find(RegFile::ConstInt, 3), nullptr);
}

TEST(ValidateIr, AcceptsAWellFormedProgram) {
  EXPECT_TRUE(ir::validate_ir(matrix_program()).ok());
}

TEST(ValidateIr, RejectsAnEmptyMaskAMissingDestinationAndTooFewSources) {
  ir::Program p = matrix_program(Opcode::M4x3, 0);
  EXPECT_FALSE(ir::validate_ir(p).ok());
  p = matrix_program();
  p.code[0].dst.reset();
  EXPECT_FALSE(ir::validate_ir(p).ok());
  p = matrix_program();
  p.code[0].src.pop_back();
  EXPECT_FALSE(ir::validate_ir(p).ok());
}

TEST(ValidateIr, MatrixRowsMustStayInsideTheFile) {
  // ps_2_0 has c0..c31: m3x3 r0.xyz, t0, c30 would read c30..c32.
  ir::Program p = matrix_program(Opcode::M3x3);
  p.profile = Profile::ps_2_0;
  p.code[0].src = {src(RegFile::Texture, 0), src(RegFile::Const, 29)};
  EXPECT_TRUE(ir::validate_ir(p).ok());
  p.code[0].src[1].index = 30;
  const ir::Status s = ir::validate_ir(p);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("c32"), std::string::npos) << s.message();
}

TEST(ValidateIr, RejectsAnInstructionOfAnotherProfile) {
  ir::Program p = matrix_program();
  p.profile = Profile::ps_1_1; // no matrix macros in ps_1_1
  p.code[0].src[0] = src(RegFile::Texture, 0);
  EXPECT_FALSE(ir::validate_ir(p).ok());
}

TEST(RunPass, ValidatesTheResultAndNamesThePass) {
  auto good = ir::run_pass(matrix_program(), "nothing", [](ir::Program&) {});
  EXPECT_TRUE(good.ok());
  auto bad = ir::run_pass(matrix_program(), "clear-masks",
                          [](ir::Program& p) { p.code[0].dst->mask = 0; });
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("after clear-masks"), std::string::npos) << bad.message();
}

TEST(ExpandMatrixMacros, OneDotProductPerWrittenRow) {
  // m4x3 r0.xyz, v0, c4 → dp4 r0.x, v0, c4; dp4 r0.y, v0, c5; dp4 r0.z, v0, c6.
  auto out = ir::run_pass(matrix_program(), "expand-matrix-macros", ir::expand_matrix_macros);
  ASSERT_TRUE(out.ok()) << out.message();
  ASSERT_EQ(out->code.size(), 3u);
  for (uint32_t row = 0; row < 3; ++row) {
    const ir::Instruction& ins = out->code[row];
    EXPECT_EQ(ins.op, Opcode::Dp4);
    EXPECT_EQ(ins.dst->mask, 1u << row);
    EXPECT_EQ(ins.src[0].file, RegFile::Input);
    EXPECT_EQ(ins.src[1].index, 4 + row);
  }
  // m3x2 r0.xy → two dp3; a narrower mask keeps only its rows.
  auto m32 = ir::run_pass(matrix_program(Opcode::M3x2, 0x2), "expand", ir::expand_matrix_macros);
  ASSERT_TRUE(m32.ok());
  ASSERT_EQ(m32->code.size(), 1u);
  EXPECT_EQ(m32->code[0].op, Opcode::Dp3);
  EXPECT_EQ(m32->code[0].src[1].index, 5u);
}

TEST(RelativeReach, EveryDeviceConstantOnceAnyReadIsRelative) {
  ir::Program p = matrix_program();
  EXPECT_FALSE(ir::relative_reach(p).has_value());
  p.code[0].src[1].rel = ir::RelAddr{RegFile::Addr, 0, {}};
  const auto reach = ir::relative_reach(p);
  ASSERT_TRUE(reach.has_value());
  EXPECT_EQ(reach->begin, 0u);
  EXPECT_EQ(reach->end, 256u); // vs_2_0 guarantees 256 c#, the devices offer 256
  EXPECT_EQ(ir::relative_constant_limit(Profile::ps_2_0), 32u);
  EXPECT_EQ(ir::relative_constant_limit(Profile::vs_1_1), 256u); // guaranteed 96
}

} // namespace
