// `tierlift run --srgb-texture` and `--srgb-write` (NUMERICS.md S1–S3): a PNG texture's bytes
// decoded to linear before filtering, the colour encoded to sRGB on an rgba8 target, the same
// on both devices, with the closed form's values.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_fixture.h"
#include "tierlift/image/io.h"

namespace {

namespace fs = std::filesystem;

class RunSrgb : public tierlift::cli_test::CliFixture {
protected:
  // A 2×1 PNG: texel 0 holds byte 128 in red, 64 in green, 255 in blue, alpha 128; texel 1 is
  // black, alpha 255.
  fs::path texture() {
    tierlift::img::Image im(2, 1, tierlift::img::Format::RGBA8);
    im.rgba = {128 / 255.0f, 64 / 255.0f, 1.0f, 128 / 255.0f, 0, 0, 0, 1};
    const fs::path p = dir / "t.png";
    EXPECT_TRUE(tierlift::img::write_png(p.string(), im, tierlift::img::PngDepth::Bits8).ok());
    return p;
  }
  fs::path listing() {
    const fs::path p = dir / "s.psh";
    std::ofstream(p) << "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n";
    return p;
  }
};

// Byte 128 reads ((128/255 + 0.055)/1.055)^2.4 = 0.2158605, byte 64 0.05126946; alpha stays
// 128/255 = 0.5019608. Pixel 0 of a 2×1 target reads texel 0 (point sampling, D3D9 centres).
TEST_F(RunSrgb, TextureDecodesOnBothDevices) {
  std::string out, err;
  ASSERT_EQ(run("run --ps " + listing().string() + " --texture s0=" + texture().string() +
                    " --size 2x1 --srgb-texture --probe 0,0 --backend both",
                out, err),
            0)
      << err;
  EXPECT_NE(out.find("0,0: 0.2158605 0.051269457 1 0.5019608"), std::string::npos) << out;
  EXPECT_NE(out.find("0,0 (vulkan): 0.2158605 0.051269457 1 0.5019608"), std::string::npos) << out;
  EXPECT_NE(out.find("identical pixels 100.00 %"), std::string::npos) << out;
}

// Decoded and encoded again into an rgba8 target: the bytes come back (128, 64, 255), alpha
// untouched; without --srgb-write the linear value is stored (0.2158605 → byte 55).
TEST_F(RunSrgb, WriteEncodesOnAnRgba8Target) {
  std::string out, err;
  const std::string base = "run --ps " + listing().string() +
                           " --texture s0=" + texture().string() +
                           " --size 2x1 --format rgba8 --srgb-texture --probe 0,0 --backend both";
  ASSERT_EQ(run(base + " --srgb-write", out, err), 0) << err;
  EXPECT_NE(out.find("0,0: 0.5019608 0.2509804 1 0.5019608"), std::string::npos) << out;
  EXPECT_NE(out.find("0,0 (vulkan): 0.5019608 0.2509804 1 0.5019608"), std::string::npos) << out;
  ASSERT_EQ(run(base, out, err), 0) << err;
  EXPECT_NE(out.find("0,0: 0.21568628 0.050980393 1 0.5019608"), std::string::npos) << out;
}

} // namespace
