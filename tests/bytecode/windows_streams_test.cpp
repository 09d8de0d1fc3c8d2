// Token streams Microsoft's assemblers produced, as facts: the listing and the DWORDs that
// D3DAssemble / D3DXAssembleShader return for it, recorded by Wine's assembler tests
// (dlls/d3dcompiler_43/tests/asm.c, dlls/d3dx9_36/tests/asm.c, run against the native
// DLLs), and shaders Wine's d3d9 tests hand to the Windows runtime (dlls/d3d9/tests/
// shader.c). Our assembler must write the same stream, and the stream must read back to a
// program that assembles to it again. Those tests assemble without validation, so some
// listings here are not valid shaders; they only pin the encoding.
//
// Opcodes covered: nop mov add mul dp3 dp4 rcp rsq lrp nrm crs sgn sincos pow mova cnd cmp
// bem dcl def defi defb call callnz ret label loop endloop rep endrep if else endif phase
// tex texld (1.4 and 2.0) texldp texldb texcoord texcrd texkill texbem texbeml texreg2ar
// texreg2gb texreg2rgb texm3x2pad texm3x2tex texm3x2depth texm3x3pad texm3x3tex texm3x3
// texm3x3spec texm3x3vspec texdp3 texdp3tex texdepth. The others (sub mad min max slt sge
// exp log lit dst frc m4x4 m4x3 m3x4 m3x3 m3x2 abs expp logp dp2add) appear in no such
// test; opcode_pins_test.cpp holds them to the documented numbers.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"

namespace {

using namespace tierlift;
using Tokens = std::vector<uint32_t>;

struct Stream {
  const char* text;
  Tokens tokens;
};

std::string hex(const Tokens& t) {
  std::string s;
  for (uint32_t v : t) s += fmt::format("0x{:08x} ", v);
  return s;
}

// The profiles of these listings all parse today; listings of shader models 2.x/3.0 are
// added once the front end reads those profiles.
const Stream kStreams[] = {
    // preproc
    {"vs.1.1\r\n//some comments\r\n//other comments\n; yet another comment\r\nadd r0, r0, r1\n",
     {0xfffe0101, 0x00000002, 0x800f0000, 0x80e40000, 0x80e40001, 0x0000ffff}},
    {"#define REG 1 + 2 +\\\n3 + 4\nvs.1.1\nmov r0, c0[ REG ]\n",
     {0xfffe0101, 0x00000001, 0x800f0000, 0xa0e4000a, 0x0000ffff}},
    // ps_1_1
    {"ps.1.1\r\ntex t0\r\nadd r0.rgb, r0, r1\r\n+mov r0.a, t0\r\n",
     {0xffff0101, 0x00000042, 0xb00f0000, 0x00000002, 0x80070000, 0x80e40000, 0x80e40001,
      0x40000001, 0x80080000, 0xb0e40000, 0x0000ffff}},
    {"ps.1.1\nmov_d4 r0, r1\n", {0xffff0101, 0x00000001, 0x8e0f0000, 0x80e40001, 0x0000ffff}},
    {"ps_1_1\ndef c2, 0, 0., 0, 0.\n",
     {0xffff0101, 0x00000051, 0xa00f0002, 0x00000000, 0x00000000, 0x00000000, 0x00000000,
      0x0000ffff}},
    // vs_1_1
    {"vs_1_1\nnop\n", {0xfffe0101, 0x00000000, 0x0000ffff}},
    {"vs_1_1\nmov oPos, c0\n", {0xfffe0101, 0x00000001, 0xc00f0000, 0xa0e40000, 0x0000ffff}},
    {"vs_1_1\nmov oT5, c0\n", {0xfffe0101, 0x00000001, 0xe00f0005, 0xa0e40000, 0x0000ffff}},
    {"vs_1_1\nmov oD1, c0\n", {0xfffe0101, 0x00000001, 0xd00f0001, 0xa0e40000, 0x0000ffff}},
    {"vs_1_1\nmov oFog, c0.x\n", {0xfffe0101, 0x00000001, 0xc00f0001, 0xa0000000, 0x0000ffff}},
    {"vs_1_1\nmov oPts, c0.x\n", {0xfffe0101, 0x00000001, 0xc00f0002, 0xa0000000, 0x0000ffff}},
    {"vs_1_1\ndcl_position0 v0", {0xfffe0101, 0x0000001f, 0x80000000, 0x900f0000, 0x0000ffff}},
    {"vs_1_1\ndcl_normal12 v15", {0xfffe0101, 0x0000001f, 0x800c0003, 0x900f000f, 0x0000ffff}},
    {"vs_1_1\ndef c12, 0, -1, -0.5, 1024\n",
     {0xfffe0101, 0x00000051, 0xa00f000c, 0x00000000, 0xbf800000, 0xbf000000, 0x44800000,
      0x0000ffff}},
    {"vs_1_1\ndp4 r0.xw, r1.wzyx, r2.xxww\n",
     {0xfffe0101, 0x00000009, 0x80090000, 0x801b0001, 0x80f00002, 0x0000ffff}},
    {"vs_1_1\nadd r0, -r0.x, -r1\n",
     {0xfffe0101, 0x00000002, 0x800f0000, 0x81000000, 0x81e40001, 0x0000ffff}},
    {"vs_1_1\nmov r0, c1[a0.x + 2]\n",
     {0xfffe0101, 0x00000001, 0x800f0000, 0xa0e42003, 0x0000ffff}},
    {"vs_1_1\nmov r0, c[ 2 + a0.x + 12 ]\n",
     {0xfffe0101, 0x00000001, 0x800f0000, 0xa0e4200e, 0x0000ffff}},
    {"vs_1_1\nmov r0, c4[ 2 ]\n", {0xfffe0101, 0x00000001, 0x800f0000, 0xa0e40006, 0x0000ffff}},
    {"vs_1_1\nrcp r0, v0.x\n", {0xfffe0101, 0x00000006, 0x800f0000, 0x90000000, 0x0000ffff}},
    {"vs.1.1\nrsq r0, v0.x\n", {0xfffe0101, 0x00000007, 0x800f0000, 0x90000000, 0x0000ffff}},
    // ps_1_3
    {"ps_1_3\ntex t0\ntexreg2ar t1, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000045, 0xb00f0001, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexreg2gb t1, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000046, 0xb00f0001, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexreg2rgb t1, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000052, 0xb00f0001, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ncnd r0, r1, r0, v0\n",
     {0xffff0103, 0x00000050, 0x800f0000, 0x80e40001, 0x80e40000, 0x90e40000, 0x0000ffff}},
    {"ps_1_3\ncmp r0, r1, r0, v0\n",
     {0xffff0103, 0x00000058, 0x800f0000, 0x80e40001, 0x80e40000, 0x90e40000, 0x0000ffff}},
    {"ps_1_3\ntexkill t0\n", {0xffff0103, 0x00000041, 0xb00f0000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000047, 0xb00f0001, 0xb0e40000, 0x00000048,
      0xb00f0002, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000047, 0xb00f0001, 0xb0e40000, 0x00000054,
      0xb00f0002, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexbem t1, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000043, 0xb00f0001, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexbeml t1, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000044, 0xb00f0001, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexdp3tex t1, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000053, 0xb00f0001, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexdp3 t1, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000055, 0xb00f0001, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3tex t3, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049,
      0xb00f0002, 0xb0e40000, 0x0000004a, 0xb00f0003, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3 t3, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049,
      0xb00f0002, 0xb0e40000, 0x00000056, 0xb00f0003, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049,
      0xb00f0002, 0xb0e40000, 0x0000004c, 0xb00f0003, 0xb0e40000, 0xa0e40000, 0x0000ffff}},
    {"ps_1_3\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3vspec t3, t0\n",
     {0xffff0103, 0x00000042, 0xb00f0000, 0x00000049, 0xb00f0001, 0xb0e40000, 0x00000049,
      0xb00f0002, 0xb0e40000, 0x0000004d, 0xb00f0003, 0xb0e40000, 0x0000ffff}},
    {"ps_1_3\ntexcoord t0\n", {0xffff0103, 0x00000040, 0xb00f0000, 0x0000ffff}},
    {"ps_1_3\nmov_x2_sat r0, 1 - r1\n",
     {0xffff0103, 0x00000001, 0x811f0000, 0x86e40001, 0x0000ffff}},
    {"ps_1_3\nmov_d8 r0, -r1\n", {0xffff0103, 0x00000001, 0x8d0f0000, 0x81e40001, 0x0000ffff}},
    {"ps_1_3\nmov_sat r0, -r1_bias\n",
     {0xffff0103, 0x00000001, 0x801f0000, 0x83e40001, 0x0000ffff}},
    {"ps_1_3\nmov_sat r0, -r1_bx2\n", {0xffff0103, 0x00000001, 0x801f0000, 0x85e40001, 0x0000ffff}},
    {"ps_1_3\nmov_x4_sat r0.a, -r1_bx2.a\n",
     {0xffff0103, 0x00000001, 0x82180000, 0x85ff0001, 0x0000ffff}},
    {"ps_1_3\ntexcoord_x2 t0\n", {0xffff0103, 0x00000040, 0xb10f0000, 0x0000ffff}},
    {"ps_1_3\ntexbem_d4 t1, t0\n", {0xffff0103, 0x00000043, 0xbe0f0001, 0xb0e40000, 0x0000ffff}},
    // ps_1_4
    {"ps_1_4\nphase\n", {0xffff0104, 0x0000fffd, 0x0000ffff}},
    {"ps_1_4\ntexcrd r0, t0\n", {0xffff0104, 0x00000040, 0x800f0000, 0xb0e40000, 0x0000ffff}},
    {"ps_1_4\ntexcrd_sat r4, t3\n", {0xffff0104, 0x00000040, 0x801f0004, 0xb0e40003, 0x0000ffff}},
    {"ps_1_4\ntexld r1, t4\n", {0xffff0104, 0x00000042, 0x800f0001, 0xb0e40004, 0x0000ffff}},
    {"ps_1_4\ntexld r5, r2_dz\n", {0xffff0104, 0x00000042, 0x800f0005, 0x89e40002, 0x0000ffff}},
    {"ps_1_4\nbem r1.rg, c0, r0\n",
     {0xffff0104, 0x00000059, 0x80030001, 0xa0e40000, 0x80e40000, 0x0000ffff}},
    {"ps_1_4\ntexdepth r5\n", {0xffff0104, 0x00000057, 0x800f0005, 0x0000ffff}},
    {"ps_1_4\nadd_x4 r0, r1, r2\n",
     {0xffff0104, 0x00000002, 0x820f0000, 0x80e40001, 0x80e40002, 0x0000ffff}},
    {"ps_1_4\nadd r0.rgb, r1, r2\n+add r0.a, r1, r2\n",
     {0xffff0104, 0x00000002, 0x80070000, 0x80e40001, 0x80e40002, 0x40000002, 0x80080000,
      0x80e40001, 0x80e40002, 0x0000ffff}},
    // vs_2_0
    {"vs_2_0\nlrp r0, v0, c0, r1\n",
     {0xfffe0200, 0x04000012, 0x800f0000, 0x90e40000, 0xa0e40000, 0x80e40001, 0x0000ffff}},
    {"vs_2_0\ndp4 oPos, v0, c0\n",
     {0xfffe0200, 0x03000009, 0xc00f0000, 0x90e40000, 0xa0e40000, 0x0000ffff}},
    {"vs_2_0\nmov r0, c0[a0.x]\n",
     {0xfffe0200, 0x03000001, 0x800f0000, 0xa0e42000, 0xb0000000, 0x0000ffff}},
    {"vs_2_0\nrep i0\nendrep\n", {0xfffe0200, 0x01000026, 0xf0e40000, 0x00000027, 0x0000ffff}},
    {"vs_2_0\nif b0\nelse\nendif\n",
     {0xfffe0200, 0x01000028, 0xe0e40800, 0x0000002a, 0x0000002b, 0x0000ffff}},
    {"vs_2_0\nloop aL, i0\nmov r0, c0[aL]\nendloop\n",
     {0xfffe0200, 0x0200001b, 0xf0e40800, 0xf0e40000, 0x03000001, 0x800f0000, 0xa0e42000,
      0xf0e40800, 0x0000001d, 0x0000ffff}},
    {"vs_2_0\nnrm r0, c0\n", {0xfffe0200, 0x02000024, 0x800f0000, 0xa0e40000, 0x0000ffff}},
    {"vs_2_0\ncrs r0, r1, r2\n",
     {0xfffe0200, 0x03000021, 0x800f0000, 0x80e40001, 0x80e40002, 0x0000ffff}},
    {"vs_2_0\nsgn r0, r1, r2, r3\n",
     {0xfffe0200, 0x04000022, 0x800f0000, 0x80e40001, 0x80e40002, 0x80e40003, 0x0000ffff}},
    {"vs_2_0\nsincos r0, r1, r2, r3\n",
     {0xfffe0200, 0x04000025, 0x800f0000, 0x80e40001, 0x80e40002, 0x80e40003, 0x0000ffff}},
    {"vs_2_0\npow r0, r1, r2\n",
     {0xfffe0200, 0x03000020, 0x800f0000, 0x80e40001, 0x80e40002, 0x0000ffff}},
    {"vs_2_0\nmova a0.y, c0.z\n", {0xfffe0200, 0x0200002e, 0xb0020000, 0xa0aa0000, 0x0000ffff}},
    {"vs_2_0\ndefb b0, true\ndefb b1, false\n",
     {0xfffe0200, 0x0200002f, 0xe00f0800, 0x00000001, 0x0200002f, 0xe00f0801, 0x00000000,
      0x0000ffff}},
    {"vs_2_0\ndefi i0, -1, 1, 10, 0\n",
     {0xfffe0200, 0x05000030, 0xf00f0000, 0xffffffff, 0x00000001, 0x0000000a, 0x00000000,
      0x0000ffff}},
    {"vs_2_0\ncall l0\nret\nlabel l0\nret\n",
     {0xfffe0200, 0x01000019, 0xa0e41000, 0x0000001c, 0x0100001e, 0xa0e41000, 0x0000001c,
      0x0000ffff}},
    {"vs_2_0\ncallnz l0, !b0\nret\nlabel l0\nret\n",
     {0xfffe0200, 0x0200001a, 0xa0e41000, 0xede40800, 0x0000001c, 0x0100001e, 0xa0e41000,
      0x0000001c, 0x0000ffff}},
    // ps_2_0
    {"ps_2_0\ndcl_cube s0\n", {0xffff0200, 0x0200001f, 0x98000000, 0xa00f0800, 0x0000ffff}},
    {"ps_2_0\ndcl_volume s0\n", {0xffff0200, 0x0200001f, 0xa0000000, 0xa00f0800, 0x0000ffff}},
    {"ps_2_0\ndcl_2d s2\ntexld r0, t1, s2\n",
     {0xffff0200, 0x0200001f, 0x90000000, 0xa00f0802, 0x03000042, 0x800f0000, 0xb0e40001,
      0xa0e40802, 0x0000ffff}},
    {"ps_2_0\ntexkill t0\n", {0xffff0200, 0x01000041, 0xb00f0000, 0x0000ffff}},
    {"ps_2_0\nmov oC0, c0\nmov oC1, c1\n",
     {0xffff0200, 0x02000001, 0x800f0800, 0xa0e40000, 0x02000001, 0x800f0801, 0xa0e40001,
      0x0000ffff}},
    {"ps_2_0\nmov oDepth, c0.x\n", {0xffff0200, 0x02000001, 0x900f0800, 0xa0000000, 0x0000ffff}},
    {"ps_2_0\ndcl_2d s2\ntexldp r0, t1, s2\n",
     {0xffff0200, 0x0200001f, 0x90000000, 0xa00f0802, 0x03010042, 0x800f0000, 0xb0e40001,
      0xa0e40802, 0x0000ffff}},
    {"ps.2.0\ndcl_2d s2\ntexldb r0, t1, s2\n",
     {0xffff0200, 0x0200001f, 0x90000000, 0xa00f0802, 0x03020042, 0x800f0000, 0xb0e40001,
      0xa0e40802, 0x0000ffff}},
    // Created by the Windows runtime in Wine's d3d9 shader tests (validated there).
    {"vs_1_1\ndcl_position0 v0\ndp4 oPos.x, v0, c0\ndp4 oPos.y, v0, c1\ndp4 oPos.z, v0, c2\n"
     "dp4 oPos.w, v0, c3\n",
     {0xfffe0101, 0x0000001f, 0x80000000, 0x900f0000, 0x00000009, 0xc0010000, 0x90e40000,
      0xa0e40000, 0x00000009, 0xc0020000, 0x90e40000, 0xa0e40001, 0x00000009, 0xc0040000,
      0x90e40000, 0xa0e40002, 0x00000009, 0xc0080000, 0x90e40000, 0xa0e40003, 0x0000ffff}},
    {"ps_1_1\ndef c1, 1.0, 0.0, 0.0, 0.0\ntex t0\ndp3 r0, c1, c0\nmul r0, v0, r0\nmul r0, t0, r0\n",
     {0xffff0101, 0x00000051, 0xa00f0001, 0x3f800000, 0x00000000, 0x00000000,
      0x00000000, 0x00000042, 0xb00f0000, 0x00000008, 0x800f0000, 0xa0e40001,
      0xa0e40000, 0x00000005, 0x800f0000, 0x90e40000, 0x80e40000, 0x00000005,
      0x800f0000, 0xb0e40000, 0x80e40000, 0x0000ffff}},
};

} // namespace

TEST(WindowsStreams, AssemblerWritesWhatWindowsWrote) {
  for (const Stream& s : kStreams) {
    SCOPED_TRACE(s.text);
    auto r = assembly::parse_text(s.text);
    ASSERT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources);
    EXPECT_EQ(hex(assembly::assemble(*r.program)), hex(s.tokens));
  }
}

TEST(WindowsStreams, StreamsReadBackToTheSameStream) {
  for (const Stream& s : kStreams) {
    SCOPED_TRACE(s.text);
    ir::DiagnosticSink diags;
    auto program = assembly::disassemble(s.tokens, diags);
    ASSERT_TRUE(program.has_value()) << (diags.all().empty() ? "" : diags.all()[0].message);
    EXPECT_EQ(hex(assembly::assemble(*program)), hex(s.tokens));
    // And through the text a user sees.
    auto reparsed = assembly::parse_text(assembly::print_program(*program));
    ASSERT_TRUE(reparsed.program.has_value())
        << assembly::print_program(*program) << ir::render_text(reparsed.diags, reparsed.sources);
    EXPECT_EQ(hex(assembly::assemble(*reparsed.program)), hex(s.tokens));
  }
}
