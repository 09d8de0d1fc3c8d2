// `tierlift glow` end to end on the CPU device: files written, JSON summary, usage errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_fixture.h"
#include "skip_policy.h"

namespace {

namespace fs = std::filesystem;

class CliGlow : public tierlift::cli_test::CliFixture {};

TEST_F(CliGlow, CpuRunWritesTheThreeImages) {
  const fs::path log = dir / "log.txt";
  ASSERT_EQ(run_cli("glow --backend cpu --downsample 4 --json -o " + (dir / "out").string(), log),
            0)
      << read(log);
  // RGBA32F (the default): PNG and PFM of each image.
  for (const char* f : {"scene-cpu", "glow-cpu", "final-cpu"})
    for (const char* ext : {".png", ".pfm"})
      EXPECT_TRUE(fs::exists(dir / "out" / (std::string(f) + ext))) << f << ext;
  EXPECT_FALSE(fs::exists(dir / "out" / "final-vulkan.png"));
  EXPECT_FALSE(fs::exists(dir / "out" / "final-analytic.png"));
  const std::string text = read(log);
  // 1280×720 / 4 = 320×180; the default σ 16 px / 4 → R = ceil(3 · 4) = 12, 25 taps → 4
  // dx9 passes of 8 an axis; a 4×4 block takes 4 downsample passes of 4 point reads:
  // 1 + 4 + 4 + 4 + 1 passes.
  EXPECT_NE(text.find("\"taps\": 25"), std::string::npos) << text;
  EXPECT_NE(text.find("\"passes\": 14"), std::string::npos) << text;
  EXPECT_NE(text.find("\"width\": 320"), std::string::npos) << text;
  EXPECT_NE(text.find("\"tier\": \"dx9\""), std::string::npos) << text;
}

TEST_F(CliGlow, BadFlagsAreUsageErrors) {
  const fs::path log = dir / "log.txt";
  EXPECT_EQ(run_cli("glow --downsample 5", log), 2) << read(log);
  EXPECT_EQ(run_cli("glow --format rgba4", log), 2) << read(log);
  EXPECT_EQ(run_cli("glow --tier dx6", log), 2) << read(log);
  EXPECT_EQ(run_cli("glow --backend gpu", log), 2) << read(log);
  EXPECT_EQ(run_cli("glow --scene a.json --image b.png", log), 2) << read(log);
}

TEST_F(CliGlow, MissingSceneFileIsAnErrorAndWritesNothing) {
  const fs::path log = dir / "log.txt";
  EXPECT_EQ(
      run_cli("glow --scene " + (dir / "nope.json").string() + " -o " + (dir / "out").string(),
              log),
      2) // an unreadable file named on the command line is an I/O error, as in every command
      << read(log);
  EXPECT_NE(read(log).find("nope.json"), std::string::npos) << read(log);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A small scene file, every way, both tiers: exit 0 (every pair within the targets) and the
// nine images; the same scene with a bad field: exit 1, a positioned error, nothing written.
TEST_F(CliGlow, SceneFileThreeWaysBothTiers) {
  const fs::path scene = dir / "small.json";
  std::ofstream(scene) << R"({"size": [96, 54], "glow": {"downsample": 2, "format": "rgba8"}})";
  for (const char* tier : {"dx9", "dx8"}) {
    const fs::path log = dir / "log.txt", out = dir / tier;
    const int code = run_cli("glow -q --tier " + std::string(tier) + " --scene " + scene.string() +
                                 " -o " + out.string(),
                             log);
    // "every way" includes lavapipe: only a machine without any Vulkan device may skip.
    if (code == 2 && read(log).find("no Vulkan device found") != std::string::npos)
      TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, read(log));
    ASSERT_EQ(code, 0) << read(log);
    const std::string text = read(log);
    EXPECT_NE(text.find("every pair within design.md's targets"), std::string::npos) << text;
    EXPECT_NE(text.find("glow " + std::string(tier) + ": 96x54 rgba8"), std::string::npos) << text;
    for (const char* way : {"cpu", "vulkan", "analytic"})
      for (const char* image : {"scene", "glow", "final"})
        EXPECT_TRUE(fs::exists(out / (std::string(image) + "-" + way + ".png"))) << way << image;
    EXPECT_FALSE(fs::exists(out / "final-cpu.pfm")); // RGBA8: PNG only
  }
}

TEST_F(CliGlow, BadSceneFieldExitsOneAndWritesNothing) {
  const std::string text = glow_refuses_scene("{\n  \"glow\": { \"downsample\": 9 }\n}\n");
  // Line 2, column 27: two spaces, "glow": { "downsample": and a space, then the 9.
  EXPECT_NE(text.find("bad.json:2:27: error: /glow/downsample: 9 is outside 1..4"),
            std::string::npos)
      << text;
}

TEST_F(CliGlow, PngSceneRunsWithDefaultParameters) {
  const fs::path png = fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "scenes" / "sign.png";
  const fs::path log = dir / "log.txt";
  ASSERT_EQ(run_cli("glow -q --json --backend analytic --image " + png.string(), log), 0)
      << read(log);
  const std::string text = read(log);
  EXPECT_NE(text.find("\"width\": 160"), std::string::npos) << text;
  EXPECT_NE(text.find("\"height\": 96"), std::string::npos) << text;
}

} // namespace
