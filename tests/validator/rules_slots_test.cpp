// Slot limits, worked out by hand from docs/d3d9-rules.md §2 and the §5 slot columns.
#include "validator_test_util.h"

using tierlift::vtest::has_error;
using tierlift::vtest::is_clean;
using tierlift::vtest::only_warns;
using tierlift::vtest::repeat;

namespace {

TEST(SlotRules, Ps13ArithmeticLimit) {
  // 9 movs: lines 2..10, the 9th is on line 10.
  EXPECT_TRUE(has_error("ps_1_3\n" + repeat("mov r0, c0", 9), "slot-limit", 10, 1,
                        {"ps_1_3 allows 8 arithmetic slots; this instruction is the 9th"}));
  EXPECT_TRUE(is_clean("ps_1_3\n" + repeat("mov r0, c0", 8)));
}

TEST(SlotRules, CoissuedPairCostsOneSlot) {
  std::string pairs = repeat("mov r0.rgb, c0\n+mov r0.a, c1", 8); // 16 lines, 8 slots
  EXPECT_TRUE(is_clean("ps_1_3\n" + pairs));
  EXPECT_TRUE(has_error("ps_1_3\n" + pairs + "mov r0, c0\n", "slot-limit", 18, 1,
                        {"allows 8 arithmetic slots; this instruction is the 9th"}));
}

TEST(SlotRules, Ps13TextureLimit) {
  EXPECT_TRUE(has_error("ps_1_3\ntex t0\ntex t1\ntex t2\ntex t3\ntexkill t0\nmov r0, t0\n",
                        "slot-limit", 6, 1,
                        {"ps_1_3 allows 4 texture slots; this instruction is the 5th"}));
  EXPECT_TRUE(is_clean("ps_1_3\ntex t0\ntex t1\ntex t2\ntex t3\nmov r0, t0\n"));
}

TEST(SlotRules, Dp4CostsTwoInPs12) {
  EXPECT_TRUE(has_error("ps_1_2\n" + repeat("mov r0, c0", 7) + "dp4 r0, r0, c1\n", "slot-limit", 9,
                        1, {"ps_1_2 allows 8 arithmetic slots; this dp4 takes slots 8..9"}));
  EXPECT_TRUE(is_clean("ps_1_2\n" + repeat("mov r0, c0", 6) + "dp4 r0, r0, c1\n"));
}

TEST(SlotRules, TexbemlTakesAnArithmeticSlot) {
  // texbeml: 1 texture + 1 arithmetic slot, so the 8th mov is the 9th arithmetic slot.
  EXPECT_TRUE(has_error("ps_1_1\ntex t0\ntexbeml t1, t0\n" + repeat("mov r0, c0", 8), "slot-limit",
                        11, 1, {"allows 8 arithmetic slots; this instruction is the 9th"}));
  EXPECT_TRUE(is_clean("ps_1_1\ntex t0\ntexbeml t1, t0\n" + repeat("mov r0, c0", 7)));
}

TEST(SlotRules, Ps14CountsPerPhase) {
  std::string phase1 = repeat("mov r1, c0", 8) + "phase\n";
  EXPECT_TRUE(is_clean("ps_1_4\n" + phase1 + repeat("mov r0, c0", 8)));
  EXPECT_TRUE(has_error("ps_1_4\n" + phase1 + repeat("mov r0, c0", 9), "slot-limit", 19, 1,
                        {"ps_1_4 allows 8 arithmetic slots per phase (this is phase 2); this "
                         "instruction is the 9th"}));
}

TEST(SlotRules, Vs11TotalCountsMacroSizes) {
  // 1 + 12 x 10 = 121 slots; the 13th exp (10 slots) takes 122..131 > 128.
  std::string head = "vs_1_1\nmov oPos, v0\n";
  EXPECT_TRUE(is_clean(head + repeat("exp r0, v0.x", 12)));
  EXPECT_TRUE(has_error(head + repeat("exp r0, v0.x", 13), "slot-limit", 15, 1,
                        {"vs_1_1 allows 128 instruction slots; this exp takes slots 122..131"}));
}

TEST(SlotRules, Vs20Total) {
  std::string head = "vs_2_0\ndcl_position v0\nmov oPos, v0\n";
  EXPECT_TRUE(is_clean(head + repeat("mov r0, v0", 255)));
  EXPECT_TRUE(has_error(head + repeat("mov r0, v0", 256), "slot-limit", 259, 1,
                        {"vs_2_0 allows 256 instruction slots; this instruction is the 257th"}));
}

TEST(SlotRules, Ps20ArithmeticAndTexture) {
  EXPECT_TRUE(is_clean("ps_2_0\n" + repeat("mov r0, c0", 63) + "mov oC0, r0\n"));
  EXPECT_TRUE(has_error("ps_2_0\n" + repeat("mov r0, c0", 64) + "mov oC0, r0\n", "slot-limit", 66,
                        1, {"ps_2_0 allows 64 arithmetic slots; this instruction is the 65th"}));
  std::string head = "ps_2_0\ndcl t0\ndcl_2d s0\n";
  EXPECT_TRUE(is_clean(head + repeat("texld r0, t0, s0", 32) + "mov oC0, r0\n"));
  EXPECT_TRUE(has_error(head + repeat("texld r0, t0, s0", 33) + "mov oC0, r0\n", "slot-limit", 36,
                        1, {"ps_2_0 allows 32 texture slots; this instruction is the 33rd"}));
}

TEST(SlotRules, Ps12CmpAndDp4Counts) {
  EXPECT_TRUE(is_clean("ps_1_2\nmov r0, c0\n" + repeat("cmp r1, r0, c0, c1", 3)));
  EXPECT_TRUE(has_error("ps_1_2\nmov r0, c0\n" + repeat("cmp r1, r0, c0, c1", 4), "slot-limit", 6,
                        1, {"ps_1_2 allows 3 cmp instructions; this is the 4th"}));
  EXPECT_TRUE(is_clean("ps_1_3\n" + repeat("dp4 r0, c0, c1", 4)));
  EXPECT_TRUE(has_error("ps_1_3\n" + repeat("dp4 r0, c0, c1", 5), "slot-limit", 6, 1,
                        {"ps_1_3 allows 4 dp4 instructions; this is the 5th"}));
}

TEST(SlotRules, ShaderModel3PastTheGuaranteedSlotsWarnsUpToTheLargestCap) {
  // Every 3.0 device has 512 instruction slots; a device may offer up to 32768 (fxc compiles
  // such programs). ps_3_0: line 1 the version, then one mov a line: slot k on line k + 1.
  const std::string ps = "ps_3_0\n";
  EXPECT_TRUE(is_clean(ps + repeat("mov r0, c0", 512) + "mov oC0, r0\n"));
  EXPECT_TRUE(only_warns(ps + repeat("mov r0, c0", 513) + "mov oC0, r0\n", "slot-limit", 514, 1,
                         {"ps_3_0 guarantees 512 instruction slots", "reaches slot 513",
                          "MaxPixelShader30InstructionSlots"}));
  EXPECT_TRUE(
      has_error(ps + repeat("mov r0, c0", 32768) + "mov oC0, r0\n", "slot-limit", 32770, 1,
                {"ps_3_0 allows 32768 instruction slots; this instruction is the 32769th"}));
  const std::string vs = "vs_3_0\ndcl_position o0\n";
  EXPECT_TRUE(only_warns(vs + repeat("mov o0, c0", 513), "slot-limit", 515, 1,
                         {"vs_3_0 guarantees 512", "MaxVertexShader30InstructionSlots"}));
}

} // namespace
