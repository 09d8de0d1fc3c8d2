// Three spellings where Microsoft's assembler writes tokens of its own, each worked out by
// hand from the token layout (docs/d3d9-rules.md §9) and matching the streams Wine's d3dcompiler
// assembler tests expect from it (dlls/d3dcompiler_43/tests/asm.c):
//   source token   bit 31 | type[2:0] << 28 | type[4:3] << 11 | swizzle << 16 | mod << 24 | n
//   c# = type 2 → 0xA0000000;  a0 = type 3 → 0xB0000000;  aL = type 15 → 0xF0000800
//   relative bit 13 = 0x2000; identity swizzle .xyzw = 0xE4
#include <gtest/gtest.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"

#include "hand_tokens_test.h"

namespace {

using Tokens = std::vector<uint32_t>;

tierlift::ir::Program parse(const std::string& text) {
  auto r = tierlift::assembly::parse_text(text);
  EXPECT_TRUE(r.program.has_value()) << tierlift::ir::render_text(r.diags, r.sources);
  return r.program.value_or(tierlift::ir::Program{});
}

// The tokens of `text`, and the same tokens back through disassemble → print → parse.
void expect_assembles_to(const std::string& text, const Tokens& expected) {
  SCOPED_TRACE(text);
  tierlift::ir::Program p = parse(text);
  tierlift::test::expect_tokens(p, expected);
  tierlift::ir::DiagnosticSink diags;
  auto back = tierlift::assembly::disassemble(expected, diags);
  ASSERT_TRUE(back.has_value());
  tierlift::ir::Program reparsed = parse(tierlift::assembly::print_program(*back));
  EXPECT_EQ(tierlift::assembly::assemble(reparsed), expected)
      << tierlift::assembly::print_program(*back);
}

} // namespace

// "#define REG 1 + 2 +\" continues onto "3 + 4": c0[REG] is c[10] = 0xA0E4000A.
TEST(WindowsAssembler, DefineBodyContinuesAfterBackslash) {
  expect_assembles_to("#define REG 1 + 2 +\\\n3 + 4\nvs.1.1\nmov r0, c0[ REG ]\n",
                      {0xFFFE0101, 0x00000001, 0x800F0000, 0xA0E4000A, 0x0000FFFF});
  // White space after the backslash still joins; CRLF line ends too.
  expect_assembles_to("#define REG 1 + 2 +\\  \r\n3 + 4\r\nvs.1.1\r\nmov r0, c0[ REG ]\r\n",
                      {0xFFFE0101, 0x00000001, 0x800F0000, 0xA0E4000A, 0x0000FFFF});
}

// A backslash joins lines for the statement after it too, and lines keep their numbers:
// an error on the joined line is reported where it is.
TEST(WindowsAssembler, ContinuationKeepsLineNumbers) {
  auto r = tierlift::assembly::parse_text("vs.1.1\nmov r0,\\\n  c0\nfoo r0\n");
  ASSERT_FALSE(r.program.has_value());
  ASSERT_FALSE(r.diags.all().empty());
  EXPECT_EQ(r.diags.all()[0].loc.line, 4u) << r.diags.all()[0].message;
}

// vs_2_0 address tokens: the swizzle as written. Instruction token 0x03000001 = mov, 3
// operand tokens (bits 24-27).
TEST(WindowsAssembler, AddressRegisterSwizzleAsWritten) {
  const uint32_t mov = 0x03000001, r0 = 0x800F0000, c0_rel = 0xA0E42000;
  // Bare a0: the identity (0xB0E40000), not .x (0xB0000000).
  expect_assembles_to("vs_2_0\nmov r0, c0[a0]\n",
                      {0xFFFE0200, mov, r0, c0_rel, 0xB0E40000, 0xFFFF});
  // a0.xyww: x=0, y=1, w=3, w=3 → 0b11'11'01'00 = 0xF4.
  expect_assembles_to("vs_2_0\nmov r0, c0[a0.xyww]\n",
                      {0xFFFE0200, mov, r0, c0_rel, 0xB0F40000, 0xFFFF});
  // A replicate stays a replicate: .y = 0x55, .w = 0xFF.
  expect_assembles_to("vs_2_0\nmov r0, c0[a0.y]\n",
                      {0xFFFE0200, mov, r0, c0_rel, 0xB0550000, 0xFFFF});
  expect_assembles_to("vs_2_0\nmov r0, -c0[a0.w+5].x\n",
                      {0xFFFE0200, mov, r0, 0xA1002005, 0xB0FF0000, 0xFFFF});
}

// The component added is the first one the swizzle selects.
TEST(WindowsAssembler, MultiComponentAddressReadsTheFirst) {
  tierlift::ir::Program p = parse("vs_2_0\nmov r0, c0[a0.zyww]\n");
  ASSERT_EQ(p.code.size(), 1u);
  ASSERT_TRUE(p.code[0].src[0].rel.has_value());
  EXPECT_EQ(p.code[0].src[0].rel->component, 2);          // z
  EXPECT_EQ(p.code[0].src[0].rel->token_swizzle(), 0xF6); // z=2, y=1, w=3, w=3
}

// loop aL, i0 / mov r0, c0[aL] / endloop: the aL address token is 0xF0E40800 (identity),
// not 0xF0000800 (.xxxx). loop = 0x1B with 2 operands, endloop = 0x1D.
TEST(WindowsAssembler, LoopRegisterTokenIsIdentity) {
  expect_assembles_to("vs_2_0\nloop aL, i0\nmov r0, c0[aL]\nendloop\n",
                      {0xFFFE0200, 0x0200001B, 0xF0E40800, 0xF0E40000, 0x03000001, 0x800F0000,
                       0xA0E42000, 0xF0E40800, 0x0000001D, 0x0000FFFF});
}

// Streams from older tools with .xxxx on aL still read (and write back unchanged).
TEST(WindowsAssembler, LoopRegisterReplicateStillReads) {
  Tokens t = {0xFFFE0200, 0x0200001B, 0xF0E40800, 0xF0E40000, 0x03000001,
              0x800F0000, 0xA0E42000, 0xF0000800, 0x0000001D, 0x0000FFFF};
  tierlift::ir::DiagnosticSink diags;
  auto p = tierlift::assembly::disassemble(t, diags);
  ASSERT_TRUE(p.has_value()) << (diags.all().empty() ? "" : diags.all()[0].message);
  EXPECT_EQ(tierlift::assembly::assemble(*p), t);
}
