// `tierlift glow --scene` on the stencil-outline scene, end to end on all three devices: the
// agreement table has a row for each render target of the object pass and for the stencil
// buffer, and every pair is within design's targets; a stencil reference outside 1..255 is a
// positioned error, exit 1, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "cli_fixture.h"

namespace {

namespace fs = std::filesystem;

class CliOutline : public tierlift::cli_test::CliFixture {};

TEST_F(CliOutline, ShippedSceneRunsOnEveryDeviceWithEveryTargetCompared) {
  ASSERT_EQ(glow_shipped_scene("stencil-outline.json"), 0) << glow_log();
  const std::string text = glow_log();
  // The rows of the object pass's three outputs and of the stencil test's buffer; cpu ·
  // vulkan agree exactly on each (the coverage, the constants and the stencil values are
  // exact in both; no blur has run yet).
  for (const char* row : {"object +color", "object +mask", "object +stencil", "outline +stencil"})
    EXPECT_TRUE(std::regex_search(text, std::regex(std::string(row) + " +0 +0 +100\\.000%")))
        << row << "\n"
        << text;
  EXPECT_NE(text.find("every pair within design.md's targets"), std::string::npos) << text;
  expect_each_way(dir / "out", "final-");
}

TEST_F(CliOutline, StencilReferenceOutOfRangeExitsOneAndWritesNothing) {
  const std::string text =
      glow_refuses_scene("{\n  \"effect\": \"stencil-outline\",\n  \"size\": [64, 48],\n"
                         "  \"outline\": { \"stencil_ref\": 256 }\n}\n",
                         "--backend all ");
  EXPECT_NE(text.find("bad.json:4:31: error: /outline/stencil_ref: 256 is outside 1..255"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("^"), std::string::npos) << text;
}

// The validator's MRT rule at the command line: oC1 written without oC0 names the file, the
// line and the column of the write, with the source line and a caret.
TEST_F(CliOutline, OC1WithoutOC0IsAPositionedError) {
  const fs::path listing = dir / "mrt.psh", log = dir / "log.txt";
  std::ofstream(listing) << "ps_2_0\nmov oC1, c1\n";
  EXPECT_EQ(run_cli("check " + listing.string(), log), 1) << read(log);
  const std::string text = read(log);
  EXPECT_NE(text.find("mrt.psh:2:5: error: oC1 is written, so every oC below it must be written "
                      "too; oC0 is not"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("    mov oC1, c1\n        ^~~"), std::string::npos) << text;
}

} // namespace
