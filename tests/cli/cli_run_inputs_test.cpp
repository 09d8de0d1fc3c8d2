// `tierlift run` without --vs: a pixel listing's t# are the quad's uv (not 0 everywhere), the
// run says what drives each input, and PNGs are opaque unless --keep-alpha.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli_test_util.h"
#include "temp_dir.h"
#include "tierlift/image/io.h"

using tierlift::test::run_cli;

namespace {

struct Scratch : tierlift::test::TempDir {
  Scratch() : TempDir("run_inputs") {}
};

constexpr const char* kShowT0 = "ps_2_0\ndcl t0\nmov oC0, t0\n";

TEST(RunInputs, TexcoordsDefaultToTheQuadUv) {
  Scratch s;
  const std::string ps = s.file("uv.psh", kShowT0);
  // Modern pixel centres: pixel (x, y) of a 4x2 target reads uv ((x + ½)/4, (y + ½)/2).
  auto r = run_cli("run --ps " + ps +
                   " --size 4x2 --format rgba32f --pixel-center modern --probe 3,1 --probe 0,0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3,1: 0.875 0.75 0 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0,0: 0.125 0.25 0 1"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("note: t0: quad uv (no --vs)"), std::string::npos) << r.err;
  // --input still sets it, the same at every pixel.
  r = run_cli("run --ps " + ps +
              " --size 4x2 --format rgba32f --probe 3,1 --input t0=0.5,0.25,0,1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3,1: 0.5 0.25 0 1"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("note: t0: 0.5,0.25,0,1 everywhere (--input t0=0.5,0.25,0,1)"),
            std::string::npos)
      << r.err;
}

TEST(RunInputs, VulkanDrawsTheSameUv) {
  Scratch s;
  const std::string ps = s.file("uv.psh", kShowT0);
  auto r = run_cli("run --ps " + ps +
                   " --size 4x2 --format rgba32f --pixel-center modern --probe 3,1 --backend both");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3,1 (vulkan): 0.875 0.75 0 1"), std::string::npos) << r.out;
}

TEST(RunInputs, JsonNamesEachInput) {
  Scratch s;
  const std::string ps = s.file("v.psh", "ps_2_0\ndcl v0\ndcl t1\nadd r0, v0, t1\nmov oC0, r0\n");
  auto r = run_cli("run --ps " + ps + " --size 2x2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  nlohmann::json inputs = nlohmann::json::parse(r.out)["result"]["inputs"];
  EXPECT_EQ(inputs["t1"], "quad uv (no --vs)");
  EXPECT_EQ(inputs["v0"], "0 everywhere (no --vs; --input v0=x,y,z,w sets it)");
  EXPECT_EQ(r.err, ""); // the notes are in the document, not on standard error
}

TEST(RunInputs, PngIsOpaqueUnlessKeepAlpha) {
  Scratch s;
  const std::string ps = s.file("a.psh", "ps_2_0\ndef c0, 1, 0.5, 0, 0\nmov oC0, c0\n");
  ASSERT_EQ(
      run_cli("run --ps " + ps + " --size 2x2 --format rgba8 -o " + s.file("o.png")).exit_code, 0);
  tierlift::img::ImageResult opaque = tierlift::img::read_png(s.file("o.png"));
  ASSERT_TRUE(opaque) << opaque.message();
  EXPECT_EQ(opaque->at(1, 1)[0], 1.0f);
  EXPECT_EQ(opaque->at(1, 1)[3], 1.0f);
  ASSERT_EQ(
      run_cli("run --ps " + ps + " --size 2x2 --format rgba8 --keep-alpha -o " + s.file("k.png"))
          .exit_code,
      0);
  tierlift::img::ImageResult kept = tierlift::img::read_png(s.file("k.png"));
  ASSERT_TRUE(kept) << kept.message();
  EXPECT_EQ(kept->at(1, 1)[0], 1.0f);
  EXPECT_EQ(kept->at(1, 1)[3], 0.0f);
}

} // namespace

namespace {

// A little-endian RGB PFM, one row; `rgb` holds 3 floats a pixel.
void write_pfm(const std::string& path, const std::vector<float>& rgb) {
  std::ofstream out(path, std::ios::binary);
  out << "PF\n" << rgb.size() / 3 << " 1\n-1.0\n";
  out.write(reinterpret_cast<const char*>(rgb.data()),
            static_cast<std::streamsize>(rgb.size() * sizeof(float)));
}

// texbem t1, t0 offsets stage 1's coordinate by M·(t0.r, t0.g): u' = u + M00·du + M10·dv.
TEST(RunInputs, BumpMatrixOffsetsTexbem) {
  Scratch s;
  const std::string ps = s.file("bem.psh", "ps_1_1\ntex t0\ntexbem t1, t0\nmov r0, t1\n");
  const std::string bump = s.file("bump.pfm"), image = s.file("lr.pfm");
  write_pfm(bump, {0.5f, 0.25f, 0.0f});                   // du = 0.5, dv = 0.25
  write_pfm(image, {0.1f, 0.1f, 0.1f, 0.9f, 0.9f, 0.9f}); // left 0.1, right 0.9
  const std::string common = " --size 2x1 --format rgba32f --pixel-center modern --address "
                             "clamp --probe 0,0 --texture s0=" +
                             bump + " --texture s1=" + image;
  // Pixel 0 reads uv (0.25, 0.5): no matrix, the left texel.
  auto r = run_cli("run --ps " + ps + common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0,0: 0.1 0.1 0.1 1"), std::string::npos) << r.out;
  // M00 = 1: u' = 0.25 + 0.5 = 0.75, the right texel; on Vulkan too.
  r = run_cli("run --ps " + ps + common + " --bump-matrix 1=1,0,0,0 --backend both");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0,0: 0.9 0.9 0.9 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0,0 (vulkan): 0.9 0.9 0.9 1"), std::string::npos) << r.out;
  // M10 = 2: u' = 0.25 + 2 · 0.25 = 0.75, the right texel.
  r = run_cli("run --ps " + ps + common + " --bump-matrix 1=0,0,2,0");
  EXPECT_NE(r.out.find("0,0: 0.9 0.9 0.9 1"), std::string::npos) << r.out;
  EXPECT_EQ(run_cli("run --ps " + ps + common + " --bump-matrix 9=1,0,0,0").exit_code, 2);
  EXPECT_EQ(run_cli("run --ps " + ps + common + " --bump-matrix 1=1,0,0").exit_code, 2);
}

} // namespace
