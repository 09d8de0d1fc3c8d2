// The frame-to-frame fields of a scene's "glow" (ramped numbers, the after-image): read into
// EffectParams, and every bad value named by JSON pointer at its line:col (counted by hand).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene_error_case.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

ir::Result<Scene> parse(const std::string& text) {
  return parse_scene(text, "s.json", "");
}

TEST(SceneFrames, RampsAndAfterimageAreRead) {
  ir::Result<Scene> s = parse(R"({"glow": {"intensity": {"keyframes": [[1, 0.5], [9, 2]]},
    "weight_scale": 0.9, "afterimage": {"mode": "glow", "gain": {"keyframes": [[4, 0.25]]}}}})");
  ASSERT_TRUE(s) << s.message();
  const EffectParams& p = s->params;
  ASSERT_EQ(p.intensity_ramp.points.size(), 2u);
  EXPECT_EQ(p.intensity_ramp.points[1], (std::pair<unsigned, double>{9, 2.0}));
  EXPECT_EQ(p.intensity, 0.5); // the first keyframe's value
  EXPECT_EQ(p.weight_scale, 0.9);
  EXPECT_TRUE(p.weight_scale_ramp.empty());
  EXPECT_EQ(p.afterimage, Afterimage::Glow);
  EXPECT_EQ(p.afterimage_gain, 0.25);
  EXPECT_EQ(p.afterimage_gain_ramp.span(), 4u);
  EXPECT_TRUE(p.animated());
  EXPECT_FALSE(parse("{}")->params.animated());
}

using Bad = SceneErrorCase;

class SceneFramesErrors : public ::testing::TestWithParam<Bad> {};

TEST_P(SceneFramesErrors, NameTheValueWithItsPosition) {
  const Bad& b = GetParam();
  expect_positioned_scene_error(parse(b.text), b);
}

INSTANTIATE_TEST_SUITE_P(
    Fields, SceneFramesErrors,
    ::testing::Values(
        Bad{R"({"glow": {"intensity": {"keyframes": [[1, 0.5], [1, 2]]}}})",
            "s.json:1:50: error: /glow/intensity/keyframes/1/0", "does not come after frame 1"},
        Bad{R"({"glow": {"intensity": {"keyframes": [[1, 2000]]}}})",
            "s.json:1:43: error: /glow/intensity/keyframes/0/1", "outside 0..1000"},
        Bad{R"({"glow": {"intensity": {"keyframes": [[0, 1]]}}})",
            "s.json:1:40: error: /glow/intensity/keyframes/0/0", "outside 1..100000"},
        Bad{R"({"glow": {"intensity": {"keyframes": []}}})",
            "s.json:1:38: error: /glow/intensity/keyframes", "not a non-empty array"},
        Bad{R"({"glow": {"intensity": "bright"}})", "s.json:1:24: error: /glow/intensity",
            "neither a number"},
        Bad{R"({"glow": {"afterimage": {"mode": "echo"}}})",
            "s.json:1:34: error: /glow/afterimage/mode", "not an after-image"},
        Bad{R"({"glow": {"afterimage": {"mode": "glow", "gain": 5}}})",
            "s.json:1:50: error: /glow/afterimage/gain", "outside 0..4"},
        Bad{R"({"glow": {"afterimage": {"gain": 0.5}}})", "error: /glow/afterimage", "mode"},
        Bad{R"({"glow": {"weight_scale": {"keys": []}}})", "error: /glow/weight_scale", "keys"},
        // Missing members are reported, never read (the fuzzer found a read of a missing
        // "period" through const operator[], undefined behaviour in nlohmann).
        Bad{R"({"glow": {"motion": {"radius": 0.1, "perimod": 16}}})", "error: /glow/motion",
            "missing \"period\""},
        Bad{R"({"glow": {"motion": {"period": 8}}})", "error: /glow/motion", "missing \"radius\""},
        Bad{R"({"glow": {"intensity": {}}})", "error: /glow/intensity", "missing \"keyframes\""}),
    scene_case_name);

} // namespace
} // namespace tierlift::effects
