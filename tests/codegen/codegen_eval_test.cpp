// Executes emitted SPIR-V with the test evaluator (spirv_eval.h: exact fp32, no GPU) and
// checks the results against the named rules of ir/numerics.h and hand-computed values.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "compile_valid.h"
#include "spirv_eval.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/ir/numerics.h"
#include "tierlift/vulkan/uniforms.h"

using namespace tierlift;
namespace num = ir::numerics;
using Vec4 = std::array<float, 4>;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

struct EvalResult {
  std::map<uint32_t, Vec4> out;
  Vec4 pos{};
  bool killed = false;
};

// The values of the stage's uniform block: its constant bank and the texture stages' bump
// states, as the Vulkan device packs them.
struct Uniforms {
  pass::ConstantBank bank;
  pass::Pass stages;
};

// The ps_1_x range of the geforce3 preset (1), whose clamps the hand-computed values below
// show (the default conventions have the d3d9 preset's FLT_MAX).
codegen::CodegenOptions geforce3() {
  codegen::CodegenOptions o;
  o.conventions.ps1x_max_value = 1.0f;
  return o;
}

EvalResult run(const std::string& text, const Uniforms& u,
               const std::map<uint32_t, Vec4>& inputs = {},
               const codegen::CodegenOptions& opt = geforce3()) {
  auto parsed = assembly::parse_text(text, "<eval>");
  EXPECT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  if (!parsed.program) return {};
  ir::DiagnosticSink diags;
  auto m = codegen::compile(*parsed.program, opt, diags);
  EXPECT_TRUE(m) << ir::render_text(diags, parsed.sources);
  if (!m) return {};
  spirv_test::SpirvEval e(m->words);
  e.inputs = inputs;
  e.uniform_words = vulkan::pack_uniforms(*m, u.bank, u.stages);
  e.run();
  return {e.outputs, e.position, e.killed};
}

uint32_t bits(float f) {
  return std::bit_cast<uint32_t>(f);
}

// Bit-exact comparison (NaN payloads aside: any NaN matches any NaN).
void expect_same(const Vec4& got, const Vec4& want, const std::string& what) {
  for (int k = 0; k < 4; ++k) {
    if (std::isnan(want[k])) {
      EXPECT_TRUE(std::isnan(got[k])) << what << " [" << k << "]";
      continue;
    }
    EXPECT_EQ(bits(got[k]), bits(want[k]))
        << what << " [" << k << "]: got " << got[k] << ", want " << want[k];
  }
}

Uniforms consts(std::vector<Vec4> f) {
  Uniforms u;
  u.bank.f = std::move(f);
  return u;
}

} // namespace

TEST(CodegenEval, Listing1OffsetsTheTexcoordAndFlipsY) {
  const std::string vs = "vs_1_1\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                         "add oT0, v3, c0\nadd oT7, v3, c7\n";
  auto u = consts({{0.5f, 0, 0, 0}, {}, {}, {}, {}, {}, {}, {-0.25f, 0.125f, 0, 0}});
  codegen::CodegenOptions opt;
  opt.pixel_offset_x = 0.25f;
  opt.pixel_offset_y = 0.5f;
  EvalResult r = run(vs, u, {{0, {0.5f, 0.5f, 0, 2}}, {3, {0.25f, 0.75f, 0, 1}}}, opt);
  expect_same(r.out[0], {0.75f, 0.75f, 0, 1}, "oT0");
  expect_same(r.out[7], {0.0f, 0.875f, 0, 1}, "oT7");
  // x + 0.25·w, −y + 0.5·w (w = 2)
  expect_same(r.pos, {1.0f, 0.5f, 0, 2}, "Position");
}

TEST(CodegenEval, SpecialValuesFollowTheNamedRules) {
  const std::string vs = "vs_2_0\ndcl_position v0\nrcp r0.x, c0.x\nrsq r0.y, c0.y\n"
                         "log r0.z, c0.z\nexp r0.w, c0.w\nmov oT0, r0\n"
                         "rcp r1.x, c1.x\nrsq r1.y, c1.y\nlog r1.z, c1.z\npow r1.w, c1.w, c2.x\n"
                         "mov oT1, r1\nmov oPos, v0\n";
  auto u = consts({{0.0f, -4.0f, -0.0f, 200.0f}, {1.0f, 0.0f, -8.0f, 0.0f}, {0.0f, 0, 0, 0}});
  EvalResult r = run(vs, u);
  expect_same(r.out[0], {FLT_MAX, 0.5f, -FLT_MAX, FLT_MAX}, "rcp/rsq/log/exp");
  expect_same(r.out[1], {1.0f, FLT_MAX, 3.0f, 1.0f}, "rcp(1)/rsq(0)/log(-8)/pow(0,0)");
}

TEST(CodegenEval, ZeroTimesAnythingIsPositiveZero) {
  auto u = consts({{0.0f, 0.0f, 2.0f, -0.0f}, {kInf, kNaN, 3.0f, 5.0f}, {1, 1, 1, 1}});
  EvalResult r =
      run("vs_1_1\ndcl_position v0\nmul oT0, c0, c1\nmad oT1, c1, c0, c2\nmov oPos, v0\n", u);
  expect_same(r.out[0], {0.0f, 0.0f, 6.0f, 0.0f}, "mul");
  expect_same(r.out[1], {1.0f, 1.0f, 7.0f, 1.0f}, "mad");
}

TEST(CodegenEval, ComparisonsWithNanTakeTheFalseBranch) {
  auto u = consts({{kNaN, 1.0f, kNaN, 2.0f}, {1.0f, kNaN, kNaN, 1.0f}});
  EvalResult r = run("vs_1_1\ndcl_position v0\nmin oT0, c0, c1\nmax oT1, c0, c1\nsge oT2, c0, c1\n"
                     "slt oT3, c0, c1\nmov oPos, v0\n",
                     u);
  Vec4 mn, mx, ge, lt;
  for (int k = 0; k < 4; ++k) {
    mn[k] = num::legacy_min(u.bank.f[0][k], u.bank.f[1][k]);
    mx[k] = num::legacy_max(u.bank.f[0][k], u.bank.f[1][k]);
    ge[k] = num::legacy_sge(u.bank.f[0][k], u.bank.f[1][k]);
    lt[k] = num::legacy_slt(u.bank.f[0][k], u.bank.f[1][k]);
  }
  expect_same(r.out[0], mn, "min");
  expect_same(r.out[1], mx, "max");
  expect_same(r.out[2], ge, "sge");
  expect_same(r.out[3], lt, "slt");
  EXPECT_EQ(r.out[0][0], 1.0f); // min(NaN, 1) = 1 (the doc ternary)
}

TEST(CodegenEval, MacrosAndVectorOpsMatchTheNumericsFunctions) {
  const Vec4 a{0.5f, -2.0f, 3.0f, 0.25f}, b{4.0f, 0.0f, -1.5f, 2.0f}, c{-1.0f, 0.75f, 8.0f, 0.0f};
  auto u = consts({a, b, c, {1, 2, 3, 4}, {5, 6, 7, 8}, {-1, 0, 1, 2}, {0.5f, 0.5f, 0.5f, 0.5f}});
  EvalResult r =
      run("vs_2_0\ndcl_position v0\ndp3 oT0, c0, c1\ndp4 oT1, c0, c1\nlrp oT2, c0, c1, c2\n"
          "frc oT3, c1\nm4x4 oT4, c0, c3\nsgn r0, c0, r1, r2\nmov oT5, r0\n"
          "crs r3.xyz, c0, c1\nmov r3.w, c2.w\nmov oT6, r3\nnrm r4, c0\nmov oT7, r4\n"
          "mov oPos, v0\n",
          u);
  const float d3 = num::legacy_dp3(a.data(), b.data()), d4 = num::legacy_dp4(a.data(), b.data());
  expect_same(r.out[0], {d3, d3, d3, d3}, "dp3");
  expect_same(r.out[1], {d4, d4, d4, d4}, "dp4");
  Vec4 lrp, frc, sgn, nrm;
  const float scale = num::legacy_nrm_scale(num::legacy_dp3(a.data(), a.data()));
  for (int k = 0; k < 4; ++k) {
    lrp[k] = num::legacy_lrp(a[k], b[k], c[k]);
    frc[k] = num::legacy_frc(b[k]);
    sgn[k] = num::legacy_sgn(a[k]);
    nrm[k] = num::legacy_mul(a[k], scale);
  }
  expect_same(r.out[2], lrp, "lrp");
  expect_same(r.out[3], frc, "frc");
  Vec4 m;
  for (int i = 0; i < 4; ++i) m[i] = num::legacy_dp4(a.data(), u.bank.f[3 + i].data());
  expect_same(r.out[4], m, "m4x4");
  expect_same(r.out[5], sgn, "sgn");
  auto mul = num::legacy_mul;
  expect_same(r.out[6],
              {mul(a[1], b[2]) - mul(a[2], b[1]), mul(a[2], b[0]) - mul(a[0], b[2]),
               mul(a[0], b[1]) - mul(a[1], b[0]), 0.0f},
              "crs");
  expect_same(r.out[7], nrm, "nrm");
}

TEST(CodegenEval, LitDstAndExpp) {
  auto u = consts({{0.5f, 0.25f, 0.0f, 2.0f}, {-1.0f, 0.5f, 0.0f, 3.0f}, {2.0f, 4.0f, 8.0f, 0.5f}});
  EvalResult r = run("vs_1_1\ndcl_position v0\nlit oT0, c0\nlit oT1, c1\ndst oT2, c0, c2\n"
                     "expp oT3, c2.w\nmov oPos, v0\n",
                     u);
  const auto l = num::legacy_lit(0.5f, 0.25f, 2.0f);
  expect_same(r.out[0], {l.x, l.y, l.z, l.w}, "lit");
  expect_same(r.out[1], {1.0f, 0.0f, 0.0f, 1.0f}, "lit x<0");
  expect_same(r.out[2], {1.0f, 1.0f, 0.0f, 0.5f}, "dst");
  expect_same(r.out[3], {1.0f, 0.5f, num::legacy_exp(0.5f), 1.0f}, "expp vs_1_1");
}

TEST(CodegenEval, AddressRegisterAndRelativeReads) {
  auto u = consts({{-0.5f, 2.5f, -2.5f, 0}, {10, 10, 10, 10}, {20, 20, 20, 20}, {30, 30, 30, 30}});
  // vs_1_1 mov a0 floors: -0.5 → -1, so c[a0.x + 2] = c1; c[a0.x + 500] is out of range.
  EvalResult r1 = run("vs_1_1\ndcl_position v0\ndef c3, 3, 3, 3, 3\nmov a0.x, c0.x\n"
                      "mov oT0, c[a0.x + 2]\nmov oT1, c[a0.x + 4]\nmov oT2, c[a0.x + 500]\n"
                      "mov oPos, v0\n",
                      u);
  expect_same(r1.out[0], {10, 10, 10, 10}, "c[a0.x + 2]");
  expect_same(r1.out[1], {3, 3, 3, 3}, "def c3 overrides");
  expect_same(r1.out[2], {0, 0, 0, 0}, "out of range");
  // vs_2_0 mova rounds half away from zero: 2.5 → 3 (c3), -2.5 → -3 (c[-3 + 5] = c2).
  EvalResult r2 = run("vs_2_0\ndcl_position v0\nmova a0.xy, c0.yz\nmov oT0, c[a0.x + 0]\n"
                      "mov oT1, c[a0.y + 5]\nmov oPos, v0\n",
                      u);
  expect_same(r2.out[0], {30, 30, 30, 30}, "mova 2.5");
  expect_same(r2.out[1], {20, 20, 20, 20}, "mova -2.5");
}

TEST(CodegenEval, LoopsRepsAndBranches) {
  Uniforms u = consts(
      {{1, 1, 1, 1}, {1, 0, 0, 0}, {0, 0, 0, 0}, {100, 0, 0, 0}, {0, 0, 0, 0}, {10000, 0, 0, 0}});
  u.bank.i[1] = {1000, 0, 0, 0}; // rep count clamps to 255
  u.bank.b[2] = true;
  EvalResult r = run("vs_2_0\ndcl_position v0\ndefi i0, 3, 1, 2, 0\nmov r0, c2\n"
                     "loop aL, i0\nadd r0, r0, c[aL]\nendloop\nmov oT0, r0\n"
                     "mov r1, c2\nrep i1\nadd r1, r1, c0\nendrep\nmov oT1, r1\n"
                     "if b2\nmov r2, c0\nelse\nmov r2, c1\nendif\nmov oT2, r2\n"
                     "mov r3, c2\ncallnz l1, !b2\ncall l1\nmov oT3, r3\nmov oPos, v0\nret\n"
                     "label l1\nadd r3, r3, c0\nret\n",
                     u);
  expect_same(r.out[0], {10101, 0, 0, 0}, "loop sums c1 + c3 + c5");
  expect_same(r.out[1], {255, 255, 255, 255}, "rep clamps to 255");
  expect_same(r.out[2], {1, 1, 1, 1}, "if b2");
  expect_same(r.out[3], {1, 1, 1, 1}, "callnz !b2 skipped, call taken");
}

// A break as the last statement of a rep or loop body (and one inside an if around the
// loop) leaves after the first iteration: the module passes spirv-val (it did not: the
// block after the break was unreachable and branched to the continue target) and adds c0
// once, c[aL] once at aL = i1.y = 1, where three iterations would give 3 and c1 + c3 + c5.
TEST(CodegenEval, BreakRightBeforeTheLoopsEndLeavesAfterOneIteration) {
  Uniforms u = consts(
      {{1, 2, 3, 4}, {10, 0, 0, 0}, {0, 0, 0, 0}, {100, 0, 0, 0}, {0, 0, 0, 0}, {1000, 0, 0, 0}});
  u.bank.b[0] = true;
  const std::string text = "vs_2_x\ndcl_position v0\ndefi i0, 3, 0, 0, 0\ndefi i1, 3, 1, 2, 0\n"
                           "mov r0, c2\nrep i0\nadd r0, r0, c0\nbreak\nendrep\nmov oT0, r0\n"
                           "mov r1, c2\nloop aL, i1\nadd r1, r1, c[aL]\nbreak\nendloop\n"
                           "mov oT1, r1\nmov r2, c2\nif b0\nrep i0\nadd r2, r2, c0\nbreak\n"
                           "endrep\nendif\nmov oT2, r2\nmov oPos, v0\n";
  auto parsed = assembly::parse_text(text, "<eval>");
  ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  test::compile_valid(*parsed.program, parsed.sources, geforce3());
  EvalResult r = run(text, u);
  expect_same(r.out[0], {1, 2, 3, 4}, "rep: c0 once");
  expect_same(r.out[1], {10, 0, 0, 0}, "loop: c1 once (aL = 1)");
  expect_same(r.out[2], {1, 2, 3, 4}, "rep in if: c0 once");
}

TEST(CodegenEval, Ps1xClampsModifiersAndCoissue) {
  auto u = consts({{2.0f, -3.0f, 0.5f, 0.25f}, {0.5f, 0.5f, 0.5f, 0.75f}});
  // c0 clamps to (1, -1, 0.5, 0.25); v0 saturates to (1, 0, 0.5, 1).
  const std::map<uint32_t, Vec4> in{{8, {1.5f, -0.5f, 0.5f, 1.0f}}};
  EvalResult r = run("ps_1_1\nmul_x4 r0, c0, v0\n", u, in);
  expect_same(r.out[0], {1.0f, 0.0f, 1.0f, 1.0f}, "shift then clamp to ±1");
  codegen::CodegenOptions wide;
  wide.conventions.ps1x_max_value = 8.0f;
  r = run("ps_1_1\nmul_x4 r0, c0, v0\n", u, in, wide);
  expect_same(r.out[0], {4.0f, 0.0f, 1.0f, 1.0f}, "max value 8");
  r = run("ps_1_1\nadd r0, c1_bx2, 1-c1\n", u);
  expect_same(r.out[0], {0.5f, 0.5f, 0.5f, 0.75f}, "bx2 and complement");
  // Both halves of a pair read r0 before either writes.
  r = run("ps_1_1\nmov r0, c1\nmul r0.rgb, r0, c1\n+add r0.a, r0, c1\n", u);
  expect_same(r.out[0], {0.25f, 0.25f, 0.25f, 1.0f}, "co-issue");
  codegen::CodegenOptions fixed = geforce3();
  fixed.conventions.ps1x_fixed_bits = 8;
  r = run("ps_1_1\nmov r0, c0\n", consts({{0.3f, -0.3f, 0.999f, 0}}), {}, fixed);
  expect_same(r.out[0], {77.0f / 256, -77.0f / 256, 1.0f, 0.0f}, "fixed point 8 bits");
}

TEST(CodegenEval, PhaseClearsAlphaAndTexkillKills) {
  auto u = consts({{0.5f, 0.5f, 0.5f, 0.5f}});
  EvalResult r = run("ps_1_4\ntexcrd r1.rgb, t0\nmov r1.a, c0\nphase\nmov r0, r1\n", u,
                     {{0, {0.25f, 0.5f, 0.75f, 1.0f}}});
  expect_same(r.out[0], {0.25f, 0.5f, 0.75f, 0.0f}, "phase alpha");
  EvalResult k =
      run("ps_2_0\ndcl t0\ntexkill t0\nmov oC0, t0\n", u, {{0, {0.0f, 0.5f, 0.5f, -1.0f}}});
  EXPECT_TRUE(k.killed); // ps_2_0 tests w too
  EvalResult k3 = run("ps_1_4\ntexkill t0\nmov r0, c0\n", u, {{0, {0.0f, 0.5f, 0.5f, -1.0f}}});
  EXPECT_FALSE(k3.killed); // ps_1_x tests xyz only
}

TEST(CodegenEval, Listings2And4SumWeightedSamples) {
  // The evaluator's texture returns its coordinate (u, v, 0, 1), so the blur is a weighted
  // sum of the texture coordinates, computed here with the legacy rules by hand.
  const std::string l4 = "ps.1.3\ntex t0\ntex t1\ntex t2\ntex t3\nmul r0, t0, c0\n"
                         "mad r0, t1, c1, r0\nmad r0, t2, c2, r0\nmad r0, t3, c3, r0\n";
  auto u = consts({{0.25f, 0.25f, 0.25f, 0.25f},
                   {0.5f, 0.5f, 0.5f, 0.5f},
                   {2.0f, 2.0f, 2.0f, 2.0f} /* clamps to 1 */,
                   {0.125f, 0.125f, 0.125f, 0.125f}});
  std::map<uint32_t, Vec4> tc{{0, {0.5f, 0.25f, 0, 1}},
                              {1, {0.75f, 0.5f, 0, 1}},
                              {2, {0.25f, 0.125f, 0, 1}},
                              {3, {1.0f, 0.0f, 0, 1}}};
  EvalResult r = run(l4, u, tc);
  // x: 0.5·0.25 + 0.75·0.5 + 0.25·1 + 1·0.125 = 0.875; y: 0.0625 + 0.25 + 0.125 + 0 = 0.4375;
  // z: 0; w: 0.25 + 0.5 + 1 + 0.125 = 1.875 → range clamp ±1 after the last mad → 1.
  expect_same(r.out[0], {0.875f, 0.4375f, 0.0f, 1.0f}, "listing 4");

  const std::string l2 = "ps.2.0\ndcl t0\ndcl t1\ndcl_2d s0\ntexld r0, t0, s0\n"
                         "texld r1, t1, s0\nmul r0, r0, c0\nmad r0, r1, c1, r0\nmov oC0, r0\n";
  r = run(l2, u, tc);
  // No ps_2_0 clamps: c2 is unused, w = 1·0.25 + 1·0.5.
  expect_same(r.out[0], {0.5f, 0.3125f, 0.0f, 0.75f}, "listing 2 (two taps)");
}

TEST(CodegenEval, PixelSelectsAndTextureAddressing) {
  auto u = consts({{-0.5f, 0.0f, 0.75f, 0.25f}, {0.5f, 0.5f, 0.5f, 0.5f}, {0.0f, 0.0f, 1.0f, 0}});
  // cmp (s0 >= 0), cnd (s0 > 0.5) per component in ps_1_4; dp2add in ps_2_0.
  EvalResult r = run("ps_1_4\ncmp r1, c0, c1, -c1\ncnd r2, c0_x2, c1, -c1\nadd r0, r1, r2\n", u);
  // cmp: (-0.5, 0.5, 0.5, 0.5); cnd on 2·c0 = (-1, 0, 1.5, 0.5): (-0.5, -0.5, 0.5, -0.5)
  expect_same(r.out[0], {-1.0f, 0.0f, 1.0f, 0.0f}, "cmp + cnd");
  r = run("ps_2_0\ndp2add r0, c0, c1, c2.z\nmov oC0, r0\n", u);
  expect_same(r.out[0], {0.75f, 0.75f, 0.75f, 0.75f}, "dp2add");
  // texcoord saturates xyz and sets w = 1.
  r = run("ps_1_1\ntexcoord t0\nmov r0, t0\n", u, {{0, {1.5f, -0.25f, 0.5f, 7.0f}}});
  expect_same(r.out[0], {1.0f, 0.0f, 0.5f, 1.0f}, "texcoord");
  // texbem: (u, v) = TC(1).xy + M·t0.rg with stage 1's matrix; the texture echoes (u, v).
  Uniforms b = u;
  b.stages.textures[1].stage.bumpenv_mat = {0.5f, 0.0f, 0.0f, 0.25f}; // M00, M01, M10, M11
  r = run("ps_1_1\ntexcoord t0\ntexbem t1, t0\nmov r0, t1\n", b,
          {{0, {0.5f, 0.5f, 0.0f, 1.0f}}, {1, {0.125f, 0.25f, 0.0f, 1.0f}}});
  expect_same(r.out[0], {0.375f, 0.375f, 0.0f, 1.0f}, "texbem");
  // texm3x3spec: t0 = (1, 0.5, 0, 1); the pads and the last row give N = (1, 0.5, 0);
  // E = c0.xyz = (1, 0, 0): R = 2(N·E)/(N·N)·N − E = (0.6, 0.8, 0) (legacy_reflect).
  r = run("ps_1_1\ntexcoord t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c0\n"
          "mov r0, t3\n",
          consts({{1.0f, 0.0f, 0.0f, 0.0f}}),
          {{0, {1.0f, 0.5f, 0.0f, 1.0f}},
           {1, {1.0f, 0.0f, 0.0f, 0}},
           {2, {0.0f, 1.0f, 0.0f, 0}},
           {3, {0.0f, 0.0f, 1.0f, 0}}});
  const num::Vec3f refl = num::legacy_reflect({1.0f, 0.5f, 0.0f}, {1.0f, 0.0f, 0.0f});
  EXPECT_NEAR(refl.x, 0.6f, 1e-6f);
  EXPECT_NEAR(refl.y, 0.8f, 1e-6f);
  expect_same(r.out[0], {refl.x, refl.y, 0.0f, 1.0f}, "texm3x3spec");
}
