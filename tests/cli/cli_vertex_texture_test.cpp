// `tierlift run --texture vs:sN=…`: the vertex stage's samplers (vs_3_0 texldl, NUMERICS.md
// F14), named as --const names a stage; sN without a prefix stays the pixel stage's.
#include <gtest/gtest.h>

#include "cli_test_util.h"
#include "temp_dir.h"
#include "tierlift/image/io.h"

using tierlift::test::run_cli;

namespace {

struct Scratch : tierlift::test::TempDir {
  Scratch() : TempDir("vertex_texture") {}
};

// Reads vertex sampler s1 at c0 (u, v, 0, lod) and hands the texel to the pixel stage.
constexpr const char* kVs = "vs_3_0\n"
                            "dcl_position v0\n"
                            "dcl_2d s1\n"
                            "dcl_position o0\n"
                            "dcl_texcoord0 o1\n"
                            "mov o0, v0\n"
                            "texldl r0, c0, s1\n"
                            "mov o1, r0\n";
constexpr const char* kPs = "ps_3_0\ndcl_texcoord0 v0\nmov oC0, v0\n";

// A 2 × 1 PFM: texel 0 = (0.25, 0.5, 0.75), texel 1 = (2, 4, 8) (alpha reads 1).
std::string two_texels(Scratch& s) {
  tierlift::img::Image im(2, 1, tierlift::img::Format::RGBA32F);
  im.rgba = {0.25f, 0.5f, 0.75f, 1, 2, 4, 8, 1};
  const std::string path = s.file("two.pfm");
  EXPECT_TRUE(tierlift::img::write_pfm(path, im).ok());
  return path;
}

TEST(RunVertexTexture, VsPrefixBindsTheVertexSampler) {
  Scratch s;
  const std::string tex = two_texels(s);
  const std::string base = "run --vs " + s.file("v.vsh", kVs) + " --ps " + s.file("p.psh", kPs) +
                           " --size 2x2 --format rgba32f --probe 1,1 --backend both";
  // POINT at u = 0.75: texel 1 on both devices.
  auto r = run_cli(base + " --texture vs:s1=" + tex + " --const vs:c0=0.75,0.5,0,0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1,1 (vulkan): 2 4 8 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1,1: 2 4 8 1"), std::string::npos) << r.out;
  // LINEAR at u = 0.5: halfway between the texel centres, their mean.
  r = run_cli(base + " --texture vs:s1=" + tex + " --const vs:c0=0.5,0.5,0,0 --filter linear");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1,1 (vulkan): 1.125 2.25 4.375 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1,1: 1.125 2.25 4.375 1"), std::string::npos) << r.out;
  // Without a prefix the texture goes to the pixel stage's s1: the vertex sampler stays
  // unbound, reads (0, 0, 0, 1), and the run says which flag was meant.
  r = run_cli(base + " --texture s1=" + tex + " --const vs:c0=0.75,0.5,0,0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1,1: 0 0 0 1"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("--texture vs:s1=..."), std::string::npos) << r.err;
}

TEST(RunVertexTexture, SamplersPastTheVertexStagesFourAreUsageErrors) {
  Scratch s;
  const std::string vs = s.file("v.vsh", kVs);
  auto r = run_cli("run --vs " + vs + " --texture vs:s4=builtin:noise --size 2x2");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("vs:sN=... (the vertex stage's samplers, N 0..3)"), std::string::npos)
      << r.err;
  r = run_cli("run --vs " + vs + " --texture ps:s16=builtin:noise --size 2x2");
  EXPECT_EQ(r.exit_code, 2) << r.err;
}

} // namespace
