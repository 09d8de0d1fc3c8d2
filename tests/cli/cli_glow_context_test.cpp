// `tierlift glow --scene` with a rendering context, end to end: the shipped fog and
// glow-image scenes run three ways within targets and write their frames; a bad fog or glow
// image is a positioned error with its caret, exit 1, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_fixture.h"

namespace {

namespace fs = std::filesystem;

class CliGlowContext : public tierlift::cli_test::CliFixture {};

const fs::path kScenes = fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "scenes";

TEST_F(CliGlowContext, ShippedScenesThreeWaysWithinTargets) {
  for (const char* name : {"glow-fog.json", "glow-context.json"})
    for (const char* tier : {"dx9", "dx8"}) {
      const fs::path out = dir / (std::string(name) + tier), log = dir / "log.txt";
      ASSERT_EQ(run_cli(std::string("glow -q --backend all --tier ") + tier + " --scene " +
                            (kScenes / name).string() + " -o " + out.string(),
                        log),
                0)
          << name << " " << tier << "\n"
          << read(log);
      const std::string text = read(log);
      EXPECT_NE(text.find("glow sources: the "), std::string::npos) << text;
      EXPECT_NE(text.find("every pair within design.md's targets"), std::string::npos) << text;
      expect_each_way(out, "final-");
    }
}

struct Bad {
  std::string json, where, says;
};

TEST_F(CliGlowContext, BadContextExitsOneWithACaretAndWritesNothing) {
  const Bad cases[] = {
      {"{\n  \"glow\": {\"fog\": {\"start\": 0.6, \"end\": 0.6}}\n}\n",
       "bad.json:2:41: error: "
       "/glow/fog/end",
       "is not beyond start"},
      {"{\n  \"size\": [64, 32],\n  \"glow_image\": \"" + (kScenes / "sign-glow.png").string() +
           "\"\n}\n",
       "bad.json:3:17: error: /glow_image", "160x96 but the scene is 64x32"},
      {"{\n  \"glow_image\": \"missing.png\"\n}\n", "bad.json:2:17: error: /glow_image",
       "cannot read the image"},
      {"{\n  \"glow\": {\"fog\": {\"start\": 0, \"end\": 1, \"color\": [2, 0, 0]}}\n}\n",
       "bad.json:2:52: error: /glow/fog/color/0", "outside 0..1"}};
  for (const Bad& b : cases) {
    SCOPED_TRACE(b.where);
    const std::string text = glow_refuses_scene(b.json);
    EXPECT_NE(text.find(b.where), std::string::npos) << text;
    EXPECT_NE(text.find(b.says), std::string::npos) << text;
    EXPECT_NE(text.find('^'), std::string::npos) << text;
  }
}

} // namespace
