// `tierlift glow --scene` on a radial-beams scene, end to end: the three ways and the
// agreement table, the beams image written; a bad "radial" field is a positioned error, exit
// 1, nothing written.
#include <gtest/gtest.h>

#include <string>

#include "cli_fixture.h"

namespace {

class CliRadial : public tierlift::cli_test::CliFixture {};

TEST_F(CliRadial, ShippedSceneThreeWaysWithinTargets) {
  ASSERT_EQ(glow_shipped_scene("radial-beams.json"), 0) << glow_log();
  const std::string text = glow_log();
  EXPECT_NE(text.find("radial-beams dx9: 320x180"), std::string::npos) << text;
  EXPECT_NE(text.find("zoom.3"), std::string::npos) << text; // 32 copies, 8 a pass
  EXPECT_NE(text.find("every pair within design.md's targets"), std::string::npos) << text;
  expect_each_way(dir / "out", "glow-");
}

TEST_F(CliRadial, BadRadialFieldExitsOneAndWritesNothing) {
  const std::string text = glow_refuses_scene(
      "{\n  \"effect\": \"radial-beams\",\n  \"radial\": { \"centre\": [2, 0.5] }\n}\n");
  EXPECT_NE(text.find("bad.json:3:26: error: /radial/centre/0: 2 is outside"), std::string::npos)
      << text;
}

} // namespace
