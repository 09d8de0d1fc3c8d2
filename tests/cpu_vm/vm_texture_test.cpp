// Texture instructions with a fake TextureUnit that returns the coordinate it was given,
// so that every coordinate computation can be checked by hand (docs/d3d9-rules.md §5.5–§5.7).
#include "vm_test_util.h"

using namespace vmtest;

namespace {
tierlift::ir::Conventions max8() {
  tierlift::ir::Conventions c;
  c.ps1x_max_value = 8;
  return c;
}
PixelOutput run(const std::string& text, const PixelInput& in, const EchoTextures& tex,
                tierlift::ir::Conventions conv = max8()) {
  ShaderVM vm = vm_of(parse(text), conv);
  return vm.run_pixel(in, {}, tex);
}
} // namespace

TEST(VmTexture, TexSamplesOwnStage) {
  EchoTextures tex;
  PixelInput in;
  in.tex[2] = {0.25f, 0.5f, 0.75f, 1};
  auto out = run("ps_1_1\ntex t2\nmov r0, t2\n", in, tex);
  EXPECT_VEC4(out.color[0], 0.25f, 0.5f, 0.75f, 1);
  EXPECT_EQ(tex.last_stage, 2);
}

TEST(VmTexture, TexProjectedDividesByW) {
  // (0.5, 0.25, 1, 2)/2 = (0.25, 0.125, 0.5, 1)
  EchoTextures tex;
  tex.stages[0].projected = true;
  PixelInput in = coords({{0.5f, 0.25f, 1, 2}});
  EXPECT_VEC4(run("ps_1_1\ntex t0\nmov r0, t0\n", in, tex).color[0], 0.25f, 0.125f, 0.5f, 1);
}

TEST(VmTexture, TexcoordSaturatesAndSetsW) {
  // (1.5, −0.5, 0.25, 7) → (1, 0, 0.25, 1)
  EchoTextures tex;
  PixelInput in = coords({{1.5f, -0.5f, 0.25f, 7}});
  EXPECT_VEC4(run("ps_1_1\ntexcoord t0\nmov r0, t0\n", in, tex).color[0], 1, 0, 0.25f, 1);
}

TEST(VmTexture, TexkillPs11TestsXyzOfCoordinates) {
  EchoTextures tex;
  PixelInput in = coords({{0.1f, 0.1f, 0.1f, -1}}); // w < 0 is ignored
  const char* text = "ps_1_1\ndef c0, 1, 1, 1, 1\ntexkill t0\nmov r0, c0\n";
  EXPECT_FALSE(run(text, in, tex).discarded);
  in.tex[0] = {0.1f, -0.1f, 0.1f, 1};
  EXPECT_TRUE(run(text, in, tex).discarded);
}

TEST(VmTexture, TexkillPs20TestsAllFour) {
  EchoTextures tex;
  PixelInput in = coords({{0.1f, 0.1f, 0.1f, -1}});
  const char* text = "ps_2_0\ndef c0, 1, 1, 1, 1\ndcl t0\ntexkill t0\nmov oC0, c0\n";
  EXPECT_TRUE(run(text, in, tex).discarded);
  in.tex[0] = {0.1f, 0.1f, 0.1f, 0};
  EXPECT_FALSE(run(text, in, tex).discarded);
}

TEST(VmTexture, TexkillPs14TestsRegisterXyz) {
  // texcrd r1 = TC0; phase 2 texkill r1: (0.5, −0.25, 0.5) → discarded.
  EchoTextures tex;
  PixelInput in = coords({{0.5f, -0.25f, 0.5f, 0}});
  const char* text = "ps_1_4\ndef c0, 1, 1, 1, 1\ntexcrd r1.rgb, t0\nphase\ntexkill r1\n"
                     "mov r0, c0\n";
  EXPECT_TRUE(run(text, in, tex).discarded);
  in.tex[0] = {0.5f, 0.25f, 0.5f, -1};
  EXPECT_FALSE(run(text, in, tex).discarded);
}

TEST(VmTexture, Texbem) {
  // Stage 1 matrix M00=0.5, M01=0.25, M10=−0.25, M11=1; t0 = TC0 = (0.5, 0.25, ...)
  // u = 0.25 + 0.5·0.5 + (−0.25)·0.25 = 0.4375; v = 0.5 + 0.25·0.5 + 1·0.25 = 0.875
  EchoTextures tex;
  tex.stages[1].bumpenv_mat = {0.5f, 0.25f, -0.25f, 1};
  PixelInput in = coords({{0.5f, 0.25f, 0, 0}, {0.25f, 0.5f, 0, 0}});
  auto out = run("ps_1_1\ntex t0\ntexbem t1, t0\nmov r0, t1\n", in, tex);
  EXPECT_VEC4(out.color[0], 0.4375f, 0.875f, 0, 0);
  EXPECT_EQ(tex.last_stage, 1);
}

TEST(VmTexture, TexReg2ArGbRgb) {
  // t0 = (0.125, 0.25, 0.375, 0.5): ar → (a, r) = (0.5, 0.125); gb → (0.25, 0.375);
  // rgb → (0.125, 0.25, 0.375).
  EchoTextures tex;
  PixelInput in = coords({{0.125f, 0.25f, 0.375f, 0.5f}});
  EXPECT_VEC4(run("ps_1_1\ntex t0\ntexreg2ar t1, t0\nmov r0, t1\n", in, tex).color[0], 0.5f, 0.125f,
              0, 0);
  EXPECT_VEC4(run("ps_1_1\ntex t0\ntexreg2gb t1, t0\nmov r0, t1\n", in, tex).color[0], 0.25f,
              0.375f, 0, 0);
  EXPECT_VEC4(run("ps_1_2\ntex t0\ntexreg2rgb t1, t0\nmov r0, t1\n", in, tex).color[0], 0.125f,
              0.25f, 0.375f, 0);
}

TEST(VmTexture, Texm3x2TexAndDepth) {
  // t0 = (0.5, 0.25, 1); u = TC1·t0 = (1, 2, 0)·t0 = 1; v = TC2·t0 = (0, 0, 0.5)·t0 = 0.5
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0.25f, 1, 0}, {1, 2, 0, 0}, {0, 0, 0.5f, 0}});
  auto out = run("ps_1_1\ntex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\nmov r0, t2\n", in, tex);
  EXPECT_VEC4(out.color[0], 1, 0.5f, 0, 0);
  // depth = u / v = 1 / 0.5 = 2 (the device clamps).
  auto d = run("ps_1_3\ndef c0, 1, 1, 1, 1\ntex t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\n"
               "mov r0, c0\n",
               in, tex);
  ASSERT_TRUE(d.depth.has_value());
  EXPECT_EQ(*d.depth, 2.0f);
}

TEST(VmTexture, Texm3x3TexAndTexm3x3) {
  // t0 = (0.5, 0.25, 0.75); rows TC1 = (0,0,1) → 0.75, TC2 = (1,1,0) → 0.75, TC3 = (2,0,0) → 1
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0.25f, 0.75f, 0}, {0, 0, 1, 0}, {1, 1, 0, 0}, {2, 0, 0, 0}});
  const char* pads = "tex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\n";
  EXPECT_VEC4(
      run(std::string("ps_1_1\n") + pads + "texm3x3tex t3, t0\nmov r0, t3\n", in, tex).color[0],
      0.75f, 0.75f, 1, 0);
  EXPECT_VEC4(
      run(std::string("ps_1_2\n") + pads + "texm3x3 t3, t0\nmov r0, t3\n", in, tex).color[0], 0.75f,
      0.75f, 1, 1);
}

TEST(VmTexture, Texm3x3SpecReflection) {
  // Rows identity → N = t0 = (0, 1, 1); E = c0 = (0, 0, 1).
  // N·E = 1, N·N = 2, k = 2·1/2 = 1, R = 1·(0, 1, 1) − (0, 0, 1) = (0, 1, 0).
  EchoTextures tex;
  PixelInput in = coords({{0, 1, 1, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}});
  auto out = run("ps_1_1\ndef c0, 0, 0, 1, 0\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\n"
                 "texm3x3spec t3, t0, c0\nmov r0, t3\n",
                 in, tex);
  EXPECT_VEC4(out.color[0], 0, 1, 0, 0);
  // vspec: E = (TC1.w, TC2.w, TC3.w) = (0, 0, 1) gives the same R.
  in.tex[3][3] = 1;
  auto v = run("ps_1_1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3vspec t3, t0\n"
               "mov r0, t3\n",
               in, tex);
  EXPECT_VEC4(v.color[0], 0, 1, 0, 0);
}

TEST(VmTexture, TexDp3AndTexDp3Tex) {
  // TC1·t0 = (1, 2, 3)·(0.5, 0.25, 0.125) = 0.5 + 0.5 + 0.375 = 1.375
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0.25f, 0.125f, 0}, {1, 2, 3, 0}});
  EXPECT_VEC4(run("ps_1_2\ntex t0\ntexdp3 t1, t0\nmov r0, t1\n", in, tex).color[0], 1.375f, 1.375f,
              1.375f, 1.375f);
  EXPECT_VEC4(run("ps_1_2\ntex t0\ntexdp3tex t1, t0\nmov r0, t1\n", in, tex).color[0], 1.375f, 0, 0,
              0);
}

TEST(VmTexture, Ps14TexldStageAndSelectors) {
  // texld r3, t1 samples stage 3 at TC1.xyz; texld r0, t0.xyw at (x, y, w).
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0.25f, 0.75f, 2}, {0.125f, 0.25f, 0.5f, 1}});
  auto out = run("ps_1_4\ntexld r3, t1\ntexld r0, t0.xyw\nadd r0, r0, r3\n", in, tex);
  // r3 = (0.125, 0.25, 0.5, 0); r0 = (0.5, 0.25, 2, 0) → sum (0.625, 0.5, 2.5, 0)
  EXPECT_VEC4(out.color[0], 0.625f, 0.5f, 2.5f, 0);
}

TEST(VmTexture, Ps14TexldFromRegisterWithDz) {
  // phase 1: texcrd r1.rgb = TC0 = (0.5, 0.25, 2); phase 2: texld r0, r1_dz → (0.25, 0.125, 2)
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0.25f, 2, 0}});
  auto out = run("ps_1_4\ntexcrd r1.rgb, t0\nphase\ntexld r0, r1_dz\n", in, tex);
  EXPECT_VEC4(out.color[0], 0.25f, 0.125f, 2, 0);
}

TEST(VmTexture, Ps14TexcrdIsNotSaturated) {
  // texcrd r0.rgb, t0 with TC0 = (1.5, −0.5, 3): kept (max 8); r0.a stays 0.
  EchoTextures tex;
  PixelInput in = coords({{1.5f, -0.5f, 3, 9}});
  auto out = run("ps_1_4\ndef c0, 0, 0, 0, 0\ntexcrd r0.rgb, t0\nmov r0.a, c0\n", in, tex);
  EXPECT_VEC4(out.color[0], 1.5f, -0.5f, 3, 0);
}

TEST(VmTexture, Ps20TexldTexldpTexldb) {
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0.25f, 1, 2}});
  const char* head = "ps_2_0\ndcl t0\ndcl_2d s2\n";
  auto a = run(std::string(head) + "texld r0, t0, s2\nmov oC0, r0\n", in, tex);
  EXPECT_VEC4(a.color[0], 0.5f, 0.25f, 1, 2);
  EXPECT_EQ(tex.last_stage, 2);
  // texldp: (0.5, 0.25, 1)/2 = (0.25, 0.125, 0.5), w = 1
  auto p = run(std::string(head) + "texldp r0, t0, s2\nmov oC0, r0\n", in, tex);
  EXPECT_VEC4(p.color[0], 0.25f, 0.125f, 0.5f, 1);
  // texldb: the bias is t0.w = 2
  run(std::string(head) + "texldb r0, t0, s2\nmov oC0, r0\n", in, tex);
  EXPECT_EQ(tex.last_bias, 2.0f);
}

// texldl samples at xyzw as given; its lod (.w) is no bias: every texture has one level,
// which any lod selects (NUMERICS.md, texldl).
TEST(VmTexture, Ps30TexldlSamplesTheCoordinateWithoutBias) {
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0.25f, 1, 3}});
  auto out = run("ps_3_0\ndcl_texcoord0 v0\ndcl_2d s1\ntexldl r0, v0, s1\nmov oC0, r0\n", in, tex);
  EXPECT_VEC4(out.color[0], 0.5f, 0.25f, 1, 3);
  EXPECT_EQ(tex.last_stage, 1);
  EXPECT_EQ(tex.last_bias, 0.0f);
}

TEST(VmTexture, Ps1xTextureResultsClampToRange) {
  // ps_1_1 with max 1: a sample of (2, −3, 0.5, 1) lands in t0 as (1, −1, 0.5, 1).
  ConstTextures tex;
  tex.value = {2, -3, 0.5f, 1};
  ShaderVM vm = vm_of(parse("ps_1_1\ntex t0\nmov r0, t0\n"), geforce3());
  EXPECT_VEC4(vm.run_pixel({}, {}, tex).color[0], 1, -1, 0.5f, 1);
}
