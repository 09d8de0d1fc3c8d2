// `tierlift run --depth-*` (NUMERICS.md D1-D5): a ps_2_0 writing oDepth against a depth buffer
// read from a .pfm, on both devices, the depth buffer written out and compared bit for bit;
// and the flags' errors (exit 2, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_fixture.h"
#include "tierlift/image/io.h"

namespace {

namespace fs = std::filesystem;
using tierlift::img::Image;

class RunDepth : public tierlift::cli_test::CliFixture {
protected:
  // oDepth = u (the quad's u: i/4 at column i of a 4x1 target), colour 1.
  fs::path ramp_listing() {
    const fs::path p = dir / "z.psh";
    std::ofstream(p) << "ps_2_0\ndef c1, 1, 1, 1, 1\ndcl t0.xy\nmov oC0, c1\nmov oDepth, t0.x\n";
    return p;
  }
  // A 4x1 depth image holding 0.6 everywhere but 0.25 at column 1.
  fs::path depth_in() {
    Image im(4, 1);
    for (uint32_t x = 0; x < 4; ++x) im.at(x, 0)[0] = x == 1 ? 0.25f : 0.6f;
    const fs::path p = dir / "in.pfm";
    EXPECT_TRUE(tierlift::img::write_pfm(p.string(), im).ok());
    return p;
  }
  std::string base() {
    return "run --ps " + ramp_listing().string() + " --size 4x1 --backend both";
  }
};

// Pixel i brings i/4 = 0, 0.25, 0.5, 0.75 against 0.6, 0.25, 0.6, 0.6 under LESS: columns 0
// and 2 pass (0 < 0.6, 0.5 < 0.6); column 1 ties (0.25 < 0.25 is false), column 3 is farther.
// The buffer becomes 0, 0.25, 0.5, 0.6 and the colour 1, 0, 1, 0, on both devices.
TEST_F(RunDepth, LessAgainstADepthImageOnBothDevices) {
  std::string out, err;
  const fs::path z = dir / "z.pfm";
  ASSERT_EQ(run(base() + " --depth-in " + depth_in().string() + " --depth-func less --depth-out " +
                    z.string() + " --probe 0,0 --probe 1,0 --probe 2,0 --probe 3,0",
                out, err),
            0)
      << err;
  EXPECT_NE(out.find("0,0: 1 1 1 1"), std::string::npos) << out;
  EXPECT_NE(out.find("1,0: 0 0 0 0"), std::string::npos) << out;
  EXPECT_NE(out.find("2,0: 1 1 1 1"), std::string::npos) << out;
  EXPECT_NE(out.find("3,0: 0 0 0 0"), std::string::npos) << out;
  EXPECT_NE(out.find("depth: cpu vs vulkan: max abs 0, identical pixels 100.00 %: bit for bit"),
            std::string::npos)
      << out;
  for (const fs::path& p : {z, dir / "z-vulkan.pfm"}) {
    tierlift::img::ImageResult read = tierlift::img::read_pfm(p.string());
    ASSERT_TRUE(read.ok()) << p << ": " << read.message();
    const float expected[] = {0.0f, 0.25f, 0.5f, 0.6f};
    for (uint32_t x = 0; x < 4; ++x) EXPECT_EQ(read->at(x, 0)[0], expected[x]) << p << " " << x;
  }
}

// --depth-write off: the colour as before, the buffer keeps its clear value; --json carries
// the state and the agreement.
TEST_F(RunDepth, WriteOffKeepsTheClearValue) {
  std::string out, err;
  const fs::path z = dir / "z.pfm";
  ASSERT_EQ(run(base() + " --depth-clear 0.5 --depth-write off --depth-out " + z.string() +
                    " --probe 1,0 --probe 2,0 --json",
                out, err),
            0)
      << err;
  EXPECT_NE(out.find("\"func\": \"lessequal\""), std::string::npos) << out;
  EXPECT_NE(out.find("\"write\": false"), std::string::npos) << out;
  EXPECT_NE(out.find("\"bit_identical\": true"), std::string::npos) << out;
  tierlift::img::ImageResult read = tierlift::img::read_pfm(z.string());
  ASSERT_TRUE(read.ok()) << read.message();
  for (uint32_t x = 0; x < 4; ++x) EXPECT_EQ(read->at(x, 0)[0], 0.5f) << x;
}

// Every bad value is a usage error (exit 2) and writes nothing.
TEST_F(RunDepth, BadValuesAreUsageErrors) {
  const fs::path z = dir / "z.pfm";
  Image wrong(3, 1);
  const fs::path small = dir / "small.pfm";
  ASSERT_TRUE(tierlift::img::write_pfm(small.string(), wrong).ok());
  Image far(4, 1);
  far.at(2, 0)[0] = 1.5f;
  const fs::path beyond = dir / "beyond.pfm";
  ASSERT_TRUE(tierlift::img::write_pfm(beyond.string(), far).ok());
  const std::pair<std::string, std::string> cases[] = {
      {" --depth-func sometimes", "--depth-func 'sometimes'"},
      {" --depth-write maybe", "--depth-write 'maybe'"},
      {" --depth-clear 1.5", "--depth-clear '1.5'"},
      {" --depth-clear nan", "--depth-clear 'nan'"},
      {" --depth-clear x", "--depth-clear 'x'"},
      {" --depth-in " + small.string(), "the image is 3x1, the target 4x1"},
      {" --depth-in " + beyond.string(), "pixel 2,0 holds 1.5"},
      {" --depth-in " + (dir / "none.pfm").string(), "error"},
      {" --depth-out " + (dir / "z.png").string(), "--depth-out takes a .pfm"},
      {" --depth-clear 0.5 --depth-in " + depth_in().string(), "give one"},
  };
  for (const auto& [flags, message] : cases) {
    std::string out, err;
    EXPECT_EQ(run(base() + flags + " -o " + z.string(), out, err), 2) << flags << "\n" << err;
    EXPECT_NE(err.find("error:"), std::string::npos) << flags << "\n" << err;
    EXPECT_NE(err.find(message), std::string::npos) << flags << "\n" << err;
    EXPECT_FALSE(fs::exists(z)) << flags;
  }
}

// The depth image may not be written over the image it starts from.
TEST_F(RunDepth, DepthOutNeverReplacesDepthIn) {
  std::string out, err;
  const fs::path in = depth_in();
  EXPECT_EQ(run(base() + " --depth-in " + in.string() + " --depth-out " + in.string(), out, err), 2)
      << err;
  EXPECT_NE(err.find("error:"), std::string::npos) << err;
  tierlift::img::ImageResult read = tierlift::img::read_pfm(in.string());
  ASSERT_TRUE(read.ok());
  EXPECT_EQ(read->at(1, 0)[0], 0.25f);
}

} // namespace
