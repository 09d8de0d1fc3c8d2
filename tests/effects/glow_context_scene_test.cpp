// The rendering context in scenes: "glow_image" and "glow"/"fog" are read into EffectParams,
// every bad value is a positioned diagnostic at its field (caret under the column), and the
// two shipped scenes (glow-fog.json, glow-context.json) agree three ways on tiers dx9 and
// dx8 at docs/design.md's targets, as does a glow image fogged toward a colour in RGBA8.
#include <gtest/gtest.h>

#include <filesystem>

#include "../vulkan/vk_test_util.h"
#include "scene_error_case.h"
#include "three_ways.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

namespace fs = std::filesystem;

TEST(GlowContextScene, FieldsAreRead) {
  ir::Result<Scene> s =
      parse_shipped(R"({"glow": {"fog": {"start": 0.1, "end": 0.9, "color": [0.5, 0, 1]}}})");
  ASSERT_TRUE(s) << s.message();
  const GlowFog& fog = s->params.context.fog;
  EXPECT_TRUE(fog.on);
  EXPECT_EQ(fog.start, 0.1);
  EXPECT_EQ(fog.end, 0.9);
  EXPECT_EQ(fog.color, (std::array<double, 3>{0.5, 0, 1}));
  EXPECT_EQ(fog.depth, nullptr); // the built-in floor
  EXPECT_EQ(s->params.context.glow_image, nullptr);

  s = parse_shipped(R"({"image": "sign.png", "glow_image": "sign-glow.png",
                "glow": {"fog": {"start": 0, "end": 1, "depth": "sign-glow.png"}}})");
  ASSERT_TRUE(s) << s.message();
  ASSERT_NE(s->params.context.glow_image, nullptr);
  EXPECT_EQ(s->params.context.glow_image->width, 160u);
  ASSERT_NE(s->params.context.fog.depth, nullptr);
  // The scene's own alpha is no longer what glows: its warnings are the glow image's.
  for (const std::string& w : s->warnings)
    EXPECT_EQ(w.find("the image's alpha"), std::string::npos) << w;
}

using Bad = SceneErrorCase;

class GlowContextSceneErrors : public ::testing::TestWithParam<Bad> {};

TEST_P(GlowContextSceneErrors, NameTheFieldWithItsPosition) {
  const Bad& b = GetParam();
  ir::Result<Scene> s = parse_shipped(b.text);
  expect_positioned_scene_error(s, b);
  EXPECT_FALSE(
      ir::failed_with(s, kSceneIoRule)); // a file the scene names is the scene's error: exit 1
}

INSTANTIATE_TEST_SUITE_P(
    Fields, GlowContextSceneErrors,
    ::testing::Values(
        Bad{R"({"glow": {"fog": {"start": 0.5, "end": 0.2}}})", "s.json:1:40: error: /glow/fog/end",
            "0.2 is not beyond start 0.5"},
        Bad{R"({"size": [64, 32], "glow_image": "sign-glow.png"})",
            "s.json:1:34: error: /glow_image", "the image is 160x96 but the scene is 64x32"},
        Bad{R"({"glow_image": "no-such.png"})", "s.json:1:16: error: /glow_image",
            "cannot read the image"},
        Bad{R"({"glow": {"fog": {"start": 0, "end": 1, "color": [0, 1.5, 0]}}})",
            "s.json:1:54: error: /glow/fog/color/1", "1.5 is outside 0..1"},
        Bad{R"({"glow": {"fog": {"start": 0, "end": 1, "color": [0, 0]}}})",
            "s.json:1:50: error: /glow/fog/color", "is not [r, g, b]"},
        Bad{R"({"glow": {"tier": "dx8", "fog": {"start": 0.7, "end": 0.8}}})",
            "s.json:1:55: error: /glow/fog/end", "tier dx8: fog from 0.7 to 0.8"},
        Bad{R"({"glow": {"fog": {"start": 0, "end": 1, "depth": "no.png"}}})",
            "s.json:1:50: error: /glow/fog/depth", "cannot read the image"},
        Bad{R"({"effect": "radial-beams", "size": [160, 96], "glow_image": "sign-glow.png"})",
            "s.json:1:47: error: /glow_image", "applies to effect \"glow\" only"},
        Bad{R"({"effect": "glsl-blur", "glow": {"fog": {"start": 0, "end": 1}}})",
            "s.json:1:34: error: /glow/fog", "applies to effect \"glow\" only"}),
    scene_case_name);

struct Shipped {
  const char* file;
  Tier tier;
};

// Both at once on 8-bit inputs: the glow image fogged toward a colour by the red channel of
// sign.png as depth. Averages and products of 8-bit texels land near rounding midpoints,
// where the analytic store must follow the devices' fp32 arithmetic.
constexpr const char* kBoth = R"({"image": "sign.png", "glow_image": "sign-glow.png",
  "glow": {"downsample": 2, "format": "rgba8",
           "fog": {"start": 0.1, "end": 0.7, "color": [0.2, 0.1, 0.4], "depth": "sign.png"}}})";

class GlowContextShipped : public vulkan::test::VulkanTest,
                           public ::testing::WithParamInterface<Shipped> {};

TEST_P(GlowContextShipped, EveryPairAgreesOnEveryPass) {
  const std::string file = GetParam().file;
  ir::Result<Scene> s =
      file.starts_with("{") ? parse_shipped(file) : load_scene_file((kScenes / file).string());
  ASSERT_TRUE(s) << s.message();
  s->params.tier = GetParam().tier;
  const PlanResult plan_built = build_scene_effect(*s);
  ASSERT_TRUE(plan_built) << plan_built.message();
  const EffectPlan& plan = *plan_built;
  img::ImageResult scene = load_scene_image(*s);
  ASSERT_TRUE(scene) << scene.message();
  test_ways::ThreeDevices devices(*dev);
  const test_ways::NamedRuns ways = test_ways::run_three_ways(plan, *scene, devices);
  for (const auto& [name, w] : ways) ASSERT_TRUE(w.run.ok()) << name << ": " << w.run.message();
  EXPECT_TRUE(dev->messages().empty()) << dev->messages().front();
  test_ways::compare_pairs(
      ways, [](const std::string& a, const std::string& b, const RunAgreement& agree) {
        for (const PassAgreement& row : agree.passes)
          EXPECT_TRUE(row.verdict.pass)
              << a << " vs " << b << ", " << row.pass << ": " << row.verdict.summary;
        EXPECT_TRUE(agree.all_pass);
      });
}

// How a case prints in test listings (GetParam): the scene and the tier.
void PrintTo(const Shipped& c, std::ostream* os) {
  *os << (std::string_view(c.file).starts_with("{") ? "both (inline scene)" : c.file) << " "
      << tier_name(c.tier);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlowContextShipped,
                         ::testing::Values(Shipped{"glow-fog.json", Tier::Dx9},
                                           Shipped{"glow-fog.json", Tier::Dx8},
                                           Shipped{"glow-context.json", Tier::Dx9},
                                           Shipped{"glow-context.json", Tier::Dx8},
                                           Shipped{kBoth, Tier::Dx9}, Shipped{kBoth, Tier::Dx8},
                                           Shipped{kBoth, Tier::Dx7}),
                         [](const ::testing::TestParamInfo<Shipped>& info) {
                           std::string n = info.param.file;
                           if (n.starts_with("{")) n = "both.json";
                           n = n.substr(0, n.find('.'));
                           std::erase(n, '-');
                           return n + "_" + std::string(tier_name(info.param.tier));
                         });

} // namespace
} // namespace tierlift::effects
