// `tierlift glow` on tier dx7 end to end: the weight-quantisation statement, the choice of
// rounding by flag, and a bad texture-stage-state file named by a scene (positioned error,
// exit 1, nothing written).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_fixture.h"

namespace {

namespace fs = std::filesystem;

class CliDx7 : public tierlift::cli_test::CliFixture {};

TEST_F(CliDx7, StatesTheQuantisationErrorOfEachRounding) {
  const fs::path log = dir / "log.txt";
  // The profile σ 8 (0.7) + σ 1.5 (0.3) at N = 4: 13 taps; their bytes sum to 258 rounded
  // plainly, 255 carried (independent figures: tests/effects/dx7_test.cpp's arithmetic,
  // printed by the tool).
  const fs::path scene = dir / "dx7.json";
  std::ofstream(scene) << R"({"glow": {"tier": "dx7", "downsample": 4, "profile": {"gaussians":
    [{"sigma": 8, "weight": 0.7}, {"sigma": 1.5, "weight": 0.3}]}}})";
  const std::string args = "glow --scene " + scene.string() + " --backend cpu -q";
  ASSERT_EQ(run_cli(args + " --weight-rounding plain", log), 0) << read(log);
  std::string text = read(log);
  EXPECT_NE(text.find("glow dx7:"), std::string::npos) << text;
  EXPECT_NE(text.find("weight rounding plain: sum of 8-bit weights 258/255 per axis"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("brighter"), std::string::npos) << text;
  ASSERT_EQ(run_cli(args, log), 0) << read(log);
  text = read(log);
  EXPECT_NE(text.find("weight rounding error-carry: sum of 8-bit weights 255/255"),
            std::string::npos)
      << text;
  EXPECT_EQ(run_cli("glow --tier dx7 --weight-rounding round", log), 2) << read(log);
}

TEST_F(CliDx7, BadStageStatesInASceneArePositionedErrors) {
  {
    std::ofstream(dir / "three.tss") << "stage 0: colorop modulate texture diffuse\n"
                                        "stage 1: colorop add current texture\n"
                                        "stage 2: colorop add current texture\n";
    std::ofstream(dir / "scene.json")
        << R"({"size": [64, 36], "glow": {"tier": "dx7", "downsample": 4,
               "listings": {"dx7/blur_pair.tss": "three.tss"}}})";
  }
  const fs::path log = dir / "log.txt";
  const fs::path out = dir / "out";
  EXPECT_EQ(
      run_cli("glow --backend cpu -o " + out.string() + " --scene " + (dir / "scene.json").string(),
              log),
      1);
  const std::string text = read(log);
  EXPECT_NE(text.find("three.tss:3:7: error: stage 2: this tier blends 2 textures"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("stage 2: colorop add current texture\n"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(out / "final-cpu.png"));
  // A weight rounding on a shader tier is a scene error at its JSON position.
  std::ofstream(dir / "dx9.json") << R"({"glow": {"tier": "dx9", "weight_rounding": "plain"}})";
  EXPECT_EQ(run_cli("glow --backend cpu --scene " + (dir / "dx9.json").string(), log), 1);
  EXPECT_NE(read(log).find("dx9.json:1:"), std::string::npos) << read(log);
  EXPECT_NE(read(log).find("weight_rounding applies to tier dx7 only"), std::string::npos)
      << read(log);
}

} // namespace
