// `tierlift run --output1..3`: a ps_2_0 listing writing oC1..oC3 draws each into a further
// render target (D3D9 MRT) on both devices; each is written to its own file, compared per
// target, and the values are the hand-computed ones.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "tierlift/image/io.h"

namespace {

namespace fs = std::filesystem;

class CliMrt : public tierlift::cli_test::CliFixture {
protected:
  // oC0 = c0, oC1 = t0·c1 (t0 the quad's uv), oC2 = c0 + c1.
  fs::path listing() {
    const fs::path p = dir / "mrt.psh";
    std::ofstream(p) << "ps_2_0\ndcl t0\nmov oC0, c0\nmul r0, t0, c1\nmov oC1, r0\n"
                        "add r1, c0, c1\nmov oC2, r1\n";
    return p;
  }
  std::string flags() {
    return "run --ps " + listing().string() +
           " --size 4x2 --const ps:c0=0.25,0.5,0.75,1 --const ps:c1=2,4,8,1 ";
  }
  // The RGB of pixel (x, y) of a PFM the run wrote.
  static std::array<float, 3> rgb(const fs::path& p, uint32_t x, uint32_t y) {
    tierlift::img::ImageResult im = tierlift::img::read_pfm(p.string());
    EXPECT_TRUE(im.ok()) << p;
    if (!im.ok()) return {};
    const float* v = im->at(x, y);
    return {v[0], v[1], v[2]};
  }
};

// Pixel (i, j) of a 4×2 target reads t0 = (i/4, j/2) with D3D9 pixel centres: oC1 at (1, 1)
// is (0.25·2, 0.5·4, 0·8) and at (3, 0) (0.75·2, 0, 0); oC2 is c0 + c1 everywhere.
TEST_F(CliMrt, EachTargetToItsOwnFileOnBothDevices) {
  const fs::path a = dir / "a.pfm", b = dir / "b.pfm", c = dir / "c.pfm";
  std::string out, err;
  ASSERT_EQ(run(flags() + "--backend both -o " + a.string() + " --output1 " + b.string() +
                    " --output2 " + c.string(),
                out, err),
            0)
      << err;
  EXPECT_NE(out.find("oC1: cpu vs vulkan: max abs per channel 0 0 0 0, identical pixels "
                     "100.00 %: within targets"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("oC2: cpu vs vulkan"), std::string::npos) << out;
  for (const char* suffix : {"", "-vulkan"}) {
    auto file = [&](const char* stem) { return dir / (std::string(stem) + suffix + ".pfm"); };
    EXPECT_EQ(rgb(file("a"), 2, 1), (std::array<float, 3>{0.25f, 0.5f, 0.75f})) << suffix;
    EXPECT_EQ(rgb(file("b"), 1, 1), (std::array<float, 3>{0.5f, 2.0f, 0.0f})) << suffix;
    EXPECT_EQ(rgb(file("b"), 3, 0), (std::array<float, 3>{1.5f, 0.0f, 0.0f})) << suffix;
    EXPECT_EQ(rgb(file("c"), 0, 0), (std::array<float, 3>{2.25f, 4.5f, 8.75f})) << suffix;
  }
}

// --json: the files, and one agreement per further target.
TEST_F(CliMrt, JsonNamesTheTargets) {
  const fs::path b = dir / "b.pfm";
  std::string out, err;
  ASSERT_EQ(run(flags() + "--json --backend both --output1 " + b.string(), out, err), 0) << err;
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j["result"]["more_outputs"], nlohmann::json::array({b.string()})) << out;
  ASSERT_EQ(j["result"]["agreement"]["more_targets"].size(), 1u) << out;
  EXPECT_EQ(j["result"]["agreement"]["more_targets"][0]["identical_share"], 1.0) << out;
}

// Targets are asked for in order; a target the listing does not write is refused before any
// file is written; two images into one file too.
TEST_F(CliMrt, RefusalsWriteNothing) {
  const fs::path a = dir / "a.png", d = dir / "d.png";
  std::string out, err;
  EXPECT_EQ(run(flags() + "--output2 " + d.string(), out, err), 2);
  EXPECT_NE(err.find("--output2 needs --output1 too"), std::string::npos) << err;
  EXPECT_EQ(run(flags() + "-o " + a.string() + " --output1 " + a.string(), out, err), 2);
  EXPECT_NE(err.find("two of the run's images would be written there"), std::string::npos) << err;
  EXPECT_EQ(run(flags() + "-o " + a.string() + " --output1 " + (dir / "b.png").string() +
                    " --output2 " + (dir / "c.png").string() + " --output3 " + d.string(),
                out, err),
            1);
  EXPECT_NE(err.find("render target 3 is asked for, but the pixel listing writes no oC3"),
            std::string::npos)
      << err;
  for (const char* f : {"a.png", "b.png", "c.png", "d.png"}) EXPECT_FALSE(fs::exists(dir / f)) << f;
}

// An output that cannot be written (its folder is missing) is an I/O error, exit 2, and
// leaves no temporary file behind.
TEST_F(CliMrt, UnwritableTargetFileIsAnIoError) {
  std::string out, err;
  EXPECT_EQ(run(flags() + "--output1 " + (dir / "no" / "b.png").string(), out, err), 2);
  EXPECT_NE(err.find("b.png"), std::string::npos) << err;
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

} // namespace
