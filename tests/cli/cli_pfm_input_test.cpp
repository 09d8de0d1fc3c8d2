// PFM as the glow's input image (`tierlift glow --image F.pfm`, a scene's "image"): HDR values
// flow through the float formats, and a bad header is a positioned error with the header line
// and a caret under the bad token, exit 1, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_fixture.h"
#include "tierlift/image/io.h"

namespace {

namespace fs = std::filesystem;
using tierlift::img::Image;

class CliPfmInput : public tierlift::cli_test::CliFixture {
protected:
  // A 24×16 black image with one texel of value v (PFM has no alpha: it reads 1, so every
  // texel is a glow source and the black ones add 0).
  fs::path one_texel(const std::string& name, float v) {
    Image im(24, 16);
    for (size_t i = 3; i < im.rgba.size(); i += 4) im.rgba[i] = 1;
    float* p = im.at(11, 7);
    p[0] = p[1] = p[2] = v;
    const std::vector<uint8_t> bytes = tierlift::img::encode_pfm(im);
    const fs::path path = dir / name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
  }
  Image run_effect(const fs::path& input, const std::string& out_name) {
    std::string out, err;
    const fs::path o = dir / out_name;
    EXPECT_EQ(
        run("glow -q --backend all --downsample 1 --image " + input.string() + " -o " + o.string(),
            out, err),
        0)
        << err;
    EXPECT_NE(out.find("every pair within design.md's targets"), std::string::npos) << out;
    tierlift::img::ImageResult glow = tierlift::img::read_pfm((o / "glow-cpu.pfm").string());
    EXPECT_TRUE(glow) << glow.message();
    return glow ? *glow : Image();
  }
};

// A 6e4 texel (near the top of half floats) gives 6e4 times the glow of a 1.0 texel, on all
// three ways (the agreement above includes the double-precision analytic model): the glow is
// linear in its sources, with nothing clamped to 1 on the way.
TEST_F(CliPfmInput, HdrTexelGivesAProportionalGlow) {
  const Image unit = run_effect(one_texel("unit.pfm", 1.0f), "unit");
  const Image hdr = run_effect(one_texel("hdr.pfm", 6e4f), "hdr");
  ASSERT_EQ(unit.rgba.size(), hdr.rgba.size());
  ASSERT_FALSE(unit.rgba.empty());
  double peak = 0;
  for (size_t i = 0; i < unit.rgba.size(); i += 4) {
    peak = std::max(peak, double(hdr.rgba[i]));
    // fp32 sums of a few dozen products: relative error well below 1e-5.
    EXPECT_NEAR(hdr.rgba[i], 6e4 * unit.rgba[i], 1e-5 * 6e4 * (unit.rgba[i] + 1e-6)) << i / 4;
  }
  EXPECT_GT(peak, 1.0); // far above what an 8-bit image could hold
}

TEST_F(CliPfmInput, BadHeaderIsPositionedAndWritesNothing) {
  struct Bad {
    const char* bytes;
    const char* says;
  };
  const Bad bads[] = {
      {"PF\n3x 2\n-1.0\n", "bad.pfm:2:1: error: PFM header: bad width '3x'\n    3x 2\n    ^~\n"},
      {"PF\n3 2\n0\n", "bad.pfm:3:1: error: PFM header: bad scale '0'"},
      {"PF\n3 0\n-1\n", "bad.pfm:2:3: error: PFM header: zero width or height\n    3 0\n      ^\n"},
      {"PF\n3 2\n-1.0\nabc", "bad.pfm: error: PFM raster truncated: 3 bytes, 72 needed"},
  };
  for (const Bad& b : bads) {
    const fs::path path = dir / "bad.pfm", o = dir / "out";
    std::ofstream(path, std::ios::binary) << b.bytes;
    std::string out, err;
    EXPECT_EQ(run("glow -q --backend cpu --image " + path.string() + " -o " + o.string(), out, err),
              1)
        << err;
    // The message names the file as given on the command line.
    std::string shown = err;
    for (size_t at; (at = shown.find(path.string())) != std::string::npos;)
      shown.replace(at, path.string().size(), "bad.pfm");
    EXPECT_NE(shown.find(b.says), std::string::npos) << shown;
    EXPECT_FALSE(fs::exists(o));
  }
}

} // namespace
