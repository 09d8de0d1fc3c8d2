// Shader models 2.x and 3.0: listings in the style fxc writes are valid, and each rule of
// docs/d3d9-rules.md §14 is reported where it is broken (bad) and quiet in the nearest
// listing that keeps it (good).
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tierlift/ir/profile.h"
#include "validator_test_util.h"

using tierlift::vtest::has_error;
using tierlift::vtest::is_clean;
using tierlift::vtest::RuleCase;

namespace {

namespace ir = tierlift::ir;

// A ps_3_0 shader of the shape fxc writes: semantics on v#, vFace and vPos, _pp and
// _centroid, predication, rep with break_comp, if_comp, gradients, oC0 and oDepth.
const char* kPs30 = R"(ps_3_0
def c4, 0.5, 1, 0, 0
defi i0, 3, 0, 0, 0
dcl_texcoord0 v0.xy
dcl_texcoord1_centroid v1.xyz
dcl_color_pp v2
dcl vFace
dcl vPos.xy
dcl_2d s0
dcl_cube s1
texld_pp r0, v0, s0
nrm_pp r1.xyz, v1
texld r2, r1, s1
mul r0, r0, r2
cmp r3.x, vFace, c4.y, c4.z
setp_gt p0.x, r3.x, c4.x
(p0.x) mul r0.xyz, r0, v2
rep i0
  add r0, r0, c0
  break_ge r0.w, c4.y
endrep
if_lt vPos.x, c1.x
  dsx r2.xy, v0
  add r0.xy, r0, r2_abs
else
  texld r2, v0.yxzw, s0
endif
mov_sat oC0, r0
mov oDepth, r3.x
)";

// A vs_3_0 shader: semantics on v# and o#, a vertex texture fetch, loop with aL reading
// c[aL + n], relative output o[aL], predication, 3.0's sincos, _sat.
const char* kVs30 = R"(vs_3_0
def c8, 1, 0, 0.5, 2
defi i0, 4, 0, 1, 0
dcl_position v0
dcl_normal v1
dcl_texcoord v2
dcl_position o0
dcl_texcoord o1.xy
dcl_color o2
dcl_texcoord1 o3
dcl_2d s0
dp4 o0.x, v0, c0
dp4 o0.y, v0, c1
dp4 o0.z, v0, c2
dp4 o0.w, v0, c3
mov o1.xy, v2
mov r1, c8.y
loop aL, i0
  add r1, r1, c[aL + 20]
endloop
texldl r2, v2, s0
setp_ge p0, v1, c8.y
(p0) mul r1, r1, c8.w
(!p0.x) mov r1.x, c8.x
sincos r3.xy, v1.x
add_sat o2, r1, r2
mov o3, r3.xyxy
)";

} // namespace

TEST(LaterProfiles, FxcStylePs30IsValid) {
  EXPECT_TRUE(is_clean(kPs30));
}

TEST(LaterProfiles, FxcStyleVs30IsValid) {
  EXPECT_TRUE(is_clean(kVs30));
}

// The fuzz seeds of the later profiles (tests/fuzz/seeds, read by .ci/run) stay valid, so
// the fuzzer starts from listings that reach every rule.
TEST(LaterProfiles, FuzzSeedsAreValid) {
  namespace fs = std::filesystem;
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(TIERLIFT_SOURCE_DIR) / "tests/fuzz/seeds")) {
    if (!e.is_regular_file() || e.path().filename().string().rfind("later_", 0) != 0) continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    SCOPED_TRACE(e.path().string());
    EXPECT_TRUE(is_clean(text.str()));
    ++n;
  }
  EXPECT_GE(n, 4);
}

// A ps_2_x listing with 2_a's features is valid under the default (most capable) caps and
// under ps_2_a, and refused under ps_2_b, which has no predication and no gradients.
TEST(LaterProfiles, Ps2xCapsPresets) {
  const std::string text = "ps_2_x\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\ndsx r1, r0\n"
                           "setp_gt p0, r1, c0\n(p0) mov r0, r1\nmov oC0, r0\n";
  EXPECT_TRUE(is_clean(text));
  auto run_with = [&](const char* preset) {
    auto caps = ir::caps_preset(preset);
    EXPECT_TRUE(caps.has_value());
    auto parsed = tierlift::assembly::parse_text(text, "t.asm");
    EXPECT_TRUE(parsed.program.has_value());
    tierlift::assembly::ValidateOptions o;
    o.caps = caps->second;
    ir::DiagnosticSink diags;
    bool ok = tierlift::assembly::validate(*parsed.program, caps->first, diags, o);
    std::string all;
    for (const ir::Diagnostic& d : diags.all())
      if (d.severity == ir::Severity::Error) all += d.rule + ": " + d.message + "\n";
    return std::pair{ok, all};
  };
  EXPECT_TRUE(run_with("ps_2_a").first) << run_with("ps_2_a").second;
  auto [ok_b, errors_b] = run_with("ps_2_b");
  EXPECT_FALSE(ok_b);
  EXPECT_NE(errors_b.find("dsx is a gradient instruction"), std::string::npos) << errors_b;
  EXPECT_NE(errors_b.find("setp_gt needs predication"), std::string::npos) << errors_b;
  EXPECT_NE(errors_b.find("a predicated instruction needs predication"), std::string::npos)
      << errors_b;
}

// The diagnostics of `text` validated as ps_2_x under the caps of fxc's target `preset`.
ir::DiagnosticSink validate_ps2x_under(const std::string& text, const char* preset, bool& ok) {
  ir::DiagnosticSink diags;
  auto parsed = tierlift::assembly::parse_text(text, "t.asm");
  EXPECT_TRUE(parsed.program.has_value());
  ok = false;
  if (!parsed.program) return diags;
  tierlift::assembly::ValidateOptions o;
  o.caps = ir::caps_preset(preset)->second;
  ok = tierlift::assembly::validate(*parsed.program, ir::Profile::ps_2_x, diags, o);
  return diags;
}

// ps_2_a has no flow control (the D3DX reference lists none among its capabilities): rep and
// if_comp are refused under it, and taken under the default 2.x caps.
TEST(LaterProfiles, Ps2aHasNoFlowControl) {
  const std::string text = "ps_2_x\ndefi i0, 2, 0, 0, 0\nmov r0, c0\nrep i0\nadd r0, r0, c1\n"
                           "endrep\nif_gt r0.x, c2.x\nmov r0, c3\nendif\nmov oC0, r0\n";
  EXPECT_TRUE(is_clean(text));
  bool ok = true;
  const ir::DiagnosticSink diags = validate_ps2x_under(text, "ps_2_a", ok);
  EXPECT_FALSE(ok);
  std::string lines;
  for (const ir::Diagnostic& d : diags.all())
    if (d.severity == ir::Severity::Error)
      lines += std::to_string(d.loc.line) + " " + d.rule + "\n";
  EXPECT_EQ(lines, "4 flow\n7 flow\n");
}

// ps_2_x's temps follow the caps: r22 exists with 32 temps (default, ps_2_b), not in ps_2_a.
TEST(LaterProfiles, Ps2xTempsFollowTheCaps) {
  const std::string text = "ps_2_x\nmov r22, c0\nmov oC0, r22\n";
  EXPECT_TRUE(is_clean(text));
  bool ok = true;
  const ir::DiagnosticSink diags = validate_ps2x_under(text, "ps_2_a", ok);
  EXPECT_FALSE(ok);
  ASSERT_FALSE(diags.all().empty());
  EXPECT_EQ(diags.all()[0].rule, "register-range");
  EXPECT_EQ(diags.all()[0].loc.line, 2u);
}

namespace {

const RuleCase kCases[] = {
    {"PredicationNeedsALaterProfile",
     "vs_2_0\ndcl_position v0\n(p0) mov oPos, v0\n",
     "predicate",
     3,
     1,
     {"predicated instructions exist in vs_2_x, ps_2_x, vs_3_0 and ps_3_0, not in vs_2_0"},
     "vs_2_x\ndcl_position v0\nsetp_gt p0, v0, c0\n(p0) mov oPos, v0\n"},
    {"SetpWritesP0",
     "vs_2_x\ndcl_position v0\nsetp_gt r0, v0, c0\nmov oPos, v0\n",
     "operand-kind",
     3,
     9,
     {"setp_gt writes the predicate p0, not r0"},
     "vs_2_x\ndcl_position v0\nsetp_gt p0, v0, c0\nmov oPos, v0\n"},
    {"OnlySetpWritesP0",
     "vs_2_x\ndcl_position v0\nmov p0, v0\nmov oPos, v0\n",
     "register-access",
     3,
     5,
     {"p0 is written by setp only"},
     "vs_2_x\ndcl_position v0\nsetp_ne p0, v0, v0\nmov oPos, v0\n"},
    {"P0IsNotData",
     "vs_2_x\ndcl_position v0\nsetp_gt p0, v0, c0\nadd oPos, v0, p0\n",
     "register-access",
     4,
     15,
     {"p0 is read only as a predicate"},
     "vs_2_x\ndcl_position v0\nsetp_gt p0, v0, c0\n(p0) add oPos, v0, c0\n"},
    {"PredicateReadBeforeSetp",
     "vs_3_0\ndcl_position v0\ndcl_position o0\n(p0.y) mov o0, v0\n",
     "read-before-write",
     4,
     1,
     {"p0.y is read before it is written"},
     "vs_3_0\ndcl_position v0\ndcl_position o0\nsetp_lt p0, v0, c0\n(p0.y) mov o0, v0\n"},
    {"BreakOutsideALoop",
     "ps_3_0\nbreak_gt r0.x, c0.x\nmov oC0, c0\n",
     "flow",
     2,
     1,
     {"break_gt outside loop/rep"},
     "ps_3_0\nrep i0\nbreak_gt c1.x, c0.x\nendrep\nmov oC0, c0\n"},
    {"IfCompNeedsReplicates",
     "ps_3_0\nif_lt c1, c0.x\nendif\nmov oC0, c0\n",
     "swizzle",
     2,
     7,
     {"if_lt compares single components: source 1 needs a replicate swizzle"},
     "ps_3_0\nif_lt c1.y, c0.x\nendif\nmov oC0, c0\n"},
    {"LoopNestingFollowsStaticDepth",
     "vs_3_0\ndcl_position o0\nrep i0\nrep i0\nrep i0\nrep i0\nrep i0\nendrep\nendrep\nendrep\n"
     "endrep\nendrep\nmov o0, c0\n",
     "flow",
     7,
     1,
     {"vs_3_0 allows loop/rep nesting depth 4; this rep is at depth 5"},
     "vs_3_0\ndcl_position o0\nrep i0\nrep i0\nrep i0\nrep i0\nendrep\nendrep\nendrep\n"
     "endrep\nmov o0, c0\n"},
    {"LoopIsNotInPs2x",
     "ps_2_x\nloop aL, i0\nendloop\nmov oC0, c0\n",
     "not-in-profile",
     2,
     1,
     {"loop is not available in ps_2_x"},
     "ps_2_x\nrep i0\nendrep\nmov oC0, c0\n"},
    {"Ps30HasNoTextureRegisters",
     "ps_3_0\ndcl_texcoord v0\nmov oC0, t0\n",
     "register-file",
     3,
     10,
     {"t0 does not exist in ps_3_0"},
     "ps_3_0\ndcl_texcoord v0\nmov oC0, v0\n"},
    {"Ps30RelativeInputsUseAL",
     "ps_3_0\ndcl_texcoord v0\ndcl_texcoord1 v1\nmov oC0, v[a0.x]\n",
     "relative-address",
     4,
     12,
     {"ps_3_0 addresses registers with aL only"},
     "ps_3_0\ndcl_texcoord v0\ndcl_texcoord1 v1\nloop aL, i0\nmov r0, v[aL]\nendloop\n"
     "mov oC0, r0\n"},
    {"Vs30WritesDeclaredOutputs",
     "vs_3_0\ndcl_position o0\nmov o0, c0\nmov o1, c1\n",
     "declaration",
     4,
     5,
     {"o1 is written but not declared"},
     "vs_3_0\ndcl_position o0\ndcl_color o1\nmov o0, c0\nmov o1, c1\n"},
    {"Vs30HasNoOPos",
     "vs_3_0\nmov oPos, c0\n",
     "register-file",
     2,
     5,
     {"oPos does not exist in vs_3_0"},
     "vs_3_0\ndcl_position o0\nmov o0, c0\n"},
    {"Vs30DeclarationsTakeNoModifiers",
     "vs_3_0\ndcl_texcoord0_centroid v0\ndcl_position o0\nmov o0, v0\n",
     "modifier",
     2,
     1,
     {"vs_3_0 declarations take no modifiers"},
     "vs_3_0\ndcl_texcoord0 v0\ndcl_position o0\nmov o0, v0\n"},
    {"AbsModifierIsThreeZeroOnly",
     "vs_2_x\ndcl_position v0\nmov oPos, v0_abs\n",
     "modifier",
     3,
     11,
     {"_abs is a vs_3_0/ps_3_0 modifier"},
     "vs_3_0\ndcl_position v0\ndcl_position o0\nmov o0, v0_abs\n"},
    {"PpIsNotInVertexShaders",
     "vs_3_0\ndcl_position o0\nadd_pp o0, c0, c1\n",
     "modifier",
     3,
     1,
     {"_pp is not allowed in vs_3_0"},
     "vs_3_0\ndcl_position o0\nadd_sat o0, c0, c1\n"},
    {"TexldlIsThreeZeroOnly",
     "ps_2_x\ndcl t0\ndcl_2d s0\ntexldl r0, t0, s0\nmov oC0, r0\n",
     "not-in-profile",
     4,
     1,
     {"texldl is not available in ps_2_x"},
     "ps_2_x\ndcl t0\ndcl_2d s0\ntexldb r0, t0, s0\nmov oC0, r0\n"},
    // A vertex shader reads textures with texldl only (vertex texture fetch: no gradients
    // there, so no implicit level of detail): texld, texldb and texldp are pixel-shader
    // instructions, refused at the instruction. The good listing is the texldl that runs.
    {"TexldIsNotInVertexShaders",
     "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ntexld r0, v0, s0\nmov o0, r0\n",
     "not-in-profile",
     5,
     1,
     {"texld is not available in vs_3_0"},
     "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ntexldl r0, v0, s0\nmov o0, r0\n"},
    {"TexldbIsNotInVertexShaders",
     "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ntexldb r0, v0, s0\nmov o0, r0\n",
     "not-in-profile",
     5,
     1,
     {"texldb is not available in vs_3_0"},
     "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ntexldl r0, v0, s0\nmov o0, r0\n"},
    {"TexldpIsNotInVertexShaders",
     "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ntexldp r0, v0, s0\nmov o0, r0\n",
     "not-in-profile",
     5,
     1,
     {"texldp is not available in vs_3_0"},
     "vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\ntexldl r0, v0, s0\nmov o0, r0\n"},
    {"FlowControlIsNotPredicated",
     "vs_3_0\ndcl_position o0\nsetp_gt p0, c0, c1\n(p0.x) rep i0\nendrep\nmov o0, c0\n",
     "predicate",
     4,
     1,
     {"rep cannot be predicated: Direct3D 9 predicates arithmetic and texture instructions "
      "only"},
     "vs_3_0\ndcl_position o0\nsetp_gt p0, c0, c1\nif p0.x\nendif\nmov o0, c0\n"},
};

TIERLIFT_RULE_SUITE(LaterRules, kCases);

} // namespace

// The listings Wine's d3dcompiler tests expect D3DAssemble to refuse, for the later
// profiles: each is refused here by the parser or the validator.
TEST(LaterProfiles, WhatWindowsRefusesIsRefused) {
  const char* refused[] = {
      "ps_3_0\ndcl_2d s2\ntexldd_x2 r0, v1, s2, v3, v4\n",
      "vs_1_1\n(p0) add r0, r0, v0\n",
      "ps_3_0\nmov r0, v[ a0 + 12 ]\n",
      "ps_3_0\nmov r0, v[ aL.x + 12 ]\n",
      "ps_3_0\ndcl_2d s2\ntexldd r0, t1, s2, v3, v4\n",
      "vs_3_0\nmov r2, 2 - r0\n",
      "vs_3_0\nmov r2, c[ aL + 3.4 ]\n",
      "vs_3_0\nmov r2, 1 - r1\n",
      "ps_3_0\ndcl_positiont o0\n",
      "vs_3_0\nadd_pp r0, r0, r1\n",
      "ps_3_0\nadd_x4 r0, r0, r1\n",
      "ps_3_0\nadd oC4, r0, r1\n",
      "vs_3_0\nadd r0, r0, v17\n",
      "vs_3_0\nadd o13, r0, r1\n",
      "vs_3_0\ncall l2048\n",
      "ps_3_0\ntexld r0, r1, s20\n",
      "vs_3_0\nadd r0, r0[ a0.x ], r1\n",
      "ps_3_0\nadd r0, v[ a0.x ], r1\n",
      "ps_3_0\ndcl_texcoord0_sat v0\n",
      "ps_3_0\ndcl_texcoord0_x2 v0\n",
      "vs_3_0\ndcl_texcoord0_centroid v0\n",
      "vs_3_0\ndcl_2d_pp s0\n",
  };
  for (const char* text : refused) {
    tierlift::vtest::Run r = tierlift::vtest::run(text);
    EXPECT_FALSE(r.parsed.program && r.valid) << text;
  }
}
