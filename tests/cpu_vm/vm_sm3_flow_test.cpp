// Shader models 2.x and 3.0 on the interpreter: dynamic flow control (if_comp, if p0,
// break, break_comp, breakp, callnz p0), loops with aL in ps_3_0, setp and predicated
// writes, sincos's one-source form, vPos/vFace, and registers linked by semantic. Every
// expected value is worked out by hand in the comment beside it. The same listings run on
// lavapipe in tests/vulkan/diff_sm3_test.cpp.
#include "tierlift/ir/flow_rules.h"
#include "vm_test_util.h"

using namespace vmtest;

namespace {

// ps_3_0 with c0..c3 copied to r0..r3; `body` leaves its result in r4 (→ oC0).
Vec4 ps30(const std::string& body, const ConstantBank& c, const std::string& head = "") {
  std::string text = "ps_3_0\n" + head + "mov r0, c0\nmov r1, c1\nmov r2, c2\nmov r3, c3\n" + body +
                     "mov oC0, r4\n";
  ShaderVM vm = vm_of(parse(text), {});
  static const ConstTextures none;
  return vm.run_pixel(PixelInput{}, c, none).color[0];
}

} // namespace

TEST(VmSm3Flow, LoopSumsConstantsThroughAl) {
  // i0 = (4, 1, 2): aL = 1, 3, 5, 7 → r4 = c1 + c3 + c5 + c7 = 1 + 10 + 100 + 1000 = 1111.
  const ConstantBank c = splats(10, {{1, 1}, {3, 10}, {5, 100}, {7, 1000}, {9, 10000}});
  const Vec4 r =
      ps30("mov r4, c0\nloop aL, i0\nadd r4, r4, c[aL]\nendloop\n", c, "defi i0, 4, 1, 2, 0\n");
  EXPECT_VEC4(r, 1111, 1111, 1111, 1111);
}

TEST(VmSm3Flow, NestedLoopsReadTheInnerAl) {
  // Outer i0 = (2, 0, 1): aL = 0, 1. Inner i1 = (3, 4, 1): aL = 4, 5, 6, restored to the
  // outer aL after each inner loop. Each outer pass adds c[aL] (c0 = 0, c1 = 1000) and
  // the inner c[aL] = c4 + c5 + c6 = 1 + 10 + 100: 2 · 111 + 0 + 1000 = 1222.
  const ConstantBank c = splats(8, {{1, 1000}, {4, 1}, {5, 10}, {6, 100}});
  const Vec4 r = ps30("mov r4, c0\nloop aL, i0\nloop aL, i1\nadd r4, r4, c[aL]\nendloop\n"
                      "add r4, r4, c[aL]\nendloop\n",
                      c, "defi i0, 2, 0, 1, 0\ndefi i1, 3, 4, 1, 0\n");
  EXPECT_VEC4(r, 1222, 1222, 1222, 1222);
}

TEST(VmSm3Flow, BreakCompLeavesTheLoop) {
  // rep 10: r4 += 1 while r4 < 3.5: r4 = 1, 2, 3, 4, then break_ge 4 ≥ 3.5 → r4 = 4.
  ConstantBank c = bank({{0, 0, 0, 0}, {1, 1, 1, 1}, {3.5f, 3.5f, 3.5f, 3.5f}});
  c.i[0] = {10, 0, 0, 0};
  const Vec4 r = ps30("mov r4, c0\nrep i0\nadd r4, r4, r1\nbreak_ge r4.x, r2.x\nendrep\n", c);
  EXPECT_VEC4(r, 4, 4, 4, 4);
}

TEST(VmSm3Flow, BreakInsideIfAndBreakp) {
  // loop aL = 0..9 adds c[aL] until c[aL].x == 0 (c7 = 0): c0..c2 = 5 sum to 15, aL = 3
  // breaks. A second loop (aL = 0 again) adds c0 = 5 and is left by breakp after its first
  // iteration (p0.x: 0 < 5): r4 = 20.
  const ConstantBank c = splats(8, {{0, 5}, {1, 5}, {2, 5}, {3, 0}, {4, 7}});
  const Vec4 r = ps30("mov r4, c7\nmov r6, c7\nloop aL, i0\nmov r5, c[aL]\n"
                      "if_eq r5.x, r6.x\nbreak\nendif\nadd r4, r4, r5\nendloop\n"
                      "setp_lt p0.x, r6.x, r0.x\nloop aL, i0\nadd r4, r4, c[aL]\nbreakp p0.x\n"
                      "endloop\n",
                      c, "defi i0, 10, 0, 1, 0\n");
  EXPECT_VEC4(r, 20, 20, 20, 20);
}

TEST(VmSm3Flow, DynamicIfElse) {
  // if_gt c0.x (2) > c1.x (1): r4 = c2 (7) else r4 = c3 (9); if_lt the same → the else.
  const ConstantBank c = bank({{2, 2, 2, 2}, {1, 1, 1, 1}, {7, 7, 7, 7}, {9, 9, 9, 9}});
  EXPECT_VEC4(ps30("if_gt r0.x, r1.x\nmov r4, r2\nelse\nmov r4, r3\nendif\n", c), 7, 7, 7, 7);
  EXPECT_VEC4(ps30("if_lt r0.x, r1.x\nmov r4, r2\nelse\nmov r4, r3\nendif\n", c), 9, 9, 9, 9);
}

TEST(VmSm3Flow, PredicatedWritesPerComponent) {
  // setp_gt p0, c0 = (1, -1, 2, -2), c7 = 0 → p0 = (T, F, T, F).
  // (p0) mov r4, c2 (all 5) over r4 = 0: (5, 0, 5, 0); (!p0.y) add r4, r4, c1 (1) with
  // p0.y = F replicated: every component written: (6, 1, 6, 1).
  const ConstantBank c = bank({{1, -1, 2, -2}, {1, 1, 1, 1}, {5, 5, 5, 5}, {0, 0, 0, 0}});
  EXPECT_VEC4(ps30("mov r4, r3\nsetp_gt p0, r0, r3\n(p0) mov r4, r2\n", c), 5, 0, 5, 0);
  EXPECT_VEC4(ps30("mov r4, r3\nsetp_gt p0, r0, r3\n(p0) mov r4, r2\n(!p0.y) add r4, r4, r1\n", c),
              6, 1, 6, 1);
}

TEST(VmSm3Flow, ComparisonsWithNan) {
  // NaN makes gt/ge/lt/le/eq false and ne true (ir/flow_rules.h).
  const float n = nan_f();
  const ConstantBank c = bank({{n, n, n, n}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}});
  const char* ops[] = {"gt", "eq", "ge", "lt", "ne", "le"};
  for (int k = 0; k < 6; ++k) {
    const std::string body =
        std::string("mov r4, r2\nsetp_") + ops[k] + " p0, r0, r1\n(p0) mov r4, r1\n";
    const float want = k == 4 ? 1.0f : 0.0f;
    SCOPED_TRACE(ops[k]);
    EXPECT_VEC4(ps30(body, c), want, want, want, want);
  }
}

TEST(VmSm3Flow, CallnzOnThePredicate) {
  // p0 = (T, F, ., .): callnz l0, p0.x runs (r4 += 1), callnz l0, !p0.x does not,
  // callnz l0, !p0.y runs: r4 = 2.
  const ConstantBank c = bank({{1, -1, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}});
  ShaderVM vm = vm_of(parse("ps_3_0\nmov r0, c0\nmov r1, c1\nmov r4, c2\nsetp_gt p0.xy, r0, r4\n"
                            "callnz l0, p0.x\n"
                            "callnz l0, !p0.x\ncallnz l0, !p0.y\nmov oC0, r4\nret\n"
                            "label l0\nadd r4, r4, r1\nret\n"),
                      {});
  EXPECT_VEC4(run_ps(vm, {}, nullptr, c).color[0], 2, 2, 2, 2);
}

TEST(VmSm3Flow, SincosOneSource) {
  // sincos r4.xy, c0.x (0): (cos 0, sin 0) = (1, 0); z, w keep r4's (3, 4).
  const ConstantBank c = bank({{0, 0, 0, 0}, {1, 2, 3, 4}, {0, 0, 0, 0}, {0, 0, 0, 0}});
  EXPECT_VEC4(ps30("mov r4, r1\nsincos r4.xy, r0.x\n", c), 1, 0, 3, 4);
}

TEST(VmSm3Flow, IterationBudgetEndsEveryLoop) {
  // Three nested rep 255 (invalid: past the nesting limit, so unvalidated) would run 16.6
  // million iterations. The budget (ir/flow_rules.h: 2 units to reach a loop, 1 per
  // completed iteration, at most 65000) ends them: reaching the outer and the middle loop
  // spends 4; each middle iteration spends 2 + 255 (its inner loop) + 1 = 258, so after 251
  // of them 4 + 251 · 258 = 64762. The 252nd reaches its inner loop at 64764 and runs
  // iterations while the units stay ≤ 65000: 1 + 236 of them. Adds: 251 · 255 + 237 =
  // 64242; then every loop leaves at its test and the code after the loops runs.
  static_assert(tierlift::ir::flow::kIterationBudget == 65000);
  static_assert(tierlift::ir::flow::kEntryCost == 2);
  ConstantBank c = bank({{0, 0, 0, 0}, {1, 1, 1, 1}});
  c.i[0] = {255, 0, 0, 0};
  ShaderVM vm =
      vm_of(parse("ps_3_0\nmov r4, c0\nrep i0\nrep i0\nrep i0\nadd r4, r4, c1\nendrep\nendrep\n"
                  "endrep\nmov oC0, r4\n",
                  false),
            {});
  EXPECT_EQ(run_ps(vm, {}, nullptr, c).color[0][0], 64242.0f);
}

TEST(VmSm3Flow, VposAndVface) {
  // vPos reads the pixel's integer coordinates (z = w = 0), vFace the face's sign.
  ShaderVM vm = vm_of(parse("ps_3_0\ndcl vPos.xy\ndcl vFace\nmov r0, c0\nmov r0.xy, vPos\n"
                            "mov r0.z, vFace\nmov oC0, r0\n"),
                      {});
  PixelInput in;
  in.pos_x = 5;
  in.pos_y = 7;
  in.face = -1;
  EXPECT_VEC4(run_ps(vm, in).color[0], 5, 7, -1, 0);
}

TEST(VmSm3Flow, InputsLinkBySemantic) {
  // dcl_texcoord2 v0 reads TC2, dcl_color1 v1 reads the second colour as it comes: a ps_3_0
  // colour input is a float register, not saturated (NUMERICS.md F6): (1 + 0.5, 2 + 2,
  // 3 + 0.25, 4 − 1).
  ShaderVM vm =
      vm_of(parse("ps_3_0\ndcl_texcoord2 v0\ndcl_color1 v1\nmov r0, v0\nadd oC0, r0, v1\n"), {});
  PixelInput in;
  in.tex[2] = {1, 2, 3, 4};
  in.color[1] = {0.5f, 2, 0.25f, -1};
  EXPECT_VEC4(run_ps(vm, in).color[0], 1.5f, 4, 3.25f, 3);
}

TEST(VmSm3Flow, ColourInputsAreSaturatedBeforePs30Only) {
  // The same colour (−0.5, 2, 0.25, 1) read as v0: a ps_2_0 reads it saturated (rule 26),
  // a ps_3_0 as it is (F6).
  PixelInput in;
  in.color[0] = {-0.5f, 2, 0.25f, 1};
  ShaderVM ps20 = vm_of(parse("ps_2_0\ndcl v0\nmov oC0, v0\n"), {});
  ShaderVM ps30 = vm_of(parse("ps_3_0\ndcl_color0 v0\nmov oC0, v0\n"), {});
  EXPECT_VEC4(run_ps(ps20, in).color[0], 0, 1, 0.25f, 1);
  EXPECT_VEC4(run_ps(ps30, in).color[0], -0.5f, 2, 0.25f, 1);
}

TEST(VmSm3Flow, OutputsLinkBySemantic) {
  // vs_3_0: dcl_position o3 is oPos, dcl_texcoord5 o0 is oT5, dcl_color0 o1 is oD0.
  ShaderVM vm = vm_of(parse("vs_3_0\ndcl_position v0\ndcl_position o3\ndcl_texcoord5 o0\n"
                            "dcl_color0 o1\nmov o3, v0\nmov o0, c0\nmov o1, c1\n"),
                      {});
  VertexInput in;
  in.v[0] = {1, 2, 3, 1};
  const VertexOutput o = run_vs(vm, in, bank({{4, 5, 6, 7}, {0.5f, 0.5f, 0.5f, 1}}));
  EXPECT_VEC4(o.pos, 1, 2, 3, 1);
  EXPECT_VEC4(o.tex[5], 4, 5, 6, 7);
  EXPECT_VEC4(o.color[0], 0.5f, 0.5f, 0.5f, 1);
  EXPECT_EQ(o.tex_written, 1u << 5);
}

TEST(VmSm3Flow, PredicatedTexkillTestsTheComponentsWhosePredicateHolds) {
  // r0 = (−1, 2, −3, 4); p0 = c1 > 0 per component. (p0) texkill r0 tests component i only
  // where p0.i holds (NUMERICS.md F3): it kills when p0.x or p0.z holds, not for p0 = (f, t,
  // f, t); (!p0.y) texkill r0 tests all four when p0.y fails, none when it holds.
  const std::string kill = "ps_3_0\nmov r0, c0\nsetp_gt p0, c1, c2\n(p0) texkill r0\nmov oC0, r0\n";
  const std::string not_y = "ps_3_0\nmov r0, c0\nsetp_gt p0, c1, c2\n(!p0.y) texkill r0\n"
                            "mov oC0, r0\n";
  const Vec4 r0{-1, 2, -3, 4}, zero{0, 0, 0, 0};
  struct Case {
    const std::string* text;
    Vec4 p; // c1: > 0 sets p0's component
    bool discarded;
  };
  const Case cases[] = {{&kill, {1, 0, 0, 0}, true},  {&kill, {0, 0, 1, 0}, true},
                        {&kill, {0, 1, 0, 1}, false}, {&kill, {0, 0, 0, 0}, false},
                        {&not_y, {0, 0, 0, 0}, true}, {&not_y, {1, 1, 1, 1}, false}};
  for (const Case& c : cases) {
    ShaderVM vm = vm_of(parse(*c.text), {});
    EXPECT_EQ(run_ps(vm, {}, nullptr, bank({r0, c.p, zero})).discarded, c.discarded)
        << *c.text << " p " << c.p[0] << c.p[1] << c.p[2] << c.p[3];
  }
}

// NUMERICS.md F13: v[aL + n] indexes the declared inputs by v# number, whatever registers
// their semantics link to. v0 = texcoord0 (t0), v1 = color0 (v0, not saturated in ps_3_0),
// v2 = texcoord3 (t3): aL = 0, 1, 2 sums (1 + 10 + 100, 2 + 20 + 200, 3 − 30 + 300,
// 4 + 40 + 400).
TEST(VmSm3Flow, RelativeInputReadIndexesTheDeclaredInputsByNumber) {
  ShaderVM vm = vm_of(parse("ps_3_0\ndefi i0, 3, 0, 1, 0\ndef c0, 0, 0, 0, 0\n"
                            "dcl_texcoord0 v0\ndcl_color0 v1\ndcl_texcoord3 v2\nmov r0, c0\n"
                            "loop aL, i0\nadd r0, r0, v0[aL]\nendloop\nmov oC0, r0\n"),
                      {});
  PixelInput in;
  in.tex[0] = {1, 2, 3, 4};
  in.color[0] = {10, 20, -30, 40};
  in.tex[3] = {100, 200, 300, 400};
  in.tex[1] = {1000, 1000, 1000, 1000}; // linked to no v#: never read
  EXPECT_VEC4(run_ps(vm, in).color[0], 111, 222, 273, 444);
}

// NUMERICS.md F13: an index on an undeclared v# or outside v0..v9 reads (0, 0, 0, 0). The
// first loop (aL = 0, 3, 6, 9) reads v0 (texcoord0), v3 and v6 (undeclared), v9 (texcoord1);
// the second (aL = 0, 1) v9 and v10, beyond ps_3_0's ten: t0 + 2·t1.
TEST(VmSm3Flow, RelativeInputReadOutsideTheDeclaredOnesIsZero) {
  ShaderVM vm = vm_of(parse("ps_3_0\ndefi i0, 4, 0, 3, 0\ndefi i1, 2, 0, 1, 0\n"
                            "def c0, 0, 0, 0, 0\ndcl_texcoord0 v0\ndcl_texcoord1 v9\n"
                            "mov r0, c0\nloop aL, i0\nadd r0, r0, v0[aL]\nendloop\n"
                            "loop aL, i1\nadd r0, r0, v9[aL]\nendloop\nmov oC0, r0\n"),
                      {});
  PixelInput in;
  for (int t = 0; t < 8; ++t) in.tex[static_cast<size_t>(t)] = {1000, 1000, 1000, 1000};
  in.tex[0] = {1, 2, 3, 4};
  in.tex[1] = {10, 20, 30, 40};
  EXPECT_VEC4(run_ps(vm, in).color[0], 21, 42, 63, 84);
}

// A vs_3_0 reads its inputs relatively too (v[aL + n] with aL only): aL = 1, 2 adds v1 + v2
// into the texcoord0 output o1.
TEST(VmSm3Flow, Vs30RelativeInputRead) {
  ShaderVM vm = vm_of(parse("vs_3_0\ndefi i0, 2, 1, 1, 0\ndef c0, 0, 0, 0, 0\n"
                            "dcl_position v0\ndcl_texcoord0 v1\ndcl_texcoord1 v2\n"
                            "dcl_position o0\ndcl_texcoord0 o1\nmov o0, v0\nmov r0, c0\n"
                            "loop aL, i0\nadd r0, r0, v[aL]\nendloop\nmov o1, r0\n"),
                      {});
  VertexInput in;
  in.v[0] = {0, 0, 0, 1};
  in.v[1] = {1, 2, 3, 4};
  in.v[2] = {0.5f, 0.25f, 0.125f, 8};
  EXPECT_VEC4(run_vs(vm, in).tex[0], 1.5f, 2.25f, 3.125f, 12);
}

// A vs_3_0 writes its outputs relatively (o[aL + n]): o3, o4, o5 are declared texcoord2,
// texcoord0, color0, so aL = 3, 4, 5 writes oT2, oT0, oD0 (not three consecutive
// registers). r0 = c0, then c0 + c1, then c0 + 2·c1: (1, 2, 3, 4), (11, 22, 33, 44),
// (21, 42, 63, 84).
TEST(VmSm3Flow, Vs30RelativeOutputWrite) {
  ShaderVM vm = vm_of(parse("vs_3_0\ndefi i0, 3, 3, 1, 0\ndef c0, 1, 2, 3, 4\n"
                            "def c1, 10, 20, 30, 40\ndcl_position v0\n"
                            "dcl_position o0\ndcl_texcoord2 o3\ndcl_texcoord0 o4\n"
                            "dcl_color0 o5\nmov o0, v0\nmov r0, c0\n"
                            "loop aL, i0\nmov o[aL], r0\nadd r0, r0, c1\nendloop\n"),
                      {});
  const VertexOutput out = run_vs(vm);
  EXPECT_VEC4(out.tex[2], 1, 2, 3, 4);
  EXPECT_VEC4(out.tex[0], 11, 22, 33, 44);
  EXPECT_VEC4(out.color[0], 21, 42, 63, 84);
  EXPECT_EQ(out.tex_written, 0b101);
  EXPECT_EQ(out.color_written, 0b01);
}

// An index on an undeclared o# (aL = 6, 7) or outside o0-o11 (a0.x = 12, -1) writes
// nothing (NUMERICS.md F13); the mask and _sat apply to a write that lands: o[aL + 1].yw_sat
// at aL = 4 writes .y = sat(3) = 1 and .w = 0.5 of o5 (color0) over its (9, 9, 9, 9).
TEST(VmSm3Flow, Vs30RelativeOutputOutsideTheTableWritesNothing) {
  ShaderVM vm = vm_of(parse("vs_3_0\ndefi i0, 2, 6, 1, 0\ndefi i1, 1, 4, 1, 0\n"
                            "def c0, 7, 7, 7, 7\ndef c1, 12, -1, 0, 0\ndef c2, 9, 9, 9, 9\n"
                            "def c3, -2, 3, 5, 0.5\ndcl_position v0\n"
                            "dcl_position o0\ndcl_texcoord2 o3\ndcl_color0 o5\nmov o0, v0\n"
                            "mov o3, c2\nmov o5, c2\nloop aL, i0\nmov o[aL], c0\nendloop\n"
                            "mova a0.x, c1.x\nmov o[a0.x], c0\nmova a0.x, c1.y\n"
                            "mov o[a0.x], c0\nloop aL, i1\nmov_sat o[aL + 1].yw, c3\nendloop\n"),
                      {});
  const VertexOutput out = run_vs(vm);
  EXPECT_VEC4(out.tex[2], 9, 9, 9, 9);
  EXPECT_VEC4(out.color[0], 9, 1, 9, 0.5f);
  EXPECT_EQ(out.tex_written, 0b100);
  EXPECT_EQ(out.color_written, 0b01);
}
