// The CTAB comment, built by hand from the D3DXSHADER_CONSTANTTABLE layout
// (constant_table.h): one float4x4 "g_mWVP" in c4..c7 of a ps_2_0 shader.
#include <gtest/gtest.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/constant_table.h"

namespace {

// Offsets count from the first byte after the "CTAB" code: header 0..27, the constant
// record 28..47, its type 48..63, "g_mWVP" at 64, "ps_2_0" at 72, "tl" at 80; 84 bytes =
// 21 DWORDs, so the comment token is 0xFFFE | (1 + 21) << 16 = 0x0016FFFE.
std::vector<uint32_t> stream_with_ctab() {
  return {0xFFFF0200, 0x0016FFFE, 0x42415443, // version, comment, "CTAB"
          28,         80,         0xFFFF0200, 1,          28,         0, 72, // header
          64,         0x00040002, 0x00000004, 48,         0,          // name, set 2 / c4, 4 regs
          0x00030003, 0x00040004, 0x00000001, 0,                      // matrix_columns float 4x4
          0x576D5F67, 0x00005056, 0x325F7370, 0x0000305F, 0x00006C74, // "g_mWVP" "ps_2_0" "tl"
          0x02000001, 0x800F0800, 0xA0E40004,                         // mov oC0, c4
          0x0000FFFF};
}

} // namespace

TEST(ConstantTable, ReadsNamesRegistersAndTypes) {
  tierlift::ir::DiagnosticSink diags;
  auto t = tierlift::assembly::read_constant_table(stream_with_ctab(), diags);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->target, "ps_2_0");
  EXPECT_EQ(t->creator, "tl");
  ASSERT_EQ(t->constants.size(), 1u);
  const auto& c = t->constants[0];
  EXPECT_EQ(c.name, "g_mWVP");
  EXPECT_EQ(c.set, tierlift::assembly::ConstantSet::Float4);
  EXPECT_EQ(c.index, 4u);
  EXPECT_EQ(c.count, 4u);
  EXPECT_EQ(c.type, "float4x4");
  EXPECT_EQ(c.registers(), "c4..c7");
  EXPECT_EQ(t->find("g_mWVP"), &c);
  EXPECT_EQ(t->find("nope"), nullptr);
  EXPECT_TRUE(diags.all().empty());
  // The shader itself still disassembles (the comment is skipped).
  EXPECT_TRUE(tierlift::assembly::disassemble(stream_with_ctab(), diags).has_value());
}

TEST(ConstantTable, PrintedAsComments) {
  tierlift::ir::DiagnosticSink diags;
  auto t = tierlift::assembly::read_constant_table(stream_with_ctab(), diags);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(tierlift::assembly::print_constant_table(*t),
            "// CTAB: ps_2_0, tl\n//   c4..c7  g_mWVP  float4x4\n");
}

// A name offset past the comment: a warning at the comment token (byte 4), no table.
TEST(ConstantTable, BrokenTableIsAWarningNotACrash) {
  auto s = stream_with_ctab();
  s[10] = 5000; // the record's name offset
  tierlift::ir::DiagnosticSink diags;
  EXPECT_FALSE(tierlift::assembly::read_constant_table(s, diags).has_value());
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].severity, tierlift::ir::Severity::Warning);
  EXPECT_EQ(diags.all()[0].loc.byte_offset, 4);
  // Offsets that wrap or overrun anywhere never read outside the comment.
  for (size_t i = 3; i < 24; ++i) {
    auto t = stream_with_ctab();
    t[i] = 0xFFFFFFFF;
    tierlift::ir::DiagnosticSink d;
    (void)tierlift::assembly::read_constant_table(t, d);
  }
}

TEST(ConstantTable, NoCommentNoTable) {
  tierlift::ir::DiagnosticSink diags;
  EXPECT_FALSE(
      tierlift::assembly::read_constant_table({0xFFFF0200, 0x0000FFFF}, diags).has_value());
  EXPECT_TRUE(diags.all().empty());
}
