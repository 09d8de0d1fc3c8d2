// Vertex-shader tokens derived by hand from the layout of docs/d3d9-rules.md §11.1/§11.2.
// Register types: v = 1 → 0x1000_0000, c = 2 → 0x2000_0000, a0 = 3 → 0x3000_0000,
// oPos/oFog/oPts = 4 → 0x4000_0000, oD = 5 → 0x5000_0000, oT = 6 → 0x6000_0000,
// i = 7 → 0x7000_0000, b = 14 (0b01110) → 0x6000_0800, aL = 15 (0b01111) → 0x7000_0800,
// l = 18 (0b10010) → lo 2, hi 2 → 0x2000_1000. Plus bit 31 on every parameter token.
#include <gtest/gtest.h>

#include "hand_tokens_test.h"
#include "ir_build.h"

using namespace tierlift::test;
using tierlift::ir::Opcode;
using tierlift::ir::Profile;
using tierlift::ir::RegFile;

TEST(BytecodeHand, Vs11Listing3ByHand) {
  // GPU Gems 21 Listing 3: dcl_position v0, dcl_texcoord v3, mov oPos, v0, add oT0..3.
  Builder b(Profile::vs_1_1);
  b.dcl_input(0, DeclUsage::Position).dcl_input(3, DeclUsage::TexCoord);
  b.ins(Opcode::Mov, D(RegFile::RastOut, kRastPos), {S(RegFile::Input, 0)});
  for (uint32_t i = 0; i < 4; ++i)
    b.ins(Opcode::Add, D(RegFile::TexCrdOut, i), {S(RegFile::Input, 3), S(RegFile::Const, i)});
  expect_tokens(b.p, {
                         0xFFFE0101, // vs_1_1: 0xFFFE0000 | 1<<8 | 1
                         0x0000001F, // dcl: SM1 has no length field
                         0x80000000, // usage position = 0, index 0
                         0x900F0000, // v0: type 1, mask F
                         0x0000001F,
                         0x80000005, // usage texcoord = 5
                         0x900F0003, // v3
                         0x00000001,
                         0xC00F0000, // oPos: type 4 → 0x4000_0000 | bit 31, index 0
                         0x90E40000,
                         0x00000002, // add oT0, v3, c0
                         0xE00F0000, // oT0: type 6 → 0x6000_0000 | bit 31
                         0x90E40003, 0xA0E40000, 0x00000002, 0xE00F0001, 0x90E40003,
                         0xA0E40001, 0x00000002, 0xE00F0002, 0x90E40003, 0xA0E40002,
                         0x00000002, 0xE00F0003, 0x90E40003, 0xA0E40003, 0x0000FFFF,
                     });
}

TEST(BytecodeHand, Vs11RelativeAddressAddsNoToken) {
  Builder b(Profile::vs_1_1);
  b.dcl_input(0, DeclUsage::Position)
      .ins(Opcode::Mov, D(RegFile::Addr, 0, 0x1), {S(RegFile::Input, 0, replicate_swizzle(0))})
      // mov oD0, c[a0.x + 5]
      .ins(Opcode::Mov, D(RegFile::AttrOut, 0), {Rel(S(RegFile::Const, 5), RegFile::Addr, 0)})
      .ins(Opcode::Mov, D(RegFile::RastOut, kRastFog, 0x1), {S(RegFile::Input, 0, 0xAA)});
  expect_tokens(b.p, {
                         0xFFFE0101,
                         0x0000001F,
                         0x80000000,
                         0x900F0000,
                         0x00000001,
                         0xB0010000, // a0.x: type 3 → 0x3000_0000, mask x = 1
                         0x90000000, // v0.x: swizzle xxxx = 0x00
                         0x00000001,
                         0xD00F0000, // oD0: type 5 → 0x5000_0000
                         0xA0E42005, // c5 with relative bit 13 (0x2000), nothing follows
                         0x00000001,
                         0xC0010001, // oFog: RastOut index 1, mask x
                         0x90AA0000, // v0.z: zzzz = 2|2<<2|2<<4|2<<6 = 0xAA
                         0x0000FFFF,
                     });
}

TEST(BytecodeHand, Vs20RelativeAddressAddsAddressToken) {
  Builder b(Profile::vs_2_0);
  b.dcl_input(4, DeclUsage::TexCoord, 2) // dcl_texcoord2 v4
      .ins(Opcode::Mova, D(RegFile::Addr, 0, 0x3), {S(RegFile::Input, 4)})
      // mov r0, c[a0.y + 7]
      .ins(Opcode::Mov, D(RegFile::Temp, 0), {Rel(S(RegFile::Const, 7), RegFile::Addr, 1)})
      // add oPos, r0, c[aL + 2]
      .ins(Opcode::Add, D(RegFile::RastOut, kRastPos),
           {S(RegFile::Temp, 0), Rel(S(RegFile::Const, 2), RegFile::Loop, 0)});
  expect_tokens(b.p, {
                         0xFFFE0200,
                         0x0200001F, // dcl, length 2
                         0x80020005, // texcoord = 5, usage index 2 in bits 16-19
                         0x900F0004,
                         0x0200002E, // mova a0.xy, v4
                         0xB0030000,
                         0x90E40004,
                         0x03000001, // length 3: dst, src, address token
                         0x800F0000,
                         0xA0E42007, // c7 | relative bit
                         0xB0550000, // a0 with .yyyy = 1|1<<2|1<<4|1<<6 = 0x55
                         0x04000002, // length 4
                         0xC00F0000,
                         0x80E40000,
                         0xA0E42002,
                         // aL: type 15 → 0x7000_0800 | bit 31, and the identity swizzle
                         // 0xE4 that Microsoft's assembler writes there (Wine's d3dcompiler
                         // asm tests), not .xxxx
                         0xF0E40800,
                         0x0000FFFF,
                     });
}

TEST(BytecodeHand, Vs20DefiDefbAndFlowControl) {
  Builder b(Profile::vs_2_0);
  b.def(RegFile::ConstInt, 2, {4, 0, 1, 0xFFFFFFFF}) // defi i2, 4, 0, 1, -1
      .def(RegFile::ConstBool, 1, {1, 0, 0, 0})      // defb b1, true
      .ins(Opcode::Loop, std::nullopt, {S(RegFile::Loop, 0), S(RegFile::ConstInt, 2)})
      .ins(Opcode::EndLoop, std::nullopt, {})
      .ins(Opcode::CallNz, std::nullopt,
           {S(RegFile::Label, 1), S(RegFile::ConstBool, 1, kIdentitySwizzle, SrcMod::Not)})
      .ins(Opcode::Ret, std::nullopt, {})
      .ins(Opcode::Label, std::nullopt, {S(RegFile::Label, 1)})
      .ins(Opcode::Ret, std::nullopt, {});
  expect_tokens(b.p, {
                         0xFFFE0200,
                         0x05000030, // defi: opcode 0x30, length 5
                         0xF00F0002, // i2: type 7 → 0x7000_0000 | bit 31 | mask F
                         0x00000004, 0x00000000, 0x00000001, 0xFFFFFFFF,
                         0x0200002F, // defb: opcode 0x2F, length 2
                         0xE00F0801, // b1: type 14 → 0x6000_0800 | bit 31 | mask F
                         0x00000001,
                         0x0200001B, // loop aL, i2
                         0xF0E40800, 0xF0E40002,
                         0x0000001D, // endloop, no operands
                         0x0200001A, // callnz l1, !b1
                         0xA0E41001, // l1: 0x2000_1000 | bit 31
                         0xEDE40801, // !b1: not = 13 → 0xD<<24
                         0x0000001C, 0x0100001E, 0xA0E41001, 0x0000001C, 0x0000FFFF,
                     });
}

TEST(BytecodeHand, CheckedAssemblyRefusesWhatTheStreamCannotCarry) {
  Builder b(Profile::vs_1_1);
  b.ins(Opcode::Mov, D(RegFile::Temp, 0), {Rel(S(RegFile::Const, 5), RegFile::Addr, 1)})
      .ins(Opcode::Mov, D(RegFile::Temp, 0), {S(RegFile::Const, 4096)});
  tierlift::ir::DiagnosticSink diags;
  EXPECT_FALSE(tierlift::assembly::assemble(b.p, diags).has_value());
  ASSERT_EQ(diags.error_count(), 2u);
  EXPECT_NE(diags.all()[0].message.find("a0.x"), std::string::npos);
  EXPECT_NE(diags.all()[1].message.find("4096"), std::string::npos);
  // The unchecked form still gives a well-formed stream (fields truncated to their bits).
  auto t = tierlift::assembly::assemble(b.p);
  EXPECT_EQ(t.back(), 0x0000FFFFu);
  EXPECT_EQ(t[6], 0xA0E40000u); // 4096 & 0x7FF = 0
}

TEST(BytecodeHand, CheckedAssemblyRefusesOpcodeOfAnotherProfile) {
  Builder b(Profile::ps_1_1);
  b.ins(Opcode::Rcp, D(RegFile::Temp, 0), {S(RegFile::Temp, 1, 0)});
  tierlift::ir::DiagnosticSink diags;
  EXPECT_FALSE(tierlift::assembly::assemble(b.p, diags).has_value());
  ASSERT_TRUE(diags.has_errors());
  EXPECT_EQ(diags.all()[0].rule, "bytecode");
}
