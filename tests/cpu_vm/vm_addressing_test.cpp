// Relative constant addressing (docs/d3d9-rules.md §1.3, §3.1–3.2), vertex outputs and their
// written masks, and listing defs overriding API constants.
#include "vm_test_util.h"

using namespace vmtest;

TEST(VmAddressing, RelativeReadWithOffsetSwizzleNegate) {
  // a0.x = floor(2.2) = 2 → c[a0.x + 3] = c5 = (1, 2, 3, 4); -c[a0.x + 3].wzyx = (−4, −3, −2, −1)
  ConstantBank c = bank({{2.2f, 0, 0, 0}});
  c.f.resize(8, Vec4{9, 9, 9, 9});
  c.f[5] = {1, 2, 3, 4};
  auto o = vs11("mov a0.x, r0.x\nmov oT0, c[a0.x + 3]\nmov oT1, -c[a0.x + 3].wzyx\n", c);
  EXPECT_VEC4(o.tex[0], 1, 2, 3, 4);
  EXPECT_VEC4(o.tex[1], -4, -3, -2, -1);
}

TEST(VmAddressing, RelativeReadSeesListingDefs) {
  // def c6 overrides the API value; c[a0.x + 4] with a0.x = 2 reads the def.
  ConstantBank c = bank({{2, 0, 0, 0}});
  c.f.resize(8, Vec4{9, 9, 9, 9});
  ShaderVM vm = vm_of(parse("vs_1_1\ndef c6, 0.5, 0.25, 0.125, 1\ndcl_position v0\nmov oPos, v0\n"
                            "mov r0, c0\nmov a0.x, r0.x\nmov oT0, c[a0.x + 4]\n"),
                      {});
  EXPECT_VEC4(vm.run_vertex({}, c).tex[0], 0.5f, 0.25f, 0.125f, 1);
}

TEST(VmAddressing, MissingApiConstantsReadZero) {
  // c7 is beyond the bank's size → (0, 0, 0, 0).
  ShaderVM vm = vm_of(parse("vs_1_1\ndcl_position v0\nmov oPos, v0\nmov oT0, c7\n"), {});
  EXPECT_VEC4(vm.run_vertex({}, bank({{1, 1, 1, 1}})).tex[0], 0, 0, 0, 0);
}

TEST(VmAddressing, VertexOutputsAndWrittenMasks) {
  // oPos = v0, oD1 = c0, oT0/oT1 written, oFog = c0.y, oPts = c0.z.
  ShaderVM vm = vm_of(parse("vs_1_1\ndcl_position v0\ndcl_texcoord v1\nmov oPos, v0\nmov oD1, c0\n"
                            "mov oT0, v1\nmov oT1, c0\nmov oFog, c0.y\nmov oPts, c0.z\n"),
                      {});
  VertexInput in;
  in.v[0] = {1, 2, 3, 1};
  in.v[1] = {0.5f, 0.25f, 0, 1};
  auto o = vm.run_vertex(in, bank({{0.75f, 0.5f, 4, 1}}));
  EXPECT_VEC4(o.pos, 1, 2, 3, 1);
  EXPECT_VEC4(o.color[1], 0.75f, 0.5f, 4, 1);
  EXPECT_VEC4(o.tex[0], 0.5f, 0.25f, 0, 1);
  EXPECT_EQ(o.color_written, 2);
  EXPECT_EQ(o.tex_written, 3);
  EXPECT_EQ(o.fog, 0.5f);
  EXPECT_EQ(o.point_size, 4.0f);
}

TEST(VmAddressing, MissingStreamComponentsReadZeroZeroZeroOne) {
  // VertexInput defaults every v# to (0, 0, 0, 1).
  ShaderVM vm =
      vm_of(parse("vs_1_1\ndcl_position v0\ndcl_normal v3\nmov oPos, v0\nmov oT0, v3\n"), {});
  EXPECT_VEC4(vm.run_vertex({}, {}).tex[0], 0, 0, 0, 1);
}

TEST(VmAddressing, LastDefWins) {
  ShaderVM vm = vm_of(parse("vs_1_1\ndef c0, 1, 1, 1, 1\ndef c0, 2, 2, 2, 2\ndcl_position v0\n"
                            "mov oPos, v0\nmov oT0, c0\n"),
                      {});
  EXPECT_VEC4(vm.run_vertex({}, bank({{5, 5, 5, 5}})).tex[0], 2, 2, 2, 2);
}
