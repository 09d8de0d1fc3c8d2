// The liveness passes on hand-built programs: dead code, the inputs a pixel stage reads,
// the vertex outputs nothing consumes.
#include <gtest/gtest.h>

#include "tierlift/ir/liveness.h"

using namespace tierlift;
using ir::Opcode;
using ir::Profile;
using ir::RegFile;

namespace {

ir::Instruction op(Opcode o, RegFile df, uint32_t di, uint8_t mask,
                   std::vector<std::pair<RegFile, uint32_t>> srcs) {
  ir::Instruction ins;
  ins.op = o;
  ins.dst = ir::DstOperand{df, di, mask, {}};
  for (auto [f, i] : srcs) {
    ir::SrcOperand s;
    s.file = f;
    s.index = i;
    ins.src.push_back(s);
  }
  return ins;
}

TEST(Liveness, AnOverwrittenComponentKillsTheEarlierWrite) {
  // mov r0.x, c0 / mov r0, c1 / mov oC0, r0: the first write is dead, c0 with it.
  ir::Program ps;
  ps.profile = Profile::ps_2_0;
  ps.code = {op(Opcode::Mov, RegFile::Temp, 0, 0x1, {{RegFile::Const, 0}}),
             op(Opcode::Mov, RegFile::Temp, 0, 0xF, {{RegFile::Const, 1}}),
             op(Opcode::Mov, RegFile::ColorOut, 0, 0xF, {{RegFile::Temp, 0}})};
  const auto dead = ir::dead_instructions(ps, {{{RegFile::ColorOut, 0}, 0xF}});
  EXPECT_EQ(dead, (std::vector<bool>{true, false, false}));
}

TEST(Liveness, AMacroWritesOnlyItsRows) {
  // mov r0, c0 / m3x2 r0.xy, v0, c1 / mov oPos, r0: m3x2 leaves .zw, so the mov stays live.
  ir::Program vs;
  vs.profile = Profile::vs_1_1;
  vs.code = {op(Opcode::Mov, RegFile::Temp, 0, 0xF, {{RegFile::Const, 0}}),
             op(Opcode::M3x2, RegFile::Temp, 0, 0x3, {{RegFile::Input, 0}, {RegFile::Const, 1}}),
             op(Opcode::Mov, RegFile::RastOut, ir::kRastPos, 0xF, {{RegFile::Temp, 0}})};
  const auto dead = ir::dead_instructions(vs, {{{RegFile::RastOut, ir::kRastPos}, 0xF}});
  EXPECT_EQ(dead, (std::vector<bool>{false, false, false}));
  // The macro's reads: v0 and the rows c1, c2.
  const auto reads = ir::registers_read(vs.code[1], vs.profile).regs;
  EXPECT_EQ(reads, (std::vector<ir::RegKey>{
                       {RegFile::Input, 0}, {RegFile::Const, 1}, {RegFile::Const, 2}}));
}

TEST(Liveness, PixelInputsAndDeadVertexOutputs) {
  // ps_1_1: tex t1 reads TC(1); add r0, v0, t1 reads the colour v0.
  ir::Program ps;
  ps.profile = Profile::ps_1_1;
  ir::Instruction tex = op(Opcode::Tex, RegFile::Texture, 1, 0xF, {});
  ps.code = {tex,
             op(Opcode::Add, RegFile::Temp, 0, 0xF, {{RegFile::Input, 0}, {RegFile::Texture, 1}})};
  const std::vector<bool> none(ps.code.size(), false);
  const std::set<ir::RegKey> in = ir::live_inputs(ps, none);
  EXPECT_EQ(in, (std::set<ir::RegKey>{{RegFile::AttrOut, 0}, {RegFile::TexCrdOut, 1}}));

  ir::Program vs;
  vs.profile = Profile::vs_1_1;
  vs.code = {op(Opcode::Mov, RegFile::TexCrdOut, 0, 0xF, {{RegFile::Input, 1}}),
             op(Opcode::Mov, RegFile::TexCrdOut, 1, 0xF, {{RegFile::Input, 1}}),
             op(Opcode::Mov, RegFile::AttrOut, 0, 0xF, {{RegFile::Input, 2}}),
             op(Opcode::Mov, RegFile::RastOut, ir::kRastPos, 0xF, {{RegFile::Input, 0}})};
  EXPECT_EQ(ir::dead_outputs(vs, in), (std::vector<ir::RegKey>{{RegFile::TexCrdOut, 0}}));
}

} // namespace
