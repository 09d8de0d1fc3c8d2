// Source modifiers, swizzles, write masks, instruction modifiers (shift, _sat) in the order
// of docs/d3d9-rules.md §7, and co-issued pairs (§4.6).
#include "vm_test_util.h"

using namespace vmtest;

namespace {
PixelInput colour(Vec4 v0) {
  PixelInput in;
  in.color[0] = v0;
  return in;
}
tierlift::ir::Conventions max8() {
  tierlift::ir::Conventions c;
  c.ps1x_max_value = 8;
  return c;
}
} // namespace

TEST(VmModifiers, NegateSwizzleAndMask) {
  // -r0 = (−1, −2, −3, −4); r0.wzyx = (4, 3, 2, 1); r0.yzxw = (2, 3, 1, 4);
  // r4 = r2, then r4.xz = r0 → (1, 20, 3, 40).
  auto o = vs20("mov oT0, -r0\nmov oT1, r0.wzyx\nmov oT2, r0.yzxw\nmov r4, r2\nmov r4.xz, r0\n"
                "mov oT3, r4\n",
                bank({{1, 2, 3, 4}, {}, {10, 20, 30, 40}}));
  EXPECT_VEC4(o.tex[0], -1, -2, -3, -4);
  EXPECT_VEC4(o.tex[1], 4, 3, 2, 1);
  EXPECT_VEC4(o.tex[2], 2, 3, 1, 4);
  EXPECT_VEC4(o.tex[3], 1, 20, 3, 40);
}

TEST(VmModifiers, ShortSwizzleRepeatsLast) {
  // .xy = .xyyy → (1, 2, 2, 2)
  auto o = vs20("mov oT0, r0.xy\n", bank({{1, 2, 3, 4}}));
  EXPECT_VEC4(o.tex[0], 1, 2, 2, 2);
}

TEST(VmModifiers, Ps1xSourceModifiers) {
  // v0 = (0.25, 0.75, 1, 0)
  Vec4 v0{0.25f, 0.75f, 1, 0};
  auto run = [&](const char* src) {
    return run_ps(make_vm(std::string("ps_1_1\nmov r0, ") + src + "\n"), colour(v0)).color[0];
  };
  EXPECT_VEC4(run("v0_bias"), -0.25f, 0.25f, 0.5f, -0.5f);  // x − 0.5
  EXPECT_VEC4(run("-v0_bias"), 0.25f, -0.25f, -0.5f, 0.5f); // −(x − 0.5)
  EXPECT_VEC4(run("1-v0"), 0.75f, 0.25f, 0, 1);             // 1 − x
  EXPECT_VEC4(run("v0_bx2"), -0.5f, 0.5f, 1, -1);           // 2x − 1
  EXPECT_VEC4(run("-v0_bx2"), 0.5f, -0.5f, -1, 1);          // −(2x − 1)
  EXPECT_VEC4(run("-v0"), -0.25f, -0.75f, -1, 0);
  EXPECT_VEC4(run("v0.a"), 0, 0, 0, 0); // alpha replicate
}

TEST(VmModifiers, Ps14TimesTwoModifier) {
  // v0_x2 = (0.5, 1.5, 2, 0); -v0_x2 = (−0.5, −1.5, −2, 0) (max value 8)
  Vec4 v0{0.25f, 0.75f, 1, 0};
  auto a = run_ps(make_vm("ps_1_4\nmov r0, v0_x2\n", max8()), colour(v0)).color[0];
  EXPECT_VEC4(a, 0.5f, 1.5f, 2, 0);
  auto b = run_ps(make_vm("ps_1_4\nmov r0, -v0_x2\n", max8()), colour(v0)).color[0];
  EXPECT_VEC4(b, -0.5f, -1.5f, -2, 0);
}

TEST(VmModifiers, ShiftModifiers) {
  // v0 = (0.5, 0.25, 1, 0.125); max value 8.
  Vec4 v0{0.5f, 0.25f, 1, 0.125f};
  auto run = [&](const char* mn) {
    return run_ps(make_vm(std::string("ps_1_4\n") + mn + " r0, v0\n", max8()), colour(v0)).color[0];
  };
  EXPECT_VEC4(run("mov_x2"), 1, 0.5f, 2, 0.25f);
  EXPECT_VEC4(run("mov_x4"), 2, 1, 4, 0.5f);
  EXPECT_VEC4(run("mov_x8"), 4, 2, 8, 1);
  EXPECT_VEC4(run("mov_d2"), 0.25f, 0.125f, 0.5f, 0.0625f);
  EXPECT_VEC4(run("mov_d4"), 0.125f, 0.0625f, 0.25f, 0.03125f);
  EXPECT_VEC4(run("mov_d8"), 0.0625f, 0.03125f, 0.125f, 0.015625f);
}

TEST(VmModifiers, ShiftThenSaturate) {
  // _x2 then _sat: (0.75, 0.25, 0.5, 0)·2 = (1.5, 0.5, 1, 0) → (1, 0.5, 1, 0).
  // (Saturating first would give 1.5 → clamp to max 8 → 1.5.)
  auto out =
      run_ps(make_vm("ps_1_4\nmov_x2_sat r0, v0\n", max8()), colour({0.75f, 0.25f, 0.5f, 0}));
  EXPECT_VEC4(out.color[0], 1, 0.5f, 1, 0);
}

TEST(VmModifiers, SaturatePs20) {
  // (1, 2, 3, 4) + (−2, −1.5, −2.75, −3.5) = (−1, 0.5, 0.25, 0.5) → sat (0, 0.5, 0.25, 0.5)
  Vec4 r = ps20("add_sat r4, r0, r1\n", bank({{1, 2, 3, 4}, {-2, -1.5f, -2.75f, -3.5f}}));
  EXPECT_VEC4(r, 0, 0.5f, 0.25f, 0.5f);
}

TEST(VmModifiers, RangeClampAfterShift) {
  // ps_1_1 max 1: mul_x4 of 0.5·0.5 = 1; add_x2 of 0.75 + 0.75 = 3 → clamp 1.
  auto out = run_ps(make_vm("ps_1_1\nadd_x2 r0, v0, v0\n"), colour({0.75f, 0.25f, 0, 0.125f}));
  EXPECT_VEC4(out.color[0], 1, 1, 0, 0.5f); // (3→1, 1, 0, 0.5)
}

TEST(VmModifiers, CoissuedPairReadsBeforeWrite) {
  // r0 = (0.25, 0.5, 0.75, 0.5). Pair: mul r0.rgb, r0, r0.a / +mov r0.a, r0.b
  // rgb = r0.rgb · old a 0.5 = (0.125, 0.25, 0.375); a = old b = 0.75.
  // (In sequence the second half would read the new b = 0.375.)
  auto vm = make_vm("ps_1_1\ndef c0, 0.25, 0.5, 0.75, 0.5\nmov r0, c0\n"
                    "mul r0.rgb, r0, r0.a\n+mov r0.a, r0.b\n");
  EXPECT_VEC4(run_ps(vm).color[0], 0.125f, 0.25f, 0.375f, 0.75f);
}

TEST(VmModifiers, CoissuedCndReadsOldR0) {
  // r0.a = 0.25 before the pair; the pair writes r0.a = 0.75 and co-issues
  // cnd r1.rgb, r0.a, c1, c3. Read-before-write: 0.25 > 0.5 fails → c3 = 0.5 (DXVK's
  // result; Wine's "always src1" and in-order execution would both give c1 = 1).
  auto vm = make_vm("ps_1_1\ndef c0, 0, 0, 0, 0.25\ndef c1, 1, 1, 1, 1\n"
                    "def c2, 0, 0, 0, 0.75\ndef c3, 0.5, 0.5, 0.5, 0.5\nmov r0, c0\n"
                    "mov r0.a, c2\n+cnd r1.rgb, r0.a, c1, c3\nmov r0.rgb, r1\n");
  EXPECT_VEC4(run_ps(vm).color[0], 0.5f, 0.5f, 0.5f, 0.75f);
}

TEST(VmModifiers, Ps1xConstantClampBeforeModifier) {
  // ps_1_4: c0 = 3 reads as 1 before any arithmetic: 1 + v0 (0.25) = 1.25 (max 8).
  auto out = run_ps(make_vm("ps_1_4\ndef c0, 3, -3, 0.5, 0\nadd r0, c0, v0\n", max8()),
                    colour({0.25f, 0.25f, 0.25f, 0.25f}));
  EXPECT_VEC4(out.color[0], 1.25f, -0.75f, 0.75f, 0.25f);
}

TEST(VmModifiers, Ps20OutputsAndDepth) {
  // oC0 and oC1 written, oDepth from r0.x.
  auto vm = make_vm("ps_2_0\ndef c0, 0.5, 0.25, 0.125, 1\ndef c1, 1, 0, 0, 1\nmov r0, c0\n"
                    "mov r1, c1\nmov oC0, r0\nmov oC1, r1\nmov oDepth, r0.x\n");
  auto out = run_ps(vm);
  EXPECT_VEC4(out.color[0], 0.5f, 0.25f, 0.125f, 1);
  EXPECT_VEC4(out.color[1], 1, 0, 0, 1);
  EXPECT_EQ(out.color_written, 3);
  ASSERT_TRUE(out.depth.has_value());
  EXPECT_EQ(*out.depth, 0.5f);
}
