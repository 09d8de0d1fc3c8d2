// Cube and volume reads on the CPU device (NUMERICS.md, cube maps and volume textures): the
// face rule of rounding.h against the Direct3D 9 / Vulkan face table worked by hand, its
// ties, both roundings of the face coordinates, the volume's slices under ADDRESSW, and the
// checks of pass::layered_binding and pass::layered_sources.
#include <gtest/gtest.h>

#include "tierlift/cpu/texture.h"
#include "tierlift/pass/setup.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::cpu {
namespace {

using pass::TextureShape;

std::shared_ptr<const img::Image> constant(uint32_t n, Vec4 c) {
  auto im = std::make_shared<img::Image>(n, n);
  for (size_t p = 0; p < im->rgba.size(); p += 4)
    for (int k = 0; k < 4; ++k) im->rgba[p + k] = c[k];
  return im;
}

struct FaceCase {
  float x, y, z;
  uint32_t face;
  double s, t; // (sc/|ma| + 1)/2, (tc/|ma| + 1)/2 from the table, by hand
};

// One direction per face, then directions whose major axis is shared (ties).
const FaceCase kFaces[] = {
    {1, 0.2f, 0.3f, 0, 0.35, 0.4},     // +X: sc = −z, tc = −y
    {-1, 0.2f, 0.3f, 1, 0.65, 0.4},    // −X: sc = z, tc = −y
    {0.2f, 1, 0.3f, 2, 0.6, 0.65},     // +Y: sc = x, tc = z
    {0.2f, -1, 0.3f, 3, 0.6, 0.35},    // −Y: sc = x, tc = −z
    {0.2f, 0.3f, 1, 4, 0.6, 0.35},     // +Z: sc = x, tc = −y
    {0.2f, 0.3f, -1, 5, 0.4, 0.35},    // −Z: sc = −x, tc = −y
    {4, -1, 2, 0, 0.25, 0.625},        // |ma| = 4
    {1, 1, 0, 2, 1, 0.5},              // |x| = |y|: y wins
    {-1, -1, 0.5f, 3, 0, 0.25},        // −Y: sc = x = −1, tc = −z = −0.5
    {1, 0, 1, 4, 1, 0.5},              // |x| = |z|: z wins
    {0, -1, -1, 5, 0.5, 1},            // |y| = |z|: z wins (−Z)
    {1, 1, 1, 4, 1, 0},                // all equal: z
    {2, 0.5f, -0.0f, 0, 0.5, 0.375},   // −0 minor components
    {0.25f, 0.5f, -0.0f, 2, 0.75, 0.5} // +Y: tc = z = −0 → t = ½
};

TEST(CubeRule, FacesAndCoordinatesFromTheTable) {
  for (const FaceCase& c : kFaces) {
    const std::string what = ::testing::PrintToString(std::vector<float>{c.x, c.y, c.z});
    const rounding::CubeCoord e = rounding::cube_coord_exact(c.x, c.y, c.z);
    const rounding::CubeCoord l = rounding::cube_coord_llvmpipe(c.x, c.y, c.z);
    EXPECT_EQ(e.face, c.face) << what;
    EXPECT_EQ(l.face, c.face) << what;
    EXPECT_EQ(e.s, static_cast<float>(c.s)) << what; // rounded once from the exact value
    EXPECT_EQ(e.t, static_cast<float>(c.t)) << what;
    // Bound of lavapipe's rule s = fl(fl(sc·h) + ½), h = fl(½/|ma|), against the exact s:
    // h's rounding moves sc·h (|sc·h| ≤ ½) by ≤ ½·2⁻²⁴ = 2⁻²⁵, the product's rounding by
    // ≤ 2⁻²⁶ (half an ulp below ½), the sum's by ≤ 2⁻²⁵ (half an ulp below 1): in all
    // ≤ 5·2⁻²⁶ ≈ 7.5e-8 ≤ 1e-7.
    EXPECT_NEAR(l.s, c.s, 1e-7) << what;
    EXPECT_NEAR(l.t, c.t, 1e-7) << what;
  }
}

// Where the two roundings part: lavapipe's h = fl(0.5/|ma|) rounds before the product.
// |ma| = 3, sc = 1: exact (1/3 + 1)/2 = 2/3 → fl32(2/3); lavapipe fl(fl(1·fl(1/6)) + ½).
TEST(CubeRule, LlvmpipeRoundsHalfOverMajorFirst) {
  const rounding::CubeCoord l = rounding::cube_coord_llvmpipe(0.7f, 0.1f, 3.0f); // +Z, sc = x
  const float h = 0.5f / 3.0f;
  EXPECT_EQ(l.s, 0.7f * h + 0.5f);
  const rounding::CubeCoord e = rounding::cube_coord_exact(0.7f, 0.1f, 3.0f);
  EXPECT_EQ(e.s, static_cast<float>((double(0.7f) / 3.0 + 1.0) / 2.0));
}

pass::TextureBinding face_cube() {
  std::vector<std::shared_ptr<const img::Image>> faces;
  for (int k = 0; k < 6; ++k) faces.push_back(constant(2, {float(k), 0, 0, 1}));
  return *pass::layered_binding(TextureShape::Cube, faces);
}

TEST(CubeSampling, DirectionReadsItsFaceOnBothRoundings) {
  pass::TextureBinding cube = face_cube();
  for (Filter f : {Filter::Point, Filter::Linear}) {
    cube.sampler.filter = f;
    for (const FaceCase& c : kFaces)
      for (bool llvmpipe : {false, true})
        EXPECT_EQ(sample_cube(cube, {c.x, c.y, c.z, 0}, llvmpipe, 0)[0], float(c.face));
  }
}

// ADDRESSU/V do not apply to a cube: the face is read with edge clamping (a WRAP sampler at
// s = 1 does not wrap to texel 0 of the face).
TEST(CubeSampling, FaceEdgesClampWhateverTheAddressMode) {
  auto face = std::make_shared<img::Image>(2, 2);
  face->rgba = {0, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1}; // column 1 reads 1
  std::vector<std::shared_ptr<const img::Image>> faces(6, face);
  pass::TextureBinding cube = *pass::layered_binding(TextureShape::Cube, faces);
  cube.sampler.filter = Filter::Linear;
  cube.sampler.address_u = cube.sampler.address_v = AddressMode::Wrap;
  // +Z with x = z: s = 1, the right edge; clamped: texel 1 alone.
  EXPECT_EQ(sample_cube(cube, {1, 0, 1, 0}, true, 0)[0], 1.0f);
  EXPECT_EQ(sample_cube(cube, {1, 0, 1, 0}, false, 0)[0], 1.0f);
}

// Direct3D 9 filters each face on its own (NUMERICS.md T4): at every corner of every face, an
// eighth of a texel inside both edges, a linear read's taps beyond the edges are the face's
// own edge texels, so a cube whose faces are the constants k reads k there under every address
// mode and both roundings (a tap from a neighbouring face would mix in its constant). The
// direction is T1's table inverted with the major axis ±1: sc, tc = ±15/16, s, t = 1/32 or 31/32.
TEST(CubeSampling, CornersOfEveryFaceReadOnlyThatFace) {
  std::vector<std::shared_ptr<const img::Image>> faces;
  for (int k = 0; k < 6; ++k) faces.push_back(constant(4, {float(k), 0, 0, 1}));
  pass::TextureBinding cube = *pass::layered_binding(TextureShape::Cube, faces);
  cube.sampler.filter = Filter::Linear;
  const float e = 15.0f / 16;
  for (AddressMode mode : {AddressMode::Wrap, AddressMode::Mirror, AddressMode::Clamp,
                           AddressMode::Border, AddressMode::MirrorOnce}) {
    cube.sampler.address_u = cube.sampler.address_v = mode;
    cube.sampler.border_color = {10, 10, 10, 10};
    for (float sc : {-e, e})
      for (float tc : {-e, e}) {
        const Vec4 dirs[6] = {{1, -tc, -sc, 0}, {-1, -tc, sc, 0}, {sc, 1, tc, 0},
                              {sc, -1, -tc, 0}, {sc, -tc, 1, 0},  {-sc, -tc, -1, 0}};
        for (int k = 0; k < 6; ++k)
          for (bool llvmpipe : {false, true})
            EXPECT_EQ(sample_cube(cube, dirs[k], llvmpipe, 0)[0], float(k))
                << "face " << k << " sc " << sc << " tc " << tc << " mode " << int(mode);
      }
  }
}

pass::TextureBinding slices(AddressMode mode, Filter filter) {
  std::vector<std::shared_ptr<const img::Image>> s;
  for (int k = 0; k < 4; ++k) s.push_back(constant(2, {float(k), 0, 0, 1}));
  pass::TextureBinding b = *pass::layered_binding(TextureShape::Volume, s);
  b.sampler.filter = filter;
  b.sampler.address_w = mode;
  b.sampler.border_color = {10, 10, 10, 10};
  return b;
}

TEST(VolumeSampling, SlicesUnderAddressW) {
  using M = AddressMode;
  struct Case {
    M mode;
    Filter filter;
    float w, expect;
  };
  const Case cases[] = {
      {M::Clamp, Filter::Point, 0.625f, 2},    {M::Wrap, Filter::Point, 1.375f, 1},
      {M::Mirror, Filter::Point, 1.125f, 3},   {M::Border, Filter::Point, 1.5f, 10},
      {M::Clamp, Filter::Linear, 0.5f, 1.5f},  {M::Wrap, Filter::Linear, 0.0625f, 0.75f},
      {M::Clamp, Filter::Linear, 0.0625f, 0},  {M::Border, Filter::Linear, 0.0625f, 2.5f},
      {M::Mirror, Filter::Linear, 0.0625f, 0}, {M::Clamp, Filter::Linear, 0.8125f, 2.75f},
  };
  for (const Case& c : cases)
    for (bool llvmpipe : {false, true})
      EXPECT_EQ(sample_volume(slices(c.mode, c.filter), {0.5f, 0.5f, c.w, 0}, llvmpipe, 0)[0],
                c.expect)
          << "mode " << int(c.mode) << " filter " << int(c.filter) << " w " << c.w;
}

TEST(LayeredBinding, ChecksFacesAndSlices) {
  std::vector<std::shared_ptr<const img::Image>> five(5, constant(2, {0, 0, 0, 1}));
  EXPECT_FALSE(pass::layered_binding(TextureShape::Cube, five).ok());
  EXPECT_TRUE(pass::layered_binding(TextureShape::Volume, five).ok());
  std::vector<std::shared_ptr<const img::Image>> six(6, std::make_shared<img::Image>(2, 3));
  ir::Result<pass::TextureBinding> r = pass::layered_binding(TextureShape::Cube, six);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message().find("square"), std::string::npos) << r.message();
  six[3] = std::make_shared<img::Image>(4, 4);
  EXPECT_FALSE(pass::layered_binding(TextureShape::Volume, six).ok());
  EXPECT_FALSE(pass::layered_binding(TextureShape::Volume, {}).ok());
}

TEST(LayeredSources, CubeAndVolumeSpellings) {
  const pass::LayeredSources c = pass::layered_sources("cube:a.png,b.png,c,d,e,f");
  EXPECT_EQ(c.shape, TextureShape::Cube);
  EXPECT_EQ(c.sources, (std::vector<std::string>{"a.png", "b.png", "c", "d", "e", "f"}));
  const pass::LayeredSources v = pass::layered_sources("volume:builtin:noise:8x8:1,x.pfm");
  EXPECT_EQ(v.shape, TextureShape::Volume);
  EXPECT_EQ(v.sources, (std::vector<std::string>{"builtin:noise:8x8:1", "x.pfm"}));
  const pass::LayeredSources t = pass::layered_sources("builtin:noise:8x8");
  EXPECT_EQ(t.shape, TextureShape::Tex2D);
  EXPECT_EQ(t.sources, std::vector<std::string>{"builtin:noise:8x8"});
}

} // namespace
} // namespace tierlift::cpu

namespace tierlift::cpu {
namespace {

// `run --texture s1=cube:…` and `volume:…` reach the pass as layered bindings; a cube of five
// faces is an error that names the stage.
TEST(LayeredSources, PreparePassBindsCubesAndVolumes) {
  pass::RunRequest r;
  r.address = AddressMode::Mirror;
  std::string cube = "cube:", volume = "volume:";
  for (int k = 0; k < 6; ++k)
    cube += (k ? "," : "") + std::string("builtin:noise:4x4:") + std::to_string(k + 1);
  for (int k = 0; k < 3; ++k)
    volume += (k ? "," : "") + std::string("builtin:noise:8x4:") + std::to_string(k + 1);
  r.textures.push_back({1, cube});
  r.textures.push_back({2, volume});
  ir::Result<pass::Pass> p = pass::prepare_pass(r);
  ASSERT_TRUE(p.ok()) << p.message();
  EXPECT_EQ(p->textures[1].shape, TextureShape::Cube);
  EXPECT_EQ(p->textures[1].layers.size(), 6u);
  EXPECT_EQ(p->textures[2].shape, TextureShape::Volume);
  EXPECT_EQ(p->textures[2].layers.size(), 3u);
  EXPECT_EQ(p->textures[2].layers[0]->width, 8u);
  EXPECT_EQ(p->textures[2].sampler.address_w, AddressMode::Mirror);
  EXPECT_NE(p->textures[1].layers[0], p->textures[1].layers[1]); // distinct seeds, distinct images

  pass::RunRequest bad;
  bad.textures.push_back({3, "cube:builtin:noise:4x4,builtin:noise:4x4"});
  ir::Result<pass::Pass> q = pass::prepare_pass(bad);
  ASSERT_FALSE(q.ok());
  EXPECT_NE(q.message().find("--texture s3: a cube texture has 6 faces, not 2"), std::string::npos)
      << q.message();
}

} // namespace
} // namespace tierlift::cpu
