// 2x2 quads on the interpreter (NUMERICS.md rules F8, F9): dsx/dsy are fine differences inside
// the quad (lanes top-left, top-right, bottom-left, bottom-right), every source is read in all
// four lanes before any lane writes, a lane texkill discards stays a neighbour, and a pixel run
// alone is its own neighbour. The same rules run on lavapipe in
// tests/vulkan/diff_gradients_test.cpp.
#include "vm_test_util.h"

using namespace vmtest;

namespace {

// t0.x of the four lanes: 1, 3 (top row), 7, 15 (bottom row); t0.y ten times as much.
std::array<PixelInput, 4> lanes() {
  std::array<PixelInput, 4> in;
  const float x[4] = {1, 3, 7, 15};
  for (size_t l = 0; l < 4; ++l) in[l].tex[0] = {x[l], 10 * x[l], 0, 1};
  return in;
}

std::array<PixelOutput, 4> run_quad(const std::string& text, const ConstantBank& c = {}) {
  ShaderVM vm = vm_of(parse(text), {});
  EXPECT_TRUE(vm.needs_quad());
  static const ConstTextures none;
  std::array<PixelOutput, 4> out;
  vm.run_quad(lanes(), c, none, out);
  return out;
}

} // namespace

TEST(VmQuads, FineDifferencesOnTheLanesOwnRowAndColumn) {
  // dsx: top row 3 − 1 = 2, bottom row 15 − 7 = 8; dsy: left column 7 − 1 = 6, right column
  // 15 − 3 = 12 (coarse differences would give 2 and 6 everywhere). y is ten times x.
  const auto out =
      run_quad("ps_3_0\ndcl_texcoord0 v0\ndsx r0, v0\ndsy r1, v0\nmov oC0, r0\nmov oC1, r1\n");
  const float dx[4] = {2, 2, 8, 8}, dy[4] = {6, 12, 6, 12};
  for (size_t l = 0; l < 4; ++l) {
    EXPECT_VEC4(out[l].color[0], dx[l], 10 * dx[l], 0, 0);
    EXPECT_VEC4(out[l].color[1], dy[l], 10 * dy[l], 0, 0);
  }
}

TEST(VmQuads, SourcesAreReadInEveryLaneBeforeAnyWrites) {
  // dsx r0, r0 in place: lane 1 reads lane 0's r0 as it was (1), not lane 0's result (2).
  const auto out = run_quad("ps_3_0\ndcl_texcoord0 v0\nmov r0, v0\ndsx r0, r0\nmov oC0, r0\n");
  const float dx[4] = {2, 2, 8, 8};
  for (size_t l = 0; l < 4; ++l) EXPECT_FLOAT_EQ(out[l].color[0][0], dx[l]) << l;
}

TEST(VmQuads, ModifiersMaskAndSaturate) {
  // -v0.yx: .x reads −t0.y, −10 and −30 on the top row: dsx = −30 + 10 = −20, saturated to 0;
  // .y (masked out) keeps c0.y = 0.5; dsy of |t0.x| into .z: 7 − 1 = 6, 15 − 3 = 12.
  const auto out = run_quad("ps_3_0\ndcl_texcoord0 v0\nmov r0, c0\ndsx_sat r0.x, -v0.yx\n"
                            "dsy r0.z, v0_abs.x\nmov oC0, r0\n",
                            bank({{0.5f, 0.5f, 0.5f, 0.5f}}));
  const float dy[4] = {6, 12, 6, 12};
  for (size_t l = 0; l < 4; ++l) EXPECT_VEC4(out[l].color[0], 0, 0.5f, dy[l], 0.5f);
}

TEST(VmQuads, KilledLaneStaysANeighbour) {
  // Only lane 1 (t0.x = 3 = c1.x) reaches the texkill, of −t0 (negative): it is discarded but
  // runs on, r0 = t0 + 100 there too, so lane 0's dsx is 103 − 101 = 2. Had lane 1 stopped at
  // the texkill, its r0 would be 0 and lane 0 would read −101.
  const auto out = run_quad("ps_3_0\ndcl_texcoord0 v0\nmov r2, -v0\nif_eq v0.x, c1.x\n"
                            "texkill r2\nendif\nadd r0, v0, c0\ndsx r1, r0\nmov oC0, r1\n",
                            bank({{100, 100, 100, 100}, {3, 0, 0, 0}}));
  EXPECT_FALSE(out[0].discarded);
  EXPECT_TRUE(out[1].discarded);
  EXPECT_FLOAT_EQ(out[0].color[0][0], 2);
  EXPECT_FLOAT_EQ(out[2].color[0][0], 8);
}

TEST(VmQuads, APixelAloneIsItsOwnNeighbour) {
  ShaderVM vm = vm_of(parse("ps_3_0\ndcl_texcoord0 v0\ndsx r0, v0\nmov oC0, r0\n"), {});
  static const ConstTextures none;
  const Vec4 r = vm.run_pixel(coords({{5, inf_f(), -2, 0}}), {}, none).color[0];
  EXPECT_EQ(r[0], 0.0f);
  EXPECT_TRUE(std::isnan(r[1])); // ∞ − ∞
  EXPECT_EQ(r[2], 0.0f);
  EXPECT_FALSE(vm_of(parse("ps_3_0\nmov oC0, c0\n"), {}).needs_quad());
}

TEST(VmQuads, TexlddReadsLevelZero) {
  // NUMERICS.md rule F10: the coordinate goes to the stage as texld's does, with no bias;
  // the gradients (here large ones, a far level once textures have levels) do not move it.
  EchoTextures tex;
  tex.last_bias = 7;
  ShaderVM vm = vm_of(parse("ps_3_0\ndcl_texcoord0 v0\ndcl_2d s3\ntexldd r0, v0, s3, c0, c1\n"
                            "mov oC0, r0\n"),
                      {});
  const PixelOutput out =
      vm.run_pixel(coords({{0.25f, 0.5f, 0.75f, 1}}), bank({{64, 64, 0, 0}, {-64, 64, 0, 0}}), tex);
  EXPECT_VEC4(out.color[0], 0.25f, 0.5f, 0.75f, 1);
  EXPECT_EQ(tex.last_stage, 3);
  EXPECT_EQ(tex.last_bias, 0.0f);
}
