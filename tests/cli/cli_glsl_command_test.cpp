// `tierlift glsl FILE`: a user's GLSL fragment shader compiled, checked, listed and drawn on
// the Vulkan device. The drawn values are checked against what the shader computes, worked
// out here by hand (pixel centres, the seed's weights), never against an earlier output.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_fixture.h"
#include "skip_policy.h"
#include "tierlift/effects/glow/glsl_blur.h"
#include "tierlift/image/io.h"

namespace {
namespace fs = std::filesystem;
using tierlift::img::Image;

const std::string kSeedH = std::string(TIERLIFT_SOURCE_DIR) + "/listings/glsl/seed004_blur_h.frag";

class CliGlslCommand : public tierlift::cli_test::CliFixture {
protected:
  // Runs `tierlift glsl ARGS`; skips (unless Vulkan is required) when no device opens.
  int glsl(const std::string& args, std::string& text) {
    const fs::path log = dir / "log.txt";
    const int rc = run_cli("glsl " + args, log);
    text = read(log);
    return rc;
  }
  bool no_device(int rc, const std::string& text) {
    return rc == 2 && text.find("device") != std::string::npos;
  }
  // A PNG of w × h: black but for `bright` at (bx, by) (alpha 1 everywhere).
  fs::path png(uint32_t w, uint32_t h, uint32_t bx, uint32_t by, float bright, float blue_step) {
    Image im(w, h, tierlift::img::Format::RGBA8);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        float* px = im.at(x, y);
        const bool b = x == bx && y == by;
        px[0] = px[1] = b ? bright : 0.0f;
        px[2] = float((x + y) % 5) * blue_step;
        px[3] = 1;
      }
    const fs::path p = dir / "in.png";
    EXPECT_TRUE(tierlift::img::write_png(p.string(), im).ok());
    return p;
  }
};

TEST_F(CliGlslCommand, ListsTheSeedShadersInterface) {
  std::string text;
  ASSERT_EQ(glsl(kSeedH, text), 0) << text;
  EXPECT_NE(text.find("valid for Vulkan 1.1 (spirv-val)"), std::string::npos) << text;
  EXPECT_NE(text.find("sampler RTScene: stage s0 (binding 2)"), std::string::npos) << text;
  EXPECT_NE(text.find("input vTexCoord: location 0"), std::string::npos) << text;
  ASSERT_EQ(glsl("--json " + kSeedH, text), 0) << text;
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["result"]["samplers"][0]["name"], "RTScene");
  EXPECT_EQ(j["result"]["inputs"][0]["location"], 0);
}

// vTexCoord on texel centres and a point read of the input: out = ((x + ½)/w, (y + ½)/h, the
// input's blue at that texel, 1), which the test computes itself.
TEST_F(CliGlslCommand, DrawsWhatTheShaderComputesAtEveryPixel) {
  std::ofstream(dir / "uv.frag") << "#version 110\nvarying vec2 vTexCoord;\n"
                                    "uniform sampler2D tex;\nvoid main() {\n"
                                    "  vec4 c = texture2D(tex, vTexCoord);\n"
                                    "  gl_FragColor = vec4(vTexCoord, c.b, 1.0);\n}\n";
  const uint32_t w = 12, h = 7;
  const fs::path in = png(w, h, 0, 0, 0, 51.0f / 255);
  const fs::path out = dir / "out.pfm";
  std::string text;
  const int rc = glsl((dir / "uv.frag").string() + " --image " + in.string() + " -o " +
                          out.string() + " --spirv " + (dir / "uv.spv").string(),
                      text);
  if (no_device(rc, text))
    TIERLIFT_SKIP_UNLESS_REQUIRED(tierlift::test::kRequireVulkan, "no Vulkan device: " + text);
  ASSERT_EQ(rc, 0) << text;
  EXPECT_EQ(fs::file_size(dir / "uv.spv") % 4, 0u);
  auto got = tierlift::img::read_image(out.string());
  ASSERT_TRUE(got) << got.message();
  ASSERT_EQ(got->width, w);
  ASSERT_EQ(got->height, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      // (x + ½)/w in fp32 interpolation: within a few ulps of 1.
      EXPECT_NEAR(got->at(x, y)[0], (x + 0.5) / w, 1e-6) << x << "," << y;
      EXPECT_NEAR(got->at(x, y)[1], (y + 0.5) / h, 1e-6) << x << "," << y;
      EXPECT_NEAR(got->at(x, y)[2], double((x + y) % 5) * 51 / 255, 1e-6) << x << "," << y;
    }
}

// The seed's horizontal blur over one white texel at the seed's 512 texels: the row through
// it holds the seed's nine weights (typed in by hand in glsl_blur.h), every other row 0.
TEST_F(CliGlslCommand, SeedBlurOfOneTexelGivesTheSeedsWeights) {
  const uint32_t w = 512, h = 3, bx = 200, by = 1;
  const fs::path in = png(w, h, bx, by, 1, 0);
  const fs::path out = dir / "out.pfm";
  std::string text;
  const int rc = glsl(kSeedH + " --image " + in.string() + " -o " + out.string(), text);
  if (no_device(rc, text))
    TIERLIFT_SKIP_UNLESS_REQUIRED(tierlift::test::kRequireVulkan, "no Vulkan device: " + text);
  ASSERT_EQ(rc, 0) << text;
  auto got = tierlift::img::read_image(out.string());
  ASSERT_TRUE(got) << got.message();
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const int k = int(x) - int(bx);
      const double want =
          y == by && k >= -4 && k <= 4 ? tierlift::effects::kSeedBlurWeights[k + 4] : 0.0;
      EXPECT_NEAR(got->at(x, y)[0], want, 1e-7) << x << "," << y;
    }
}

TEST_F(CliGlslCommand, BadGlslIsPositionedAndNothingIsWritten) {
  std::ofstream(dir / "bad.frag") << "varying vec2 vTexCoord;\nvoid main(void)\n{\n"
                                     "  gl_FragColor = texture2D(RTScene, vTexCoord);\n}\n";
  std::string text;
  const std::string bad = (dir / "bad.frag").string();
  EXPECT_EQ(
      glsl(bad + " -o " + (dir / "o.png").string() + " --spirv " + (dir / "o.spv").string(), text),
      1)
      << text;
  EXPECT_NE(text.find(bad + ":4:28: error: 'RTScene'"), std::string::npos) << text;
  EXPECT_NE(text.find("                           ^"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
  EXPECT_FALSE(fs::exists(dir / "o.spv"));
}

TEST_F(CliGlslCommand, RefusesWhatThePassCannotFeed) {
  // The quad writes texture coordinates at locations 0..3 only.
  std::ofstream(dir / "loc5.frag")
      << "layout(location = 5) in vec4 far;\nvoid main() { gl_FragColor = far; }\n";
  std::string text;
  EXPECT_EQ(glsl((dir / "loc5.frag").string() + " -o " + (dir / "o.png").string(), text), 1)
      << text;
  EXPECT_NE(text.find("input 'far' is at location 5"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

// A Vulkan GLSL source with its own output at location 0 passes through as it is.
TEST_F(CliGlslCommand, VulkanGlslWithItsOwnOutput) {
  std::ofstream(dir / "own.frag") << "#version 450\nlayout(location = 0) in vec4 uv;\n"
                                     "layout(location = 0) out vec4 o;\n"
                                     "void main() { o = vec4(uv.y, uv.x, 0.25, 1.0); }\n";
  const fs::path out = dir / "own.pfm";
  std::string text;
  const int rc = glsl((dir / "own.frag").string() + " --size 4x2 -o " + out.string(), text);
  if (no_device(rc, text))
    TIERLIFT_SKIP_UNLESS_REQUIRED(tierlift::test::kRequireVulkan, "no Vulkan device: " + text);
  ASSERT_EQ(rc, 0) << text;
  auto got = tierlift::img::read_image(out.string());
  ASSERT_TRUE(got) << got.message();
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      EXPECT_NEAR(got->at(x, y)[0], (y + 0.5) / 2, 1e-6);
      EXPECT_NEAR(got->at(x, y)[1], (x + 0.5) / 4, 1e-6);
      EXPECT_NEAR(got->at(x, y)[2], 0.25, 1e-7);
    }
}

TEST_F(CliGlslCommand, UsageAndIoErrors) {
  std::string text;
  // Never over its own input.
  EXPECT_EQ(glsl(kSeedH + " -o " + kSeedH, text), 2) << text;
  EXPECT_NE(text.find("refusing to write over an input file"), std::string::npos) << text;
  EXPECT_EQ(glsl((dir / "missing.frag").string(), text), 2) << text;
  EXPECT_EQ(glsl(kSeedH + " --format rgb9", text), 2) << text;
  EXPECT_EQ(glsl(kSeedH + " --size 0x4", text), 2) << text;
  EXPECT_EQ(
      glsl(kSeedH + " --image " + (dir / "none.png").string() + " -o " + (dir / "o.png").string(),
           text),
      2)
      << text;
  EXPECT_FALSE(fs::exists(dir / "o.png"));
}

} // namespace
