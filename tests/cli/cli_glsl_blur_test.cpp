// `tierlift glow --scene listings/scenes/glsl-blur.json`: the GLSL blur end to end on all
// three ways, and a scene whose GLSL does not compile.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_fixture.h"
#include "skip_policy.h"

namespace {
namespace fs = std::filesystem;

const std::string kScene = std::string(TIERLIFT_SOURCE_DIR) + "/listings/scenes/glsl-blur.json";

class CliGlslBlur : public tierlift::cli_test::CliFixture {};

TEST_F(CliGlslBlur, AllThreeWaysAgree) {
  const fs::path log = dir / "log.txt";
  const int rc =
      run_cli("glow -q --scene " + kScene + " --backend all -o " + (dir / "out").string(), log);
  const std::string text = read(log);
  if (rc == 2 && text.find("device") != std::string::npos)
    TIERLIFT_SKIP_UNLESS_REQUIRED(tierlift::test::kRequireVulkan, "no Vulkan device: " + text);
  ASSERT_EQ(rc, 0) << text;
  EXPECT_NE(text.find("glsl-blur: 512x512 rgba32f, 9 taps per axis, 2 GLSL passes"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("kernel weights sum to 0.98"), std::string::npos) << text;
  EXPECT_NE(text.find("every pair within design.md's targets"), std::string::npos) << text;
  expect_each_way(dir / "out", "final-");
}

TEST_F(CliGlslBlur, BadGlslIsPositionedInTheGlslFileAndNothingIsWritten) {
  std::ofstream(dir / "bad.frag") << "varying vec2 vTexCoord;\nvoid main(void)\n{\n"
                                     "  gl_FragColor = texture2D(RTScene, vTexCoord);\n}\n";
  const std::string text = glow_refuses_scene(
      R"({"effect": "glsl-blur", "size": [512, 512], "glsl": {"horizontal": "bad.frag"}})",
      "--backend cpu ");
  // "  gl_FragColor = texture2D(" is 27 characters: RTScene starts at column 28 of line 4.
  EXPECT_NE(
      text.find((dir / "bad.frag").string() + ":4:28: error: 'RTScene': undeclared identifier"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find("                           ^~~~~~~"), std::string::npos) << text;
}

TEST_F(CliGlslBlur, GlslObjectUnderTheGlowIsAPositionedSceneError) {
  std::ofstream(dir / "mixed.json") << "{\n  \"glsl\": {}\n}\n";
  const fs::path log = dir / "log.txt";
  EXPECT_EQ(run_cli("glow --backend cpu --scene " + (dir / "mixed.json").string(), log), 1);
  EXPECT_NE(
      read(log).find("mixed.json:2:3: error: /glsl: \"glsl\" configures \"effect\": \"glsl-blur\""),
      std::string::npos)
      << read(log);
}

} // namespace
