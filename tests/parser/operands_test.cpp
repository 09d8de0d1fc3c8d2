// Operands: registers, source modifiers, swizzles, masks and relative addressing.
#include "test_util.h"

namespace tierlift::assembly::test {
namespace {

using ir::RegFile;
using ir::SrcMod;

// The sources of the single instruction in `body` (after a version line).
std::vector<ir::SrcOperand> sources(const std::string& version, const std::string& body) {
  ir::Program p = must_parse(version + "\n" + body + "\n");
  if (p.code.empty()) return {};
  return p.code.back().src;
}

TEST(ParserOperands, EveryRegisterName) {
  struct Case {
    const char* text;
    RegFile file;
    uint32_t index;
  };
  const Case cases[] = {
      {"r11", RegFile::Temp, 11},
      {"v15", RegFile::Input, 15},
      {"c255", RegFile::Const, 255},
      {"a0", RegFile::Addr, 0},
      {"t7", RegFile::Texture, 7},
      {"s15", RegFile::Sampler, 15},
      {"i3", RegFile::ConstInt, 3},
      {"b9", RegFile::ConstBool, 9},
      {"aL", RegFile::Loop, 0},
      {"oPos", RegFile::RastOut, ir::kRastPos},
      {"oFog", RegFile::RastOut, ir::kRastFog},
      {"oPts", RegFile::RastOut, ir::kRastPts},
      {"oD1", RegFile::AttrOut, 1},
      {"oT7", RegFile::TexCrdOut, 7},
      {"oC3", RegFile::ColorOut, 3},
      {"oDepth", RegFile::DepthOut, 0},
      {"l12", RegFile::Label, 12},
  };
  for (const Case& c : cases) {
    // Any register may appear as a mov source as far as the parser is concerned.
    auto src = sources("vs_2_0", std::string("mov r0, ") + c.text);
    ASSERT_EQ(src.size(), 1u) << c.text;
    EXPECT_EQ(src[0].file, c.file) << c.text;
    EXPECT_EQ(src[0].index, c.index) << c.text;
  }
}

TEST(ParserOperands, SourceModifiers) {
  struct Case {
    const char* text;
    SrcMod mod;
  };
  const Case cases[] = {
      {"r1", SrcMod::None},          {"-r1", SrcMod::Neg},    {"r1_bias", SrcMod::Bias},
      {"-r1_bias", SrcMod::BiasNeg}, {"r1_bx2", SrcMod::Bx2}, {"-r1_bx2", SrcMod::Bx2Neg},
      {"1-r1", SrcMod::Comp},        {"r1_x2", SrcMod::X2},   {"-r1_x2", SrcMod::X2Neg},
      {"r1_dz", SrcMod::Dz},         {"r1_db", SrcMod::Dz},   {"r1_dw", SrcMod::Dw},
      {"r1_da", SrcMod::Dw},         {"r1_abs", SrcMod::Abs}, {"-r1_abs", SrcMod::AbsNeg},
      {"!b1", SrcMod::Not},          {"r1_BX2", SrcMod::Bx2},
  };
  for (const Case& c : cases) {
    auto src = sources("ps_1_4", std::string("mov r0, ") + c.text);
    ASSERT_EQ(src.size(), 1u) << c.text;
    EXPECT_EQ(src[0].mod, c.mod) << c.text;
    EXPECT_EQ(src[0].index, 1u) << c.text;
  }
}

TEST(ParserOperands, SwizzlesReplicateTheLastComponent) {
  struct Case {
    const char* text;
    uint8_t swizzle;
  };
  const Case cases[] = {
      {"r1", ir::make_swizzle(0, 1, 2, 3)},       {"r1.xyzw", ir::make_swizzle(0, 1, 2, 3)},
      {"r1.x", ir::make_swizzle(0, 0, 0, 0)},     {"r1.w", ir::make_swizzle(3, 3, 3, 3)},
      {"r1.xy", ir::make_swizzle(0, 1, 1, 1)},    {"r1.wzx", ir::make_swizzle(3, 2, 0, 0)},
      {"r1.wzyx", ir::make_swizzle(3, 2, 1, 0)},  {"r1.rgba", ir::make_swizzle(0, 1, 2, 3)},
      {"r1.b", ir::make_swizzle(2, 2, 2, 2)},     {"r1.bgr", ir::make_swizzle(2, 1, 0, 0)},
      {"r1_bx2.a", ir::make_swizzle(3, 3, 3, 3)}, {"t0_dw.xyw", ir::make_swizzle(0, 1, 3, 3)},
  };
  for (const Case& c : cases) {
    auto src = sources("vs_1_1", std::string("mov r0, ") + c.text);
    ASSERT_EQ(src.size(), 1u) << c.text;
    EXPECT_EQ(src[0].swizzle, c.swizzle) << c.text;
  }
}

TEST(ParserOperands, BareRcpRsqSourceReadsX) {
  // docs/d3d9-rules.md §4.3: rcp/rsq with no subscript use .x; other scalar sources keep what is
  // written (the validator then asks for a replicate swizzle).
  EXPECT_EQ(sources("vs_1_1", "rcp r0, r1")[0].swizzle, ir::replicate_swizzle(0));
  EXPECT_EQ(sources("vs_1_1", "rsq r0, r1")[0].swizzle, ir::replicate_swizzle(0));
  EXPECT_EQ(sources("vs_1_1", "rcp r0, r1.y")[0].swizzle, ir::replicate_swizzle(1));
  EXPECT_EQ(sources("vs_1_1", "log r0, r1")[0].swizzle, ir::kIdentitySwizzle);
}

TEST(ParserOperands, WriteMasksInBothSpellings) {
  const std::pair<const char*, uint8_t> cases[] = {
      {"r0", 0xF},     {"r0.x", 0x1}, {"r0.xy", 0x3}, {"r0.xz", 0x5},  {"r0.yzw", 0xE},
      {"r0.rgb", 0x7}, {"r0.a", 0x8}, {"r0.ra", 0x9}, {"r0.xyzw", 0xF}};
  for (auto [text, mask] : cases) {
    ir::Program p = must_parse(std::string("vs_1_1\nmov ") + text + ", v0\n");
    ASSERT_EQ(p.code.size(), 1u) << text;
    EXPECT_EQ(p.code[0].dst->mask, mask) << text;
  }
}

TEST(ParserOperands, EveryRelativeAddressingForm) {
  struct Case {
    const char* text;
    uint32_t index;
    bool rel;
    RegFile rel_file;
    uint8_t component;
  };
  const Case cases[] = {
      {"c[a0.x + 4]", 4, true, RegFile::Addr, 0},
      {"c4[a0.x]", 4, true, RegFile::Addr, 0},
      {"c[4 + a0.x]", 4, true, RegFile::Addr, 0},
      {"c[2 + a0.x + 12]", 14, true, RegFile::Addr, 0},
      {"c4[2]", 6, false, RegFile::Addr, 0},
      {"c[5]", 5, false, RegFile::Addr, 0},
      {"c[aL]", 0, true, RegFile::Loop, 0},
      {"c[aL + 3]", 3, true, RegFile::Loop, 0},
      {"c[a0.y + 1]", 1, true, RegFile::Addr, 1},
      {"c[a0.w]", 0, true, RegFile::Addr, 3},
      {"c[a0.x+4]", 4, true, RegFile::Addr, 0},
      {"c10[a0.z + 2]", 12, true, RegFile::Addr, 2},
      {"c[a0.x - 1 + 8]", 7, true, RegFile::Addr, 0},
      {"c[a0]", 0, true, RegFile::Addr, 0},
  };
  for (const Case& c : cases) {
    auto src = sources("vs_2_0", std::string("mov r0, ") + c.text);
    ASSERT_EQ(src.size(), 1u) << c.text;
    EXPECT_EQ(src[0].file, RegFile::Const) << c.text;
    EXPECT_EQ(src[0].index, c.index) << c.text;
    ASSERT_EQ(src[0].rel.has_value(), c.rel) << c.text;
    if (c.rel) {
      EXPECT_EQ(src[0].rel->file, c.rel_file) << c.text;
      EXPECT_EQ(src[0].rel->component, c.component) << c.text;
    }
  }
}

TEST(ParserOperands, RelativeAddressWithSwizzleAndNegationHasPositions) {
  ir::Program p = must_parse("vs_1_1\nmov r0, -c[a0.x + 4].yx\n");
  const ir::SrcOperand& s = p.code[0].src[0];
  EXPECT_EQ(s.mod, SrcMod::Neg);
  EXPECT_EQ(s.swizzle, ir::make_swizzle(1, 0, 0, 0));
  EXPECT_EQ(s.loc.line, 2u);
  EXPECT_EQ(s.loc.col, 9u);
  EXPECT_EQ(s.loc.length, 15u); // "-c[a0.x + 4].yx"
  ASSERT_TRUE(s.rel);
  EXPECT_EQ(s.rel->loc.col, 12u);
  EXPECT_EQ(s.rel->loc.length, 4u); // "a0.x"
  EXPECT_EQ(p.code[0].dst->loc.col, 5u);
  EXPECT_EQ(p.code[0].dst->loc.length, 2u);
}

} // namespace
} // namespace tierlift::assembly::test
