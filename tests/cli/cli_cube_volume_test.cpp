// `tierlift run --texture sN=cube:…` and `volume:…`: six face files (or slices) become one
// cube (volume) texture that both devices read; a face count other than six is an error.
#include <gtest/gtest.h>

#include "cli_test_util.h"
#include "temp_dir.h"
#include "tierlift/image/io.h"

using tierlift::test::run_cli;

namespace {

struct Scratch : tierlift::test::TempDir {
  Scratch() : TempDir("cube_volume") {}
};

// A 2×2 PFM whose texels are all (v, v/2, 0).
std::string constant_pfm(const Scratch& s, const std::string& name, float v) {
  tierlift::img::Image im(2, 2);
  for (size_t p = 0; p < im.rgba.size(); p += 4) {
    im.rgba[p] = v;
    im.rgba[p + 1] = v / 2;
    im.rgba[p + 3] = 1;
  }
  const std::string path = s.file(name);
  EXPECT_TRUE(tierlift::img::write_pfm(path, im).ok());
  return path;
}

// Direction c0 = (0.2, 0.3, −1) reads −Z, the sixth face: 6 and 3 on both devices.
TEST(RunCubeVolume, CubeFacesInD3D9Order) {
  Scratch s;
  std::string faces;
  for (int k = 0; k < 6; ++k)
    faces += (k ? "," : "") + constant_pfm(s, "f" + std::to_string(k) + ".pfm", float(k + 1));
  const std::string ps =
      s.file("c.psh", "ps_2_0\ndcl_cube s0\nmov r1, c0\ntexld r0, r1, s0\nmov oC0, r0\n");
  auto r = run_cli("run --ps " + ps + " --size 2x2 --format rgba32f --const ps:c0=0.2,0.3,-1,0" +
                   " --texture s0=cube:" + faces + " --probe 1,1 --backend both");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1,1: 6 3 0 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1,1 (vulkan): 6 3 0 1"), std::string::npos) << r.out;
}

// w = 0.7 on three slices reads slice floor(2.1) = 2 (point filtering).
TEST(RunCubeVolume, VolumeSlices) {
  Scratch s;
  const std::string slices = constant_pfm(s, "a.pfm", 1) + "," + constant_pfm(s, "b.pfm", 2) + "," +
                             constant_pfm(s, "c.pfm", 4);
  const std::string ps =
      s.file("v.psh", "ps_2_0\ndcl_volume s0\nmov r1, c0\ntexld r0, r1, s0\nmov oC0, r0\n");
  auto r = run_cli("run --ps " + ps + " --size 2x2 --format rgba32f --const ps:c0=0.5,0.5,0.7,0" +
                   " --texture s0=volume:" + slices + " --probe 0,0 --backend both");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0,0: 4 2 0 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0,0 (vulkan): 4 2 0 1"), std::string::npos) << r.out;
}

TEST(RunCubeVolume, FiveFacesAreAnError) {
  Scratch s;
  std::string faces;
  for (int k = 0; k < 5; ++k)
    faces += (k ? "," : "") + constant_pfm(s, "f" + std::to_string(k) + ".pfm", 1);
  const std::string ps =
      s.file("c.psh", "ps_2_0\ndcl_cube s0\nmov r1, c0\ntexld r0, r1, s0\nmov oC0, r0\n");
  auto r = run_cli("run --ps " + ps + " --size 2x2 --texture s0=cube:" + faces);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("a cube texture has 6 faces, not 5"), std::string::npos) << r.err;
}

} // namespace
