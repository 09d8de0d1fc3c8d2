// One test per rule of NUMERICS.md, named as NUMERICS.md names it. Every expected value is
// worked out by hand in the comment beside it.
#include <cfloat>
#include <cmath>

#include "tierlift/ir/numerics.h"
#include "vm_test_util.h"

using namespace vmtest;

namespace {
// `op` (rcp, rsq, log, ...) of a in vs_2_0, written to oT0, and of b, written to oT1.
VertexOutput op_of_two(const char* op, float a, float b, tierlift::ir::Conventions conv = {}) {
  const std::string o(op);
  return vs("vs_2_0", o + " r4, r0.x\nmov oT0, r4\n" + o + " r5, r0.y\nmov oT1, r5\n",
            bank({{a, b, 0, 0}}), conv);
}
// c0 = `r`, and c[20 + k] = (k, 0, 0, 0) for k = -16..19: a relative read c[a0 + 20] shows
// the address register's value k in .x.
ConstantBank with_offsets(Vec4 r) {
  ConstantBank c = bank({r});
  c.f.resize(40);
  for (int i = 4; i < 40; ++i) c.f[i] = {float(i - 20), 0, 0, 0};
  return c;
}
} // namespace

TEST(Numerics, RcpOfZeroIsFltMax) {
  // rcp(+0) and rcp(-0) are both +FLT_MAX (doc pseudo-code "f == 0 ? +big").
  auto o = op_of_two("rcp", 0.0f, -0.0f);
  EXPECT_EQ(o.tex[0][0], FLT_MAX);
  EXPECT_EQ(o.tex[1][3], FLT_MAX);
}

TEST(Numerics, RcpOfOneIsExact) {
  // rcp(1) = 1 exactly; rcp(4) = 0.25 (exact in binary).
  auto o = op_of_two("rcp", 1.0f, 4.0f);
  EXPECT_EQ(o.tex[0][0], 1.0f);
  EXPECT_EQ(o.tex[1][0], 0.25f);
}

TEST(Numerics, RcpOverflowClampsToFltMax) {
  // 2^-140 is a denormal; 1/2^-140 = 2^140 > FLT_MAX (≈ 2^128) → clamps to ±FLT_MAX when
  // denormals are kept (Rounding::Exact; under Llvmpipe it is rcp(±0), rule 13).
  float tiny = std::ldexp(1.0f, -140);
  tierlift::ir::Conventions exact;
  exact.rounding = tierlift::ir::Rounding::Exact;
  auto o = op_of_two("rcp", tiny, -tiny, exact);
  EXPECT_EQ(o.tex[0][0], FLT_MAX);
  EXPECT_EQ(o.tex[1][0], -FLT_MAX);
  // rcp(2^127) = 2^-127, a denormal result, kept.
  EXPECT_EQ(tierlift::ir::numerics::legacy_rcp(0x1p127f), 0x1p-127f);
}

TEST(Numerics, RsqOfZeroIsFltMax) {
  auto o = op_of_two("rsq", 0.0f, -0.0f);
  EXPECT_EQ(o.tex[0][0], FLT_MAX);
  EXPECT_EQ(o.tex[1][0], FLT_MAX);
}

TEST(Numerics, RsqOfNegativeUsesAbs) {
  // rsq(-4) = 1/sqrt(4) = 0.5; rsq(-1) = 1 exactly (never NaN).
  auto o = op_of_two("rsq", -4.0f, -1.0f);
  EXPECT_EQ(o.tex[0][0], 0.5f);
  EXPECT_EQ(o.tex[1][0], 1.0f);
}

TEST(Numerics, LogOfZeroIsMinusFltMax) {
  auto o = op_of_two("log", 0.0f, -0.0f);
  EXPECT_EQ(o.tex[0][0], -FLT_MAX);
  EXPECT_EQ(o.tex[1][0], -FLT_MAX);
}

TEST(Numerics, LogOfNegativeUsesAbs) {
  // log2|-8| = 3; log2|-0.5| = -1.
  auto o = op_of_two("log", -8.0f, -0.5f);
  EXPECT_EQ(o.tex[0][0], 3.0f);
  EXPECT_EQ(o.tex[1][0], -1.0f);
}

TEST(Numerics, ExpOverflowIsFltMax) {
  // 2^128 and 2^inf overflow fp32 → +FLT_MAX; 2^-inf = 0; 2^3 = 8.
  auto o = vs20("exp r4, r0.x\nmov oT0, r4\nexp r5, r0.y\nmov oT1, r5\n"
                "exp r6, r0.z\nmov oT2, r6\nexp r7, r0.w\nmov oT3, r7\n",
                bank({{128.0f, inf_f(), -inf_f(), 3.0f}}));
  EXPECT_EQ(o.tex[0][0], FLT_MAX);
  EXPECT_EQ(o.tex[1][0], FLT_MAX);
  EXPECT_EQ(o.tex[2][0], 0.0f);
  EXPECT_EQ(o.tex[3][0], 8.0f);
}

TEST(Numerics, ZeroTimesInfIsZero) {
  // mul (0,inf,-inf,0)·(inf,0,0,-inf) = 0 everywhere; mad adds 1 → 1; dp4 → 0.
  float i = inf_f();
  auto c = bank({{0, i, -i, 0}, {i, 0, 0, -i}, {1, 1, 1, 1}});
  auto o = vs20("mul r4, r0, r1\nmov oT0, r4\nmad r5, r0, r1, r2\nmov oT1, r5\n"
                "dp4 r6, r0, r1\nmov oT2, r6\n",
                c);
  EXPECT_VEC4(o.tex[0], 0, 0, 0, 0);
  EXPECT_VEC4(o.tex[1], 1, 1, 1, 1);
  EXPECT_VEC4(o.tex[2], 0, 0, 0, 0);
}

TEST(Numerics, ZeroTimesNanIsZero) {
  // (0, NaN, 0, 2)·(NaN, 0, -0, 3) = (0, 0, 0, 6).
  float n = nan_f();
  auto o = vs20("mul r4, r0, r1\nmov oT0, r4\n", bank({{0, n, 0, 2}, {n, 0, -0.0f, 3}}));
  EXPECT_VEC4(o.tex[0], 0, 0, 0, 6);
}

TEST(Numerics, MinMaxWithNan) {
  // min = (a < b) ? a : b; max = (a >= b) ? a : b; a NaN compare is false → b.
  // a = (NaN, 1, NaN, 2), b = (1, NaN, NaN, 3): min = (1, NaN, NaN, 2), max = (1, NaN, NaN, 3).
  float n = nan_f();
  auto o = vs20("min r4, r0, r1\nmov oT0, r4\nmax r5, r0, r1\nmov oT1, r5\n",
                bank({{n, 1, n, 2}, {1, n, n, 3}}));
  EXPECT_EQ(o.tex[0][0], 1.0f);
  EXPECT_TRUE(std::isnan(o.tex[0][1]));
  EXPECT_TRUE(std::isnan(o.tex[0][2]));
  EXPECT_EQ(o.tex[0][3], 2.0f);
  EXPECT_EQ(o.tex[1][0], 1.0f);
  EXPECT_TRUE(std::isnan(o.tex[1][1]));
  EXPECT_TRUE(std::isnan(o.tex[1][2]));
  EXPECT_EQ(o.tex[1][3], 3.0f);
}

TEST(Numerics, CmpCndWithNan) {
  // cmp: (s0 >= 0) ? s1 : s2 with s0 = (NaN, 1, -1, 0) → (20, 10, 20, 10).
  float n = nan_f();
  Vec4 r = ps20("cmp r4, r0, r1, r2\n", bank({{n, 1, -1, 0}, {10, 10, 10, 10}, {20, 20, 20, 20}}));
  EXPECT_VEC4(r, 20, 10, 20, 10);
  // cnd (ps_1_4, per component): (s0 > 0.5) ? s1 : s2, s0 = (NaN, 0.6, 0.5, 0.4)
  // → (0.75, 0.25, 0.75, 0.75).
  auto vm = make_vm("ps_1_4\ndef c1, 0.25, 0.25, 0.25, 0.25\ndef c2, 0.75, 0.75, 0.75, 0.75\n"
                    "mov r1, c0\ncnd r0, r1, c1, c2\n");
  auto out = run_ps(vm, {}, nullptr, bank({{n, 0.6f, 0.5f, 0.4f}}));
  EXPECT_VEC4(out.color[0], 0.75f, 0.25f, 0.75f, 0.75f);
}

TEST(Numerics, SgeSltWithNan) {
  // a = (NaN, 1, NaN, 0), b = (1, NaN, NaN, 0): sge = (0, 0, 0, 1), slt = (0, 0, 0, 0).
  float n = nan_f();
  auto o = vs20("sge r4, r0, r1\nmov oT0, r4\nslt r5, r0, r1\nmov oT1, r5\n",
                bank({{n, 1, n, 0}, {1, n, n, 0}}));
  EXPECT_VEC4(o.tex[0], 0, 0, 0, 1);
  EXPECT_VEC4(o.tex[1], 0, 0, 0, 0);
}

TEST(Numerics, SgnOfNan) {
  // (x < 0) ? -1 : (x == 0) ? 0 : 1 on (NaN, -2, 0, 3) → (1, -1, 0, 1).
  auto o = vs20("sgn r4, r0, r5, r6\nmov oT0, r4\n", bank({{nan_f(), -2, 0, 3}}));
  EXPECT_VEC4(o.tex[0], 1, -1, 0, 1);
}

TEST(Numerics, DenormalsAreKept) {
  // Rounding::Exact: 2^-140 · 0.5 = 2^-141 (a denormal, exact); 2^-140 + 0 = 2^-140.
  float d = std::ldexp(1.0f, -140);
  tierlift::ir::Conventions exact;
  exact.rounding = tierlift::ir::Rounding::Exact;
  auto o = vs("vs_2_0", "mul r4, r0, r1\nmov oT0, r4\nadd r5, r0, r2\nmov oT1, r5\n",
              bank({{d, d, d, d}, {0.5f, 0.5f, 0.5f, 0.5f}, {0, 0, 0, 0}}), exact);
  EXPECT_EQ(o.tex[0][0], std::ldexp(1.0f, -141));
  EXPECT_EQ(o.tex[1][0], d);
}

TEST(Numerics, DenormalsFlushLikeLavapipe) {
  // Rounding::Llvmpipe (the default): an operation reads a denormal as the zero of its sign
  // and writes a denormal result as the zero of its sign; mov keeps the bits.
  namespace num = tierlift::ir::numerics;
  constexpr auto F = num::Denormals::Flush;
  const float d = 0x1p-140f;
  auto sign = [](float x) { return std::signbit(x); };
  // The function the rules share: the zero of the denormal's sign, everything else kept.
  EXPECT_EQ(num::flush_denormal(d), 0.0f);
  EXPECT_FALSE(sign(num::flush_denormal(d)));
  EXPECT_TRUE(sign(num::flush_denormal(-d)));
  EXPECT_EQ(num::flush_denormal(FLT_MIN), FLT_MIN);
  EXPECT_TRUE(std::isnan(num::flush_denormal(nan_f())));
  // Operand flushed: (−0) + (+0) = +0 (a flushed result would be −0).
  EXPECT_FALSE(sign(num::legacy_add<F>(-d, 0.0f)));
  EXPECT_EQ(num::legacy_add<F>(d, FLT_MIN), FLT_MIN);
  // Result flushed, sign kept: 2^-70 · −2^-70 = −2^-140 → −0 (legacy_mul's product).
  EXPECT_TRUE(sign(num::legacy_mul<F>(0x1p-70f, -0x1p-70f)));
  EXPECT_EQ(num::legacy_mul<F>(-d, 0x1p100f), 0.0f); // rule 8: a zero factor gives +0
  EXPECT_FALSE(sign(num::legacy_mul<F>(-d, 0x1p100f)));
  // mad: the product 2^-140 is flushed before the sum.
  EXPECT_EQ(num::legacy_mad<F>(0x1p-70f, 0x1p-70f, FLT_MIN), FLT_MIN);
  // The issue-16 cases: rcp/rsq/log of ±denormal are those of ±0 (rules 1, 3, 5).
  EXPECT_EQ(num::legacy_rcp<F>(-d), FLT_MAX);
  EXPECT_EQ(num::legacy_rsq<F>(d), FLT_MAX);
  EXPECT_EQ(num::legacy_log<F>(-d), -FLT_MAX);
  // exp: 2^-130 is below 2^-126 → 0.
  EXPECT_EQ(num::legacy_exp<F>(-130.0f), 0.0f);
  // Comparisons read zeros; the select hands on the operand's own bits.
  EXPECT_EQ(num::legacy_cmp<F>(-d, 1.0f, 2.0f), 1.0f);
  EXPECT_EQ(num::legacy_slt<F>(-d, 0.0f), 0.0f);
  EXPECT_EQ(num::legacy_min<F>(-d, 0.0f), 0.0f); // −0 < +0 is false → src1
  EXPECT_EQ(num::legacy_max<F>(-d, 0.0f), -d);   // −0 ≥ +0 → src0, its bits
  EXPECT_EQ(num::legacy_sgn<F>(d), 0.0f);
  EXPECT_EQ(num::legacy_frc<F>(-d), 0.0f); // not rule 22's 1.0
  EXPECT_EQ(num::legacy_saturate<F>(d), 0.0f);
  EXPECT_EQ(num::legacy_mov_a0_floor<F>(-d), 0);
  // ps_1_x clamps flush (lavapipe's min/max instructions).
  EXPECT_TRUE(sign(num::legacy_ps1x_const<F>(-d)));
  EXPECT_EQ(num::legacy_ps1x_const<F>(-d), 0.0f);
  // Through the VM: mov keeps, add flushes, a def loads flushed.
  auto o = vs20("mov oT0, r0\nadd r5, r0, r2\nmov oT1, r5\n", bank({{d, -d, d, -d}, {}, {}}));
  EXPECT_EQ(o.tex[0][1], -d);
  EXPECT_EQ(o.tex[1][0], 0.0f);
  EXPECT_FALSE(sign(o.tex[1][1]));
  auto def = make_vm("vs_2_0\ndef c10, 1e-40, -1e-40, 0, 0\ndcl_position v0\nmov oPos, v0\n"
                     "mov oT0, c10\n")
                 .run_vertex(VertexInput{}, bank({}));
  EXPECT_EQ(def.tex[0][0], 0.0f);
  EXPECT_TRUE(sign(def.tex[0][1]));
}

TEST(Numerics, MadIsNotFused) {
  // a = b = 1 + 2^-12: a·b = 1 + 2^-11 + 2^-24, which rounds (tie to even) to 1 + 2^-11.
  // Unfused: (1 + 2^-11) − (1 + 2^-11) = 0. Fused it would be 2^-24.
  float a = 1.0f + std::ldexp(1.0f, -12);
  float c = -(1.0f + std::ldexp(1.0f, -11));
  auto o =
      vs20("mad r4, r0, r1, r2\nmov oT0, r4\n", bank({{a, a, a, a}, {a, a, a, a}, {c, c, c, c}}));
  EXPECT_EQ(o.tex[0][0], 0.0f);
  Vec4 r = ps20("mad r4, r0, r1, r2\n", bank({{a, a, a, a}, {a, a, a, a}, {c, c, c, c}}));
  EXPECT_EQ(r[0], 0.0f);
}

TEST(Numerics, DotProductsSumLeftToRight) {
  // dp3 (1e8, 1, -1e8)·(1,1,1): (1e8 + 1) rounds to 1e8 (ulp 8), − 1e8 = 0.
  // dp4 with w = 1: 0 + 1 = 1.
  auto o = vs20("dp3 r4, r0, r1\nmov oT0, r4\ndp4 r5, r0, r1\nmov oT1, r5\n",
                bank({{1e8f, 1, -1e8f, 1}, {1, 1, 1, 1}}));
  EXPECT_EQ(o.tex[0][0], 0.0f);
  EXPECT_EQ(o.tex[1][0], 1.0f);
}

TEST(Numerics, PowOfZeroToZeroIsOne) {
  // pow(x, 0) = 1 for x = 0, NaN, inf; pow(0, 2) = 0; pow(0, -1) = +FLT_MAX.
  auto o = vs20("pow r4, r0.x, r1.x\nmov oT0, r4\npow r5, r0.y, r1.x\nmov oT1, r5\n"
                "pow r6, r0.z, r1.x\nmov oT2, r6\npow r7, r0.x, r1.y\nmov oT3, r7\n"
                "pow r8, r0.x, r1.z\nmov oT4, r8\n",
                bank({{0, nan_f(), inf_f(), 0}, {0, 2, -1, 0}}));
  EXPECT_EQ(o.tex[0][0], 1.0f);
  EXPECT_EQ(o.tex[1][0], 1.0f);
  EXPECT_EQ(o.tex[2][0], 1.0f);
  EXPECT_EQ(o.tex[3][0], 0.0f);
  EXPECT_EQ(o.tex[4][0], FLT_MAX);
}

TEST(Numerics, PowUsesAbsBase) {
  // |-2|^3 = exp2(3·log2 2) = 8; |-4|^0.5 = exp2(0.5·2) = 2.
  auto o = vs20("pow r4, r0.x, r1.x\nmov oT0, r4\npow r5, r0.y, r1.y\nmov oT1, r5\n",
                bank({{-2, -4, 0, 0}, {3, 0.5f, 0, 0}}));
  EXPECT_EQ(o.tex[0][0], 8.0f);
  EXPECT_EQ(o.tex[1][0], 2.0f);
}

TEST(Numerics, NrmOfZeroIsZero) {
  // (0,0,0,5): squared length 0 → scale 0 → (0,0,0,0).
  // (3,4,0,2): length 5 → scale 1/5 → (0.6, 0.8, 0, 0.4).
  auto o = vs20("nrm r4, r0\nmov oT0, r4\nnrm r5, r1\nmov oT1, r5\n",
                bank({{0, 0, 0, 5}, {3, 4, 0, 2}}));
  EXPECT_VEC4(o.tex[0], 0, 0, 0, 0);
  EXPECT_VEC4(o.tex[1], 0.6f, 0.8f, 0, 0.4f);
}

TEST(Numerics, LitEdgeCases) {
  // (1, 0, _, 0): x > 0 → y = 1; y = 0 is not > 0 → z = 0 (no 0^0). → (1, 1, 0, 1)
  // (0, .5, _, 2): x = 0 is not > 0 → (1, 0, 0, 1)
  // (1, .5, _, 0): z = 0.5^0 = 1 → (1, 1, 1, 1)
  // (2, 2, _, 200): power clamps to 127.9961 → z = 2^127.9961 ≈ 3.3936e38 (finite)
  auto o = vs11("lit oT0, r0\nlit oT1, r1\nlit oT2, r2\nlit oT3, r3\n",
                bank({{1, 0, 0, 0}, {0, 0.5f, 0, 2}, {1, 0.5f, 0, 0}, {2, 2, 0, 200}}));
  EXPECT_VEC4(o.tex[0], 1, 1, 0, 1);
  EXPECT_VEC4(o.tex[1], 1, 0, 0, 1);
  EXPECT_VEC4(o.tex[2], 1, 1, 1, 1);
  EXPECT_NEAR(o.tex[3][2] / std::exp2(127.9961), 1.0, 1e-5);
  EXPECT_EQ(o.tex[3][1], 2.0f);
}

TEST(Numerics, MovaRoundsHalfAwayFromZero) {
  // mova a0, (0.5, -0.5, 2.5, -1.49) → (1, -1, 3, -1); c[20 + k] holds k in .x.
  const ConstantBank c = with_offsets({0.5f, -0.5f, 2.5f, -1.49f});
  auto o = vs20("mova a0, r0\nmov oT0, c[a0.x + 20]\nmov oT1, c[a0.y + 20]\n"
                "mov oT2, c[a0.z + 20]\nmov oT3, c[a0.w + 20]\n",
                c);
  EXPECT_EQ(o.tex[0][0], 1.0f);
  EXPECT_EQ(o.tex[1][0], -1.0f);
  EXPECT_EQ(o.tex[2][0], 3.0f);
  EXPECT_EQ(o.tex[3][0], -1.0f);
}

TEST(Numerics, MovA0Floors) {
  // vs_1_1 mov a0.x floors: 1.7 → 1, -0.5 → -1, 2.5 → 2.
  const ConstantBank c = with_offsets({1.7f, -0.5f, 2.5f, 0});
  auto o = vs11("mov a0.x, r0.x\nmov oT0, c[a0.x + 20]\nmov a0.x, r0.y\n"
                "mov oT1, c[a0.x + 20]\nmov a0.x, r0.z\nmov oT2, c[a0.x + 20]\n",
                c);
  EXPECT_EQ(o.tex[0][0], 1.0f);
  EXPECT_EQ(o.tex[1][0], -1.0f);
  EXPECT_EQ(o.tex[2][0], 2.0f);
}

TEST(Numerics, FrcOfTinyNegativeIsOne) {
  // frc(-1e-10) = -1e-10 − (−1) = 1 − 1e-10, which rounds to 1.0 in fp32.
  // frc(-0.25) = 0.75; frc(1.75) = 0.75.
  auto o = vs20("frc r4, r0\nmov oT0, r4\n", bank({{-1e-10f, -0.25f, 1.75f, 0}}));
  EXPECT_VEC4(o.tex[0], 1.0f, 0.75f, 0.75f, 0.0f);
}

TEST(Numerics, SaturateOfNanIsZero) {
  // _sat of (NaN, 2, -1, 0.5) → (0, 1, 0, 0.5).
  Vec4 r = ps20("mov_sat r4, r0\n", bank({{nan_f(), 2, -1, 0.5f}}));
  EXPECT_VEC4(r, 0, 1, 0, 0.5f);
}

TEST(Numerics, Ps1xConstantsClampToUnit) {
  // def c0 = (2, -3, 0.5, 1.5) reads as (1, -1, 0.5, 1); with max value 8 the sum
  // c0 + c0 = (2, -2, 1, 2) shows that the clamp happened at the read.
  tierlift::ir::Conventions conv;
  conv.ps1x_max_value = 8;
  auto vm = make_vm("ps_1_1\ndef c0, 2, -3, 0.5, 1.5\nadd r0, c0, c0\n", conv);
  EXPECT_VEC4(run_ps(vm).color[0], 2, -2, 1, 2);
  // API constants clamp too: c1 = (5, -5, 0, 0.25) → r0 = (1, -1, 0, 0.25).
  auto vm2 = make_vm("ps_1_1\nmov r0, c1\n");
  EXPECT_VEC4(run_ps(vm2, {}, nullptr, bank({{0, 0, 0, 0}, {5, -5, 0, 0.25f}})).color[0], 1, -1, 0,
              0.25f);
}

TEST(Numerics, Ps1xResultsClampToMaxValue) {
  // max 1: r1 = c0 + c0 = 2 → 1 at the store; r0 = r1 - c1 = 1 - 0.5 = 0.5 (not 1.5).
  auto vm = make_vm("ps_1_1\ndef c0, 1, 1, 1, 1\ndef c1, 0.5, 0.5, 0.5, 0.5\n"
                    "add r1, c0, c0\nsub r0, r1, c1\n");
  EXPECT_VEC4(run_ps(vm).color[0], 0.5f, 0.5f, 0.5f, 0.5f);
  // max 8: add_x4 of 1 + 1 = 8; then r1 + r1 = 16 → 8; negative → -8.
  tierlift::ir::Conventions conv;
  conv.ps1x_max_value = 8;
  auto vm8 = make_vm("ps_1_4\ndef c0, 1, -1, 0.5, 0\nadd_x4 r1, c0, c0\nadd r0, r1, r1\n", conv);
  EXPECT_VEC4(run_ps(vm8).color[0], 8, -8, 8, 0);
}

TEST(Numerics, Ps1xColorInputsAreSaturated) {
  // v0 = (1.5, -0.5, 0.25, 2) arrives as (1, 0, 0.25, 1).
  auto vm = make_vm("ps_1_1\nmov r0, v0\n");
  PixelInput in;
  in.color[0] = {1.5f, -0.5f, 0.25f, 2.0f};
  EXPECT_VEC4(run_ps(vm, in).color[0], 1, 0, 0.25f, 1);
}

TEST(Numerics, Ps1xFixedPointQuantises) {
  // 8 bits: 0.1·256 = 25.6 → floor(26.1) = 26 → 26/256 = 0.1015625
  //         1/512 ·256 = 0.5 → floor(1.0) = 1 → 1/256 (ties round up)
  //        -1/512 ·256 = -0.5 → floor(0.0) = 0 → 0
  //         1 → 256/256 = 1 (the limit for max 1)
  tierlift::ir::Conventions conv;
  conv.ps1x_fixed_bits = 8;
  auto vm = make_vm("ps_1_1\ndef c0, 0.1, 0.001953125, -0.001953125, 1\nmov r0, c0\n", conv);
  EXPECT_VEC4(run_ps(vm).color[0], 0.1015625f, 0.00390625f, 0.0f, 1.0f);
  // 9 bits: 0.1·512 = 51.2 → floor(51.7) = 51 → 51/512 = 0.099609375
  conv.ps1x_fixed_bits = 9;
  auto vm9 = make_vm("ps_1_1\ndef c0, 0.1, 0.1, 0.1, 0.1\nmov r0, c0\n", conv);
  EXPECT_FLOAT_EQ(run_ps(vm9).color[0][0], 0.099609375f);
}

TEST(Numerics, PhaseAlphaReadsZero) {
  // r1 = (0.25, 0.5, 0.75, 1) in phase 1; after `phase` its alpha reads as 0. A valid
  // listing cannot read it (the validator reports read-before-write), so the listing is
  // parsed valid (`mov r0.rgb, r1`) and its mask widened to .rgba by hand afterwards.
  auto prog = parse("ps_1_4\ndef c0, 0.25, 0.5, 0.75, 1\nmov r1, c0\nphase\nmov r0.rgb, r1\n");
  ASSERT_EQ(prog.code.size(), 3u);
  prog.code[2].dst->mask = 0xF;
  ShaderVM vm = vm_of(prog, {});
  EXPECT_VEC4(run_ps(vm).color[0], 0.25f, 0.5f, 0.75f, 0.0f);
}

TEST(Numerics, RelativeOutOfRangeIsZero) {
  // a0.x = 300 (≥ 256 constants) and a0.x = -1 both read (0,0,0,0), even though the bank
  // holds non-zero values there.
  ConstantBank c = bank({{300, -1, 0, 0}});
  c.f.resize(400, Vec4{7, 7, 7, 7});
  c.f[0] = {300, -1, 0, 0};
  auto o = vs11("mov a0.x, r0.x\nmov oT0, c[a0.x + 0]\nmov a0.x, r0.y\nmov oT1, c[a0.x]\n", c);
  EXPECT_VEC4(o.tex[0], 0, 0, 0, 0);
  EXPECT_VEC4(o.tex[1], 0, 0, 0, 0);
}

TEST(Numerics, DepthRatioWithZeroDivisor) {
  // texdepth: r5.g == 0 → depth 1.0; else r5.r / r5.g = 0.5 / 0.25 = 2 (device clamps).
  auto vm = make_vm("ps_1_4\ndef c0, 0.5, 0, 0, 0\ntexcrd r5.rgb, t0\nphase\ntexdepth r5\n"
                    "mov r0, c0\n");
  PixelInput in;
  in.tex[0] = {0.5f, 0.0f, 0, 0};
  auto out = run_ps(vm, in);
  ASSERT_TRUE(out.depth.has_value());
  EXPECT_EQ(*out.depth, 1.0f);
  tierlift::ir::Conventions conv;
  conv.ps1x_max_value = 8;
  in.tex[0] = {0.5f, 0.25f, 0, 0};
  auto vm8 = make_vm("ps_1_4\ndef c0, 0.5, 0, 0, 0\ntexcrd r5.rgb, t0\nphase\ntexdepth r5\n"
                     "mov r0, c0\n",
                     conv);
  EXPECT_EQ(*run_ps(vm8, in).depth, 2.0f);
}

TEST(Numerics, ReflectWithZeroNormal) {
  // t0 = texcoord of TC0 = 0 → N = (TC1·0, TC2·0, TC3·0) = 0 → R = -E = (-0.5, 0.25, -1).
  auto vm = make_vm("ps_1_1\ndef c0, 0.5, -0.25, 1, 0\ntexcoord t0\ntexm3x3pad t1, t0\n"
                    "texm3x3pad t2, t0\ntexm3x3spec t3, t0, c0\nmov r0, t3\n");
  EchoTextures tex;
  PixelInput in;
  in.tex[1] = {1, 0, 0, 0};
  in.tex[2] = {0, 1, 0, 0};
  in.tex[3] = {0, 0, 1, 0};
  EXPECT_VEC4(run_ps(vm, in, &tex).color[0], -0.5f, 0.25f, -1.0f, 0.0f);
}

TEST(Numerics, ProjectDivideByZeroGivesOne) {
  // texld r0, t0_dw.xyw: TC0 = (0.5, 0.25, 0, 0): w = 0 → x = y = 1 → coord (1, 1, w=0).
  // TC0 = (1, 0.5, 0, 2) → (0.5, 0.25, 2).
  tierlift::ir::Conventions conv;
  conv.ps1x_max_value = 8;
  auto vm = make_vm("ps_1_4\ntexld r0, t0_dw.xyw\n", conv);
  EchoTextures tex;
  PixelInput in;
  in.tex[0] = {0.5f, 0.25f, 0, 0};
  EXPECT_VEC4(run_ps(vm, in, &tex).color[0], 1, 1, 0, 0);
  in.tex[0] = {1, 0.5f, 0, 2};
  EXPECT_VEC4(run_ps(vm, in, &tex).color[0], 0.5f, 0.25f, 2, 0);
}

TEST(Numerics, TexbemlLuminanceNotClamped) {
  // t0 = echo(TC0) = (0.125, 0.25, 0.75, 0). Stage 1: identity matrix, lscale 2, loffset 0.5.
  // u = 0.25 + 1·0.125 + 0·0.25 = 0.375; v = 0.5 + 0·0.125 + 1·0.25 = 0.75
  // L = 0.75·2 + 0.5 = 2 (not clamped to 1) → t1 = (0.75, 1.5, 0, 0)
  tierlift::ir::Conventions conv;
  conv.ps1x_max_value = 8;
  auto vm = make_vm("ps_1_1\ntex t0\ntexbeml t1, t0\nmov r0, t1\n", conv);
  EchoTextures tex;
  tex.stages[1].bumpenv_mat = {1, 0, 0, 1};
  tex.stages[1].bumpenv_lscale = 2;
  tex.stages[1].bumpenv_loffset = 0.5f;
  PixelInput in;
  in.tex[0] = {0.125f, 0.25f, 0.75f, 0};
  in.tex[1] = {0.25f, 0.5f, 0, 0};
  EXPECT_VEC4(run_ps(vm, in, &tex).color[0], 0.75f, 1.5f, 0, 0);
}
