// Shader models 2.x and 3.0 against the token streams Microsoft's assembler writes: the
// listings and DWORDs of Wine's d3dcompiler assembler tests (dlls/d3dcompiler_43/tests/
// asm.c: vs_2_x, ps_2_x, vs_3_0, ps_3_0; assembled there with validation skipped, so some
// are not valid shaders), then hand-derived tokens for the rows those tests leave out (the
// other comparisons of if/break/setp, texldb/texldp in ps_3_0).
//
// Token layout (docs/d3d9-rules.md §11): instruction = opcode | control << 16 | length << 24
// | predicated << 28. Parameter = bit 31 | type[2:0] << 28 | type[4:3] << 11 | n, with
// r = 0 → 0x80000000, v = 1 → 0x90000000, c = 2 → 0xA0000000, a0 = 3 → 0xB0000000,
// o# = 6 → 0xE0000000, i = 7 → 0xF0000000, oC = 8 → 0x80000800, s = 10 → 0xA0000800,
// b = 14 → 0xE0000800, aL = 15 → 0xF0000800, vPos/vFace = 17 → 0x90001000,
// l = 18 → 0xA0001000, p0 = 19 → 0xB0001000.
#include <gtest/gtest.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/constant_table.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"

#include "hand_tokens_test.h"

namespace {

using Tokens = std::vector<uint32_t>;
namespace ir = tierlift::ir;
namespace assembly = tierlift::assembly;

struct Case {
  const char* text;
  Tokens tokens;
};

ir::Program parse(const std::string& text) {
  auto r = assembly::parse_text(text);
  EXPECT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources);
  return r.program.value_or(ir::Program{});
}

// assemble(parse(text)) is the stream; disassembling the stream gives the same IR; and
// print → parse → assemble of the disassembly gives the stream back (disasm ∘ assemble is
// the identity).
void expect_case(const Case& c) {
  SCOPED_TRACE(c.text);
  ir::Program p = parse(c.text);
  tierlift::test::expect_tokens(p, c.tokens);
  ir::DiagnosticSink diags;
  auto back = assembly::disassemble(c.tokens, diags);
  ASSERT_TRUE(back.has_value()) << (diags.all().empty() ? "" : diags.all()[0].message);
  ir::Program reparsed = parse(assembly::print_program(*back));
  EXPECT_EQ(tierlift::test::hex(assembly::assemble(reparsed)), tierlift::test::hex(c.tokens))
      << assembly::print_program(*back);
}

} // namespace

TEST(LaterProfileTokens, Vs2xAsWindowsAssemblesIt) {
  const Case cases[] = {
      {"vs_2_x\nrep i0\nbreak\nendrep\n",
       {0xfffe0201, 0x01000026, 0xf0e40000, 0x0000002c, 0x00000027, 0x0000ffff}},
      {"vs_2_x\nif_ge r0, r1\nendif\n",
       {0xfffe0201, 0x02030029, 0x80e40000, 0x80e40001, 0x0000002b, 0x0000ffff}},
      {"vs_2_x\nrep i0\nbreak_ne r0, r1\nendrep",
       {0xfffe0201, 0x01000026, 0xf0e40000, 0x0205002d, 0x80e40000, 0x80e40001, 0x00000027,
        0x0000ffff}},
      {"vs_2_x\nsetp_gt p0, r0, r1\n(!p0) add r2, r2, r3\n",
       {0xfffe0201, 0x0301005e, 0xb00f1000, 0x80e40000, 0x80e40001, 0x14000002, 0x800f0002,
        0xbde41000, 0x80e40002, 0x80e40003, 0x0000ffff}},
      {"vs_2_x\nif p0.x\nelse\nendif\n",
       {0xfffe0201, 0x01000028, 0xb0001000, 0x0000002a, 0x0000002b, 0x0000ffff}},
      {"vs_2_x\ncallnz l0, !p0.z\nret\nlabel l0\nret\n",
       {0xfffe0201, 0x0200001a, 0xa0e41000, 0xbdaa1000, 0x0000001c, 0x0100001e, 0xa0e41000,
        0x0000001c, 0x0000ffff}},
      {"vs.2.x\nrep i0\nbreakp p0.w\nendrep\n",
       {0xfffe0201, 0x01000026, 0xf0e40000, 0x01000060, 0xb0ff1000, 0x00000027, 0x0000ffff}},
  };
  for (const Case& c : cases) expect_case(c);
}

TEST(LaterProfileTokens, Ps2xAsWindowsAssemblesIt) {
  const Case cases[] = {
      {"ps_2_x\ndefb b0, true\ndefb b1, false\n",
       {0xffff0201, 0x0200002f, 0xe00f0800, 0x00000001, 0x0200002f, 0xe00f0801, 0x00000000,
        0x0000ffff}},
      {"ps_2_x\ndefi i0, -1, 1, 10, 0\ndefi i1, 0, 40, 30, 10\n",
       {0xffff0201, 0x05000030, 0xf00f0000, 0xffffffff, 0x00000001, 0x0000000a, 0x00000000,
        0x05000030, 0xf00f0001, 0x00000000, 0x00000028, 0x0000001e, 0x0000000a, 0x0000ffff}},
      {"ps_2_x\ndsx r0, r0\n", {0xffff0201, 0x0200005b, 0x800f0000, 0x80e40000, 0x0000ffff}},
      {"ps_2_x\ndsy r0, r0\n", {0xffff0201, 0x0200005c, 0x800f0000, 0x80e40000, 0x0000ffff}},
      {"ps_2_x\ndcl_2d s2\ntexldd r0, v1, s2, r3, r4\n",
       {0xffff0201, 0x0200001f, 0x90000000, 0xa00f0802, 0x0500005d, 0x800f0000, 0x90e40001,
        0xa0e40802, 0x80e40003, 0x80e40004, 0x0000ffff}},
      {"ps_2_x\ncall l0\nret\nlabel l0\nret\n",
       {0xffff0201, 0x01000019, 0xa0e41000, 0x0000001c, 0x0100001e, 0xa0e41000, 0x0000001c,
        0x0000ffff}},
      {"ps_2_x\ncallnz l0, b0\nret\nlabel l0\nret\n",
       {0xffff0201, 0x0200001a, 0xa0e41000, 0xe0e40800, 0x0000001c, 0x0100001e, 0xa0e41000,
        0x0000001c, 0x0000ffff}},
      {"ps_2_x\ncallnz l0, !b0\nret\nlabel l0\nret\n",
       {0xffff0201, 0x0200001a, 0xa0e41000, 0xede40800, 0x0000001c, 0x0100001e, 0xa0e41000,
        0x0000001c, 0x0000ffff}},
      {"ps_2_x\nif !b0\nelse\nendif\n",
       {0xffff0201, 0x01000028, 0xede40800, 0x0000002a, 0x0000002b, 0x0000ffff}},
      {"ps_2_x\nsetp_gt p0, r0, r1\n(!p0) add r2, r2, r3\n",
       {0xffff0201, 0x0301005e, 0xb00f1000, 0x80e40000, 0x80e40001, 0x14000002, 0x800f0002,
        0xbde41000, 0x80e40002, 0x80e40003, 0x0000ffff}},
      {"ps.2.x\ncall l2047\nret\nlabel l2047\nret\n",
       {0xffff0201, 0x01000019, 0xa0e417ff, 0x0000001c, 0x0100001e, 0xa0e417ff, 0x0000001c,
        0x0000ffff}},
  };
  for (const Case& c : cases) expect_case(c);
}

TEST(LaterProfileTokens, Vs30AsWindowsAssemblesIt) {
  const Case cases[] = {
      {"vs_3_0\nmov r0, c0\n", {0xfffe0300, 0x02000001, 0x800f0000, 0xa0e40000, 0x0000ffff}},
      {"vs_3_0\ndcl_2d s0\n", {0xfffe0300, 0x0200001f, 0x90000000, 0xa00f0800, 0x0000ffff}},
      {"vs_3_0\ndcl_position o0\n", {0xfffe0300, 0x0200001f, 0x80000000, 0xe00f0000, 0x0000ffff}},
      {"vs_3_0\ndcl_texcoord12 o11\n",
       {0xfffe0300, 0x0200001f, 0x800c0005, 0xe00f000b, 0x0000ffff}},
      {"vs_3_0\ntexldl r0, v0, s0\n",
       {0xfffe0300, 0x0300005f, 0x800f0000, 0x90e40000, 0xa0e40800, 0x0000ffff}},
      {"vs_3_0\nmov r0, c0[aL]\n",
       {0xfffe0300, 0x03000001, 0x800f0000, 0xa0e42000, 0xf0e40800, 0x0000ffff}},
      {"vs_3_0\nmov o[ a0.x + 12 ], r0\n",
       {0xfffe0300, 0x03000001, 0xe00f200c, 0xb0000000, 0x80e40000, 0x0000ffff}},
      {"vs_3_0\nadd_sat r0, r0, r1\n",
       {0xfffe0300, 0x03000002, 0x801f0000, 0x80e40000, 0x80e40001, 0x0000ffff}},
      {"vs_3_0\nmov r2, r1_abs\n", {0xfffe0300, 0x02000001, 0x800f0002, 0x8be40001, 0x0000ffff}},
      {"vs_3_0\nmov r2, r1.xygb\n", {0xfffe0300, 0x02000001, 0x800f0002, 0x80940001, 0x0000ffff}},
      {"vs_3_0\nmov r2.xyb, r1\n", {0xfffe0300, 0x02000001, 0x80070002, 0x80e40001, 0x0000ffff}},
      {"vs_3_0\nmova_sat a0.x, r1\n", {0xfffe0300, 0x0200002e, 0xb0110000, 0x80e40001, 0x0000ffff}},
      // 3.0's sincos has one source (0x25 with length 2).
      {"vs_3_0\nsincos r0, r1\n", {0xfffe0300, 0x02000025, 0x800f0000, 0x80e40001, 0x0000ffff}},
      {"vs_3_0\ndef c0, 1.0f, 1.0f, 1.0f, 0.5f\n",
       {0xfffe0300, 0x05000051, 0xa00f0000, 0x3f800000, 0x3f800000, 0x3f800000, 0x3f000000,
        0x0000ffff}},
      {"vs.3.0\nadd r0, v20[aL], r2\n",
       {0xfffe0300, 0x04000002, 0x800f0000, 0x90e42014, 0xf0e40800, 0x80e40002, 0x0000ffff}},
  };
  for (const Case& c : cases) expect_case(c);
}

TEST(LaterProfileTokens, Ps30AsWindowsAssemblesIt) {
  const Case cases[] = {
      {"ps_3_0\nmov r0, c0\n", {0xffff0300, 0x02000001, 0x800f0000, 0xa0e40000, 0x0000ffff}},
      {"ps_3_0\ndcl_normal5 v0\n", {0xffff0300, 0x0200001f, 0x80050003, 0x900f0000, 0x0000ffff}},
      {"ps_3_0\nmov r0, vPos\n", {0xffff0300, 0x02000001, 0x800f0000, 0x90e41000, 0x0000ffff}},
      {"ps_3_0\nmov r0, vFace\n", {0xffff0300, 0x02000001, 0x800f0000, 0x90e41001, 0x0000ffff}},
      {"ps_3_0\nmov r0, v[ aL + 12 ]\n",
       {0xffff0300, 0x03000001, 0x800f0000, 0x90e4200c, 0xf0e40800, 0x0000ffff}},
      {"ps_3_0\nloop aL, i0\nmov r0, v0[aL]\nendloop\n",
       {0xffff0300, 0x0200001b, 0xf0e40800, 0xf0e40000, 0x03000001, 0x800f0000, 0x90e42000,
        0xf0e40800, 0x0000001d, 0x0000ffff}},
      {"ps_3_0\ntexldl r0, v0, s0\n",
       {0xffff0300, 0x0300005f, 0x800f0000, 0x90e40000, 0xa0e40800, 0x0000ffff}},
      {"ps_3_0\nadd_pp r0, r0, r1\n",
       {0xffff0300, 0x03000002, 0x802f0000, 0x80e40000, 0x80e40001, 0x0000ffff}},
      {"ps_3_0\ndsx_sat r0, r1\n", {0xffff0300, 0x0200005b, 0x801f0000, 0x80e40001, 0x0000ffff}},
      {"ps_3_0\ntexldd_pp r0, r1, r2, r3, r4\n",
       {0xffff0300, 0x0500005d, 0x802f0000, 0x80e40001, 0x80e40002, 0x80e40003, 0x80e40004,
        0x0000ffff}},
      {"ps_3_0\ntexkill v0\n", {0xffff0300, 0x01000041, 0x900f0000, 0x0000ffff}},
      {"ps_3_0\nadd oC3, r0, r1\n",
       {0xffff0300, 0x03000002, 0x800f0803, 0x80e40000, 0x80e40001, 0x0000ffff}},
      {"ps_3_0\ndcl_texcoord0_centroid v0\n",
       {0xffff0300, 0x0200001f, 0x80000005, 0x904f0000, 0x0000ffff}},
      {"ps_3_0\ndcl_2d_centroid s0\n",
       {0xffff0300, 0x0200001f, 0x90000000, 0xa04f0800, 0x0000ffff}},
      {"ps.3.0\ndcl_2d_pp s0\n", {0xffff0300, 0x0200001f, 0x90000000, 0xa02f0800, 0x0000ffff}},
  };
  for (const Case& c : cases) expect_case(c);
}

// The comparison is the control field (bits 16-23): gt 1, eq 2, ge 3, lt 4, ne 5, le 6.
// r0.x = 0x80000000 (swizzle .xxxx = 0x00), c1.y = 0xA0550001 (.yyyy = 0x55),
// p0 = 0xB00F1000 as a destination.
TEST(LaterProfileTokens, EveryComparisonByHand) {
  const char* names[] = {"gt", "eq", "ge", "lt", "ne", "le"};
  for (uint32_t k = 0; k < 6; ++k) {
    const uint32_t cmp = (k + 1) << 16;
    const std::string n = names[k];
    expect_case({("ps_3_0\nif_" + n + " r0.x, c1.y\nendif\n").c_str(),
                 {0xffff0300, 0x02000029 | cmp, 0x80000000, 0xa0550001, 0x0000002b, 0x0000ffff}});
    expect_case({("vs_3_0\nrep i0\nbreak_" + n + " r0.x, c1.y\nendrep\n").c_str(),
                 {0xfffe0300, 0x01000026, 0xf0e40000, 0x0200002d | cmp, 0x80000000, 0xa0550001,
                  0x00000027, 0x0000ffff}});
    expect_case({("vs_2_x\nsetp_" + n + " p0, r0.x, c1.y\n").c_str(),
                 {0xfffe0201, 0x0300005e | cmp, 0xb00f1000, 0x80000000, 0xa0550001, 0x0000ffff}});
  }
  // The ifc_ / breakc_ spellings of other disassemblers are the same instructions.
  EXPECT_EQ(assembly::assemble(parse("ps_3_0\nifc_lt r0.x, c1.y\nendif\n")),
            assembly::assemble(parse("ps_3_0\nif_lt r0.x, c1.y\nendif\n")));
  EXPECT_EQ(assembly::assemble(parse("vs_3_0\nrep i0\nbreakc_ne r0.x, c1.y\nendrep\n")),
            assembly::assemble(parse("vs_3_0\nrep i0\nbreak_ne r0.x, c1.y\nendrep\n")));
}

// ps_3_0 keeps ps_2_0's texld forms (texldp control 1, texldb control 2) and predicated
// texture reads: (p0.y) puts p0 with .yyyy (0x55) after the destination.
TEST(LaterProfileTokens, Ps30TextureFormsByHand) {
  expect_case({"ps_3_0\ndcl_2d s1\ntexldp r0, r1, s1\ntexldb r2, r1, s1\n",
               {0xffff0300, 0x0200001f, 0x90000000, 0xa00f0801, 0x03010042, 0x800f0000, 0x80e40001,
                0xa0e40801, 0x03020042, 0x800f0002, 0x80e40001, 0xa0e40801, 0x0000ffff}});
  expect_case(
      {"ps_3_0\n(p0.y) texld r0, r1, s1\n",
       {0xffff0300, 0x14000042, 0x800f0000, 0xb0551000, 0x80e40001, 0xa0e40801, 0x0000ffff}});
  // sincos in 3.0 with its usual .xy mask and a replicate source: mask 3 → 0x80030000.
  expect_case({"ps_3_0\nsincos r0.xy, r1.w\n",
               {0xffff0300, 0x02000025, 0x80030000, 0x80ff0001, 0x0000ffff}});
}

// What the 1.x / 2.0 readers refuse stays refused: a predicated token in vs_2_0, relative
// addressing of a destination outside vs_3_0.
TEST(LaterProfileTokens, PredicatedTokenOutsideTheLaterProfilesIsRefused) {
  ir::DiagnosticSink diags;
  EXPECT_FALSE(assembly::disassemble(
      {0xfffe0200, 0x14000002, 0x800f0002, 0xbde41000, 0x80e40002, 0x80e40003, 0x0000ffff}, diags));
  ASSERT_FALSE(diags.all().empty());
  EXPECT_NE(diags.all()[0].message.find("predicated"), std::string::npos);
  ir::DiagnosticSink d2;
  EXPECT_FALSE(assembly::disassemble(
      {0xffff0300, 0x03000001, 0x800f200c, 0xb0000000, 0x80e40000, 0x0000ffff}, d2));
}

// A ps_3_0 stream with fxc's CTAB comment after the version token (layout as in
// constant_table_test.cpp: float4x4 "g_mWVP" in c4..c7, target "ps_3_0" = 0x335F7370
// 0x0000305F): the table is read, and the disassembly keeps the comment as "//!comment"
// lines (eight words a line) that assemble back to the same stream.
TEST(LaterProfileTokens, Ps30ConstantTableIsRead) {
  const Tokens stream = {0xFFFF0300, 0x0016FFFE, 0x42415443, 28,         80,         0xFFFF0300,
                         1,          28,         0,          72,         64,         0x00040002,
                         0x00000004, 48,         0,          0x00030003, 0x00040004, 0x00000001,
                         0,          0x576D5F67, 0x00005056, 0x335F7370, 0x0000305F, 0x00006C74,
                         0x02000001, 0x800F0800, 0xA0E40004, 0x0000FFFF};
  ir::DiagnosticSink diags;
  auto t = assembly::read_constant_table(stream, diags);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->target, "ps_3_0");
  ASSERT_EQ(t->constants.size(), 1u);
  EXPECT_EQ(t->constants[0].registers(), "c4..c7");
  auto p = assembly::disassemble(stream, diags);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->profile, ir::Profile::ps_3_0);
  EXPECT_EQ(assembly::print_program(*p),
            "ps_3_0\n"
            "//!comment 0x42415443 0x0000001c 0x00000050 0xffff0300 0x00000001 0x0000001c "
            "0x00000000 0x00000048\n"
            "//!comment+ 0x00000040 0x00040002 0x00000004 0x00000030 0x00000000 0x00030003 "
            "0x00040004 0x00000001\n"
            "//!comment+ 0x00000000 0x576d5f67 0x00005056 0x335f7370 0x0000305f 0x00006c74\n"
            "mov oC0, c4\n");
  EXPECT_EQ(assembly::assemble(*p), stream);
}
