#include <gtest/gtest.h>

#include <set>

#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/profile.h"
#include "tierlift/ir/registers.h"

using namespace tierlift::ir;

TEST(OpcodeTable, EveryOpcodeHasExactlyOneRow) {
  std::set<Opcode> seen;
  for (const OpInfo& info : opcode_table()) EXPECT_TRUE(seen.insert(info.op).second);
  EXPECT_EQ(seen.size(), static_cast<size_t>(kOpcodeCount));
  for (int i = 0; i < kOpcodeCount; ++i)
    EXPECT_EQ(static_cast<int>(op_info(static_cast<Opcode>(i)).op), i);
}

TEST(OpcodeTable, MnemonicLookupPicksTheRowOfTheProfile) {
  EXPECT_EQ(find_opcode("texld", Profile::ps_1_4)->op, Opcode::TexLd14);
  EXPECT_EQ(find_opcode("texld", Profile::ps_2_0)->op, Opcode::TexLd);
  EXPECT_EQ(find_opcode("texld", Profile::ps_2_0)->num_src, 2);
  EXPECT_EQ(find_opcode("nosuch", Profile::ps_2_0), nullptr);
  // Not legal in ps_1_1: still found, so the validator can name the profiles.
  const OpInfo* dp4 = find_opcode("dp4", Profile::ps_1_1);
  ASSERT_NE(dp4, nullptr);
  EXPECT_FALSE(legal_in(*dp4, Profile::ps_1_1));
}

TEST(OpcodeTable, BytecodeLookup) {
  EXPECT_EQ(find_opcode_by_code(0x42, 0, Profile::ps_1_3)->op, Opcode::Tex);
  EXPECT_EQ(find_opcode_by_code(0x42, 0, Profile::ps_1_4)->op, Opcode::TexLd14);
  EXPECT_EQ(find_opcode_by_code(0x42, 1, Profile::ps_2_0)->op, Opcode::TexLdP);
  EXPECT_EQ(find_opcode_by_code(0x40, 0, Profile::ps_1_4)->op, Opcode::TexCrd);
  EXPECT_EQ(find_opcode_by_code(0x40, 0, Profile::ps_1_1)->op, Opcode::TexCoord);
}

TEST(OpcodeTable, AvailabilityMatchesTheSheet) {
  // docs/d3d9-rules.md §5.8: ps_2_0 has no sge, slt, cnd, dst, lit, expp, logp.
  for (auto mn : {"sge", "slt", "cnd", "dst", "lit", "expp", "logp"})
    EXPECT_FALSE(legal_in(*find_opcode(mn, Profile::ps_2_0), Profile::ps_2_0)) << mn;
  EXPECT_EQ(find_opcode("exp", Profile::vs_1_1)->slots[profile_index(Profile::vs_1_1)], 10);
  EXPECT_EQ(find_opcode("texbeml", Profile::ps_1_1)->extra_arith, 1);
}

TEST(Profile, BothSpellingsAndTokens) {
  EXPECT_EQ(parse_profile("ps.1.3"), Profile::ps_1_3);
  EXPECT_EQ(parse_profile("vs_2_0"), Profile::vs_2_0);
  EXPECT_FALSE(parse_profile("ps_4_0").has_value());
  EXPECT_EQ(version_token(Profile::vs_1_1), 0xFFFE0101u);
  EXPECT_EQ(version_token(Profile::ps_1_4), 0xFFFF0104u);
  EXPECT_EQ(version_token(Profile::ps_2_0), 0xFFFF0200u);
}

TEST(Registers, SwizzleText) {
  EXPECT_EQ(swizzle_text(kIdentitySwizzle), "");
  EXPECT_EQ(swizzle_text(replicate_swizzle(0)), ".x");
  EXPECT_EQ(swizzle_text(make_swizzle(0, 1, 1, 1)), ".xy");
  EXPECT_EQ(swizzle_text(make_swizzle(3, 2, 0, 0)), ".wzx");
  EXPECT_EQ(mask_text(0x7), ".xyz");
  EXPECT_EQ(mask_text(0xF), "");
}
