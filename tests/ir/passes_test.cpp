// The IR passes and the structural IR validator, on programs built by hand.
#include <bit>

#include <gtest/gtest.h>

#include "tierlift/ir/device_pipeline.h"
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

TEST(RelativeConstantLimit, EveryDeviceConstant) {
  EXPECT_EQ(ir::relative_constant_limit(Profile::vs_2_0), 256u);
  EXPECT_EQ(ir::relative_constant_limit(Profile::ps_2_0), 32u);
  EXPECT_EQ(ir::relative_constant_limit(Profile::vs_1_1), 256u); // guaranteed 96
}

ir::Instruction instr(Opcode op, RegFile dst, uint32_t index, std::vector<ir::SrcOperand> s) {
  ir::Instruction ins;
  ins.op = op;
  ins.dst = ir::DstOperand{dst, index, 0xF, {}};
  ins.src = std::move(s);
  return ins;
}

// ps_2_0: mov r1, t0 / mul r0, r1, c1 / mov oC0, r0, with c1 bound to 0. The device pipeline
// rewrites the product to mul r0, c1, c1 (+0 whatever r1 holds), so mov r1, t0 feeds
// nothing and becomes nop; with drop_dead off (the Vulkan device, whose emitter prunes) it
// stays; with c1 = 1 nothing is rewritten and nothing copied.
TEST(DevicePipeline, SpecialisesDropsDeadCodeAndValidates) {
  ir::Program p;
  p.profile = Profile::ps_2_0;
  p.code = {instr(Opcode::Mov, RegFile::Temp, 1, {src(RegFile::Texture, 0)}),
            instr(Opcode::Mul, RegFile::Temp, 0, {src(RegFile::Temp, 1), src(RegFile::Const, 1)}),
            instr(Opcode::Mov, RegFile::ColorOut, 0, {src(RegFile::Temp, 0)})};
  std::vector<std::array<float, 4>> bank(2, {0, 0, 0, 0});
  auto out = ir::prepare_for_device(p, bank);
  ASSERT_TRUE(out) << out.message();
  ASSERT_TRUE(out->specialised);
  const ir::Program& s = *out->specialised;
  EXPECT_EQ(s.code[0].op, Opcode::Nop);
  EXPECT_EQ(s.code[1].src[0].file, RegFile::Const);
  EXPECT_EQ(s.code[1].src[0].index, 1u);
  EXPECT_EQ(s.code[2].op, Opcode::Mov);
  auto kept = ir::prepare_for_device(p, bank, {.drop_dead = false});
  ASSERT_TRUE(kept && kept->specialised);
  EXPECT_EQ(kept->specialised->code[0].op, Opcode::Mov);
  bank[1] = {1, 1, 1, 1};
  auto same = ir::prepare_for_device(p, bank);
  ASSERT_TRUE(same);
  EXPECT_FALSE(same->specialised);
}

} // namespace
