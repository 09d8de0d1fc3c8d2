// Versions, comments, declarations, definitions and instruction modifiers.
#include <bit>

#include "test_util.h"

namespace tierlift::assembly::test {
namespace {

using ir::Opcode;
using ir::RegFile;

TEST(ParserVersion, BothSpellingsGiveTheSameProfile) {
  const std::pair<const char*, ir::Profile> cases[] = {
      {"vs.1.1", ir::Profile::vs_1_1}, {"vs_1_1", ir::Profile::vs_1_1},
      {"vs.2.0", ir::Profile::vs_2_0}, {"vs_2_0", ir::Profile::vs_2_0},
      {"ps.1.1", ir::Profile::ps_1_1}, {"ps_1_2", ir::Profile::ps_1_2},
      {"ps.1.3", ir::Profile::ps_1_3}, {"ps_1_4", ir::Profile::ps_1_4},
      {"ps.2.0", ir::Profile::ps_2_0}, {"PS_2_0", ir::Profile::ps_2_0}};
  for (auto [text, profile] : cases) {
    ir::Program p = must_parse(std::string(text) + "\n");
    EXPECT_EQ(p.profile, profile) << text;
    EXPECT_EQ(p.version_loc.line, 1u);
    EXPECT_EQ(p.version_loc.col, 1u);
  }
}

TEST(ParserVersion, UnsupportedVersionIsNamed) {
  expect_first_errors(
      {{.text = "ps_4_0\nmov oC0, r0\n", .rule = "unsupported-version", .line = 1, .col = 1}});
}

TEST(ParserComments, AllCommentFormsAreIgnored) {
  ir::Program p = must_parse("; leading comment\n"
                             "// another\n"
                             "/* block\n spanning */ vs_1_1 /* inline */ ; trailing\n"
                             "mov oPos, v0 // c++ style\n"
                             "mov /* in the middle */ oD0, v1 ; asm style\n"
                             "/* a */ /* b */ mov oT0, v2\n");
  ASSERT_EQ(p.code.size(), 3u);
  EXPECT_EQ(p.code[1].loc.line, 6u);
  EXPECT_EQ(p.code[1].loc.col, 1u);
  EXPECT_EQ(p.code[1].dst->loc.col, 25u); // "mov " + 19-byte comment + " "
  EXPECT_EQ(p.code[2].loc.line, 7u);
  EXPECT_EQ(p.code[2].loc.col, 17u);
}

TEST(ParserWhitespace, NoBreakSpaceTabAndCarriageReturnAreWhiteSpace) {
  ir::Program p = must_parse("ps.1.3\r\n\ttex\xC2\xA0t0\r\nmul\xC2\xA0\xC2\xA0r0, t0,\tc0\r\n");
  ASSERT_EQ(p.code.size(), 2u);
  EXPECT_EQ(p.code[0].op, Opcode::Tex);
  EXPECT_EQ(p.code[0].dst->loc.col, 7u);    // byte columns: tab = 1 byte, U+00A0 = 2 bytes
  EXPECT_EQ(p.code[1].src[0].loc.col, 12u); // mul, 2 x 2 bytes, "r0, "
}

TEST(ParserDecl, VertexUsagesWithAndWithoutIndex) {
  ir::Program p = must_parse(
      "vs_2_0\ndcl_position v0\ndcl_texcoord v1\ndcl_texcoord3 v2.xy\ndcl_blendindices15 v3\n"
      "dcl_color1 v4\ndcl_positiont v5\n");
  ASSERT_EQ(p.decls.size(), 6u);
  EXPECT_EQ(p.decls[0].usage, ir::DeclUsage::Position);
  EXPECT_EQ(p.decls[1].usage, ir::DeclUsage::TexCoord);
  EXPECT_EQ(p.decls[1].usage_index, 0);
  EXPECT_EQ(p.decls[2].usage_index, 3);
  EXPECT_EQ(p.decls[2].reg.mask, 0x3);
  EXPECT_EQ(p.decls[2].reg.index, 2u);
  EXPECT_EQ(p.decls[3].usage, ir::DeclUsage::BlendIndices);
  EXPECT_EQ(p.decls[3].usage_index, 15);
  EXPECT_EQ(p.decls[4].usage, ir::DeclUsage::Color);
  EXPECT_EQ(p.decls[5].usage, ir::DeclUsage::PositionT);
  EXPECT_EQ(p.decls[5].seq, 5u);
}

TEST(ParserDecl, PixelDeclarationsAndSamplers) {
  ir::Program p =
      must_parse("ps_2_0\ndcl t0.xy\ndcl_pp t1\ndcl_centroid_pp v0\ndcl_pp_centroid t2.xyz\n"
                 "dcl_2d s0\ndcl_cube s1\ndcl_volume s15\n");
  ASSERT_EQ(p.decls.size(), 7u);
  EXPECT_EQ(p.decls[0].reg.file, RegFile::Texture);
  EXPECT_EQ(p.decls[0].reg.mask, 0x3);
  EXPECT_TRUE(p.decls[1].mods.pp);
  EXPECT_TRUE(p.decls[2].mods.pp && p.decls[2].mods.centroid);
  EXPECT_EQ(p.decls[2].reg.file, RegFile::Input);
  EXPECT_TRUE(p.decls[3].mods.pp && p.decls[3].mods.centroid);
  EXPECT_EQ(p.decls[4].sampler_type, ir::SamplerType::Tex2D);
  EXPECT_EQ(p.decls[5].sampler_type, ir::SamplerType::Cube);
  EXPECT_EQ(p.decls[6].sampler_type, ir::SamplerType::Volume);
  EXPECT_EQ(p.decls[6].reg.index, 15u);
}

TEST(ParserDef, FloatsAreReadExactly) {
  ir::Program p =
      must_parse("ps_2_0\ndef c0, 1, 1.0, .5, -0.25\ndef c1, 1.0f, 1e-3, -0, 0.1\n"
                 "def c2, 3.4028235e38, 1e-45, +2, -.75f\ndef c3, 2.f, 5., 1E2, 2.5e+1F\n");
  ASSERT_EQ(p.defs.size(), 4u);
  EXPECT_EQ(p.defs[3].raw[0], 0x40000000u); // 2
  EXPECT_EQ(p.defs[3].raw[1], 0x40A00000u); // 5
  EXPECT_EQ(p.defs[3].raw[2], 0x42C80000u); // 100
  EXPECT_EQ(p.defs[3].raw[3], 0x41C80000u); // 25
  EXPECT_EQ(p.defs[0].raw[0], 0x3F800000u);
  EXPECT_EQ(p.defs[0].raw[1], 0x3F800000u);
  EXPECT_EQ(p.defs[0].raw[2], 0x3F000000u);
  EXPECT_EQ(p.defs[0].raw[3], 0xBE800000u);
  EXPECT_EQ(p.defs[1].raw[0], 0x3F800000u);
  EXPECT_EQ(p.defs[1].raw[1], 0x3A83126Fu); // 0.001f, nearest float
  EXPECT_EQ(p.defs[1].raw[2], 0x80000000u); // -0 keeps its sign
  EXPECT_EQ(p.defs[1].raw[3], 0x3DCCCCCDu); // 0.1f
  EXPECT_EQ(p.defs[2].raw[0], 0x7F7FFFFFu); // FLT_MAX
  EXPECT_EQ(p.defs[2].raw[1], 0x00000001u); // smallest denormal
  EXPECT_EQ(p.defs[2].raw[2], 0x40000000u);
  EXPECT_EQ(p.defs[2].raw[3], 0xBF400000u);
}

TEST(ParserDef, IntegersAndBooleans) {
  ir::Program p = must_parse("vs_2_0\ndefi i3, 255, 0, -128, 0\ndefb b1, true\ndefb b2, FALSE\n");
  ASSERT_EQ(p.defs.size(), 3u);
  EXPECT_EQ(p.defs[0].file, RegFile::ConstInt);
  EXPECT_EQ(p.defs[0].index, 3u);
  EXPECT_EQ(p.defs[0].i(0), 255);
  EXPECT_EQ(p.defs[0].i(2), -128);
  EXPECT_EQ(p.defs[1].file, RegFile::ConstBool);
  EXPECT_TRUE(p.defs[1].b());
  EXPECT_FALSE(p.defs[2].b());
}

TEST(ParserMods, InstructionModifiersInAnyOrder) {
  ir::Program p =
      must_parse("ps_1_4\nmul_x2 r0, r1, r2\nmul_sat_x4 r0, r1, r2\nmul_x8_sat r0, r1, r2\n"
                 "mul_d2 r0, r1, r2\nmul_d4 r0, r1, r2\nmul_d8 r0, r1, r2\nmov_pp r0, r1\n"
                 "mov_centroid_pp_sat r0, r1\n");
  ASSERT_EQ(p.code.size(), 8u);
  EXPECT_EQ(p.code[0].mods.shift, 1);
  EXPECT_EQ(p.code[1].mods.shift, 2);
  EXPECT_TRUE(p.code[1].mods.sat);
  EXPECT_EQ(p.code[2].mods.shift, 3);
  EXPECT_TRUE(p.code[2].mods.sat);
  EXPECT_EQ(p.code[3].mods.shift, -1);
  EXPECT_EQ(p.code[4].mods.shift, -2);
  EXPECT_EQ(p.code[5].mods.shift, -3);
  EXPECT_TRUE(p.code[6].mods.pp);
  EXPECT_TRUE(p.code[7].mods.pp && p.code[7].mods.centroid && p.code[7].mods.sat);
}

TEST(ParserMods, CoissueAndSequenceNumbers) {
  ir::Program p =
      must_parse("ps.1.1\ndef c0, 1, 1, 1, 1\ntex t0\nmul r0.rgb, t0, v0\n+add r0.a, t0, c0\n");
  ASSERT_EQ(p.code.size(), 3u);
  EXPECT_FALSE(p.code[1].coissue);
  EXPECT_TRUE(p.code[2].coissue);
  EXPECT_EQ(p.code[1].dst->mask, 0x7);
  EXPECT_EQ(p.code[2].dst->mask, 0x8);
  EXPECT_EQ(p.defs[0].seq, 0u);
  EXPECT_EQ(p.code[0].seq, 1u);
  EXPECT_EQ(p.code[2].seq, 3u);
  EXPECT_EQ(p.code[2].loc.col, 2u);
}

TEST(ParserMods, MnemonicsAndRegistersIgnoreCase) {
  ir::Program p = must_parse("VS_1_1\nMOV OPOS, V0\nMov oD0, v1.XYZW\nmov opos.X, v0\n");
  ASSERT_EQ(p.code.size(), 3u);
  EXPECT_EQ(p.code[0].op, Opcode::Mov);
  EXPECT_EQ(p.code[0].dst->file, RegFile::RastOut);
  EXPECT_EQ(p.code[1].src[0].swizzle, ir::kIdentitySwizzle);
  EXPECT_EQ(p.code[2].dst->mask, 0x1);
}

TEST(ParserMods, NotLegalInProfileStillParsesWithThatRowsShape) {
  // rcp exists but not in ps_1_1: parsed with its shape, the validator reports it.
  ir::Program p = must_parse("ps_1_1\nrcp r0, r1.x\n");
  ASSERT_EQ(p.code.size(), 1u);
  EXPECT_EQ(p.code[0].op, Opcode::Rcp);
  // texld in ps_1_4 takes one source, in ps_2_0 two.
  EXPECT_EQ(must_parse("ps_1_4\ntexld r0, t0\n").code[0].op, Opcode::TexLd14);
  EXPECT_EQ(must_parse("ps_2_0\ntexld r0, t0, s0\n").code[0].op, Opcode::TexLd);
}

TEST(ParserMods, SeveralStatementsOnOneLine) {
  ir::Program p = must_parse("vs_1_1 mov oPos, v0 mov oD0, v1\n");
  ASSERT_EQ(p.code.size(), 2u);
  EXPECT_EQ(p.code[1].loc.col, 21u);
}

} // namespace
} // namespace tierlift::assembly::test
