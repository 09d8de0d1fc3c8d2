// Glow scenes (scene.h): the files in listings/scenes load and build, bad fields are named
// with file:line:col and a caret, weights that do not sum to one warn with the right figure,
// and the schema file lists the keys the loader accepts. Expected positions are counted by
// hand in the JSON texts below (columns 1-based, in bytes).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include "listing_files.h"
#include "scene_error_case.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

namespace fs = std::filesystem;

TEST(Scene, EveryShippedSceneLoadsAndBuilds) {
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(kScenes)) {
    if (e.path().extension() != ".json" || e.path().filename() == "scene.schema.json") continue;
    ++n;
    ir::Result<Scene> s = load_scene_file(e.path().string());
    ASSERT_TRUE(s) << e.path() << "\n" << s.message();
    PlanResult plan = build_scene_effect(*s);
    EXPECT_TRUE(plan) << e.path() << ": " << plan.message();
    img::ImageResult image = load_scene_image(*s);
    ASSERT_TRUE(image) << image.message();
    EXPECT_EQ(image->width, s->params.width);
  }
  EXPECT_EQ(n, 15u); // default, dx8, sawtooth, sign, dx7, dx7-plain-rounding, radial-beams,
                     // stencil-outline, glsl-blur, afterimage, afterimage-runaway, ramping,
                     // glow-context, glow-fog, lamp
}

TEST(Scene, DefaultJsonSaysWhatTheBuiltInDefaultIs) {
  ir::Result<Scene> s = load_scene_file((kScenes / "default.json").string());
  ASSERT_TRUE(s) << s.message();
  const EffectParams &a = s->params, &b = default_scene().params;
  EXPECT_EQ(s->image, "builtin:neon");
  EXPECT_EQ(a.width, 1280u);
  EXPECT_EQ(a.height, 720u);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.tier, b.tier);
  EXPECT_EQ(a.downsample, b.downsample);
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.half_texel, b.half_texel);
  EXPECT_EQ(a.intensity, b.intensity);
  ASSERT_EQ(a.profile.terms.size(), b.profile.terms.size());
  ASSERT_FALSE(a.profile.terms.empty());
  for (size_t i = 0; i < a.profile.terms.size(); ++i) {
    EXPECT_EQ(a.profile.terms[i].sigma, b.profile.terms[i].sigma);
    EXPECT_EQ(a.profile.terms[i].weight, b.profile.terms[i].weight);
  }
}

TEST(Scene, FieldsAreRead) {
  ir::Result<Scene> s = parse_shipped(R"({"size": [64, 48], "glow": {"tier": "dx8", "downsample": 3,
    "format": "rgba8", "half_texel": false, "intensity": 0.5, "taps": 5,
    "profile": {"gaussians": [{"sigma": 2, "weight": 1}]}}})");
  ASSERT_TRUE(s) << s.message();
  const EffectParams& p = s->params;
  EXPECT_EQ(p.width, 64u);
  EXPECT_EQ(p.height, 48u);
  EXPECT_EQ(p.tier, Tier::Dx8);
  EXPECT_EQ(p.downsample, 3u);
  EXPECT_EQ(p.format, img::Format::RGBA8);
  EXPECT_FALSE(p.half_texel);
  EXPECT_EQ(p.intensity, 0.5);
  EXPECT_EQ(p.profile.max_taps, 5u);
}

// Each bad field: the message names the JSON pointer at line:col of its value, then the
// source line and a caret under that column (scene_error_case.h).
using Bad = SceneErrorCase;

class SceneErrors : public ::testing::TestWithParam<Bad> {};

TEST_P(SceneErrors, NameTheFieldWithItsPosition) {
  const Bad& b = GetParam();
  expect_positioned_scene_error(parse_shipped(b.text), b);
}

INSTANTIATE_TEST_SUITE_P(
    Fields, SceneErrors,
    ::testing::Values(
        Bad{"{\n  \"glow\": {\n    \"tier\": \"dx6\"\n  }\n}", "s.json:3:13: error: /glow/tier",
            "not a tier"},
        Bad{"{\"glow\": {\"downsample\": 0}}", "s.json:1:25: error: /glow/downsample",
            "outside 1..4"},
        Bad{"{\"glow\": {\"downsample\": 9}}", "s.json:1:25: error: /glow/downsample",
            "outside 1..4"},
        Bad{"{\"glow\": {\"profile\": {\"gaussians\": [{\"sigma\": -1, \"weight\": 1}]}}}",
            "s.json:1:47: error: /glow/profile/gaussians/0/sigma", "must be > 0"},
        Bad{"{\"size\": [16385, 10]}", "s.json:1:11: error: /size/0", "outside 1..16384"},
        Bad{"{\"image\": \"no-such.png\"}", "s.json:1:11: error: /image", "cannot read"},
        Bad{"{\"glow\": {\"colour\": 1}}", "s.json:1:11: error: /glow/colour", "unknown key"},
        Bad{"{\"glow\": {\"tier\": \"dx8\", \"intensity\": 5}}",
            "s.json:1:39: error: /glow/intensity", "outside 0..4"},
        Bad{"{\"glow\": {\"taps\": 4}}", "s.json:1:19: error: /glow/taps", "even"},
        // The one tap cap (effects::kMaxBlurTaps): radius 1024, 2·1024 + 1 taps.
        Bad{"{\"glow\": {\"taps\": 2051}}", "s.json:1:19: error: /glow/taps", "outside 1..2049"}),
    scene_case_name);

TEST(Scene, SyntaxErrorsHaveAPosition) {
  ir::Result<Scene> s = parse_shipped("{\n  \"glow\": {\"tier\": \"dx9\", }\n}");
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("s.json:2:27: error: syntax error"), std::string::npos) << s.message();
}

TEST(Scene, WeightsThatDoNotSumToOneWarnByHowMuch) {
  ir::Result<Scene> s = parse_shipped(R"({"glow": {"profile": {"gaussians": [
      {"sigma": 3, "weight": 0.49}, {"sigma": 1, "weight": 0.49}]}}})");
  ASSERT_TRUE(s) << s.message();
  // 0.98 per axis, 0.98² = 0.9604 after both: 3.96 % darker.
  const std::vector<std::string> w = glow_warnings(s->params);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "profile weights sum to 0.98: the glow is 3.96 % darker than its sources "
                  "(0.9604 after both axes)");
  EXPECT_TRUE(glow_warnings(default_scene().params).empty());
}

TEST(Scene, SawtoothTapsByHand) {
  // period 2 px, radius 3 px, N = 1: saw(x) = 1 − frac(|x|/2) → x = 0: 1, ±1: ½, ±2: 1, ±3: ½;
  // the sum is 5, so the taps are 0.2, 0.1, 0.2, 0.1 from the centre out.
  ir::Result<Scene> s = parse_shipped(R"({"glow": {"downsample": 1,
      "profile": {"sawtooth": {"period": 2, "radius": 3, "weight": 1}}}})");
  ASSERT_TRUE(s) << s.message();
  ir::Result<std::vector<BlurTap>> sampled = sample_blur_profile(s->params.profile, 1);
  ASSERT_TRUE(sampled) << sampled.message();
  const std::vector<BlurTap>& taps = *sampled;
  ASSERT_EQ(taps.size(), 7u);
  const double want[7] = {0.1, 0.2, 0.1, 0.2, 0.1, 0.2, 0.1};
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(taps[k].offset, k - 3);
    EXPECT_NEAR(taps[k].weight, want[k], 1e-12) << k;
  }
}

std::set<std::string> keys_of(const nlohmann::json& props) {
  std::set<std::string> out;
  for (auto it = props.begin(); it != props.end(); ++it) out.insert(it.key());
  return out;
}

std::set<std::string> keys_of(std::span<const std::string_view> keys) {
  return {keys.begin(), keys.end()};
}

std::set<std::string> values_of(const nlohmann::json& array) {
  std::set<std::string> out;
  for (const auto& v : array) out.insert(v.get<std::string>());
  return out;
}

TEST(Scene, TheSchemaFileListsTheKeysTheLoaderAccepts) {
  const auto schema = nlohmann::json::parse(test::read_file(kScenes / "scene.schema.json"));
  EXPECT_EQ(keys_of(schema["properties"]), keys_of(scene_keys()));
  EXPECT_EQ(keys_of(schema["properties"]["glow"]["properties"]), keys_of(scene_glow_keys()));
  EXPECT_EQ(keys_of(schema["properties"]["glow"]["properties"]["profile"]["properties"]),
            keys_of(scene_profile_keys()));
  EXPECT_EQ(keys_of(schema["properties"]["glow"]["properties"]["fog"]["properties"]),
            keys_of(scene_fog_keys()));
  EXPECT_EQ(keys_of(schema["properties"]["radial"]["properties"]), keys_of(scene_radial_keys()));
  EXPECT_EQ(keys_of(schema["properties"]["outline"]["properties"]), keys_of(scene_outline_keys()));
  EXPECT_EQ(values_of(schema["properties"]["effect"]["enum"]), keys_of(scene_effects()));
  EXPECT_EQ(keys_of(schema["properties"]["glsl"]["properties"]), keys_of(scene_glsl_keys()));
}

// The effect registry (effect_kinds): each kind once, named as the scene files name it, with
// the key of its own object; a scene's "effect" string selects the kind.
TEST(Scene, EachEffectKindIsRegisteredOnceWithItsNameAndObject) {
  const std::pair<EffectKind, std::pair<std::string_view, std::string_view>> expected[] = {
      {EffectKind::Glow, {"glow", ""}},
      {EffectKind::RadialBeams, {"radial-beams", "radial"}},
      {EffectKind::StencilOutline, {"stencil-outline", "outline"}},
      {EffectKind::GlslBlur, {"glsl-blur", "glsl"}}};
  ASSERT_EQ(effect_kinds().size(), std::size(expected));
  for (const auto& [kind, names] : expected) {
    const EffectInfo& info = effect_info(kind);
    EXPECT_EQ(info.kind, kind);
    EXPECT_EQ(info.name, names.first);
    EXPECT_EQ(info.object, names.second);
    EXPECT_EQ(parse_effect_kind(names.first), kind);
  }
  EXPECT_EQ(parse_effect_kind("bloom"), std::nullopt);
  EXPECT_EQ(parse_effect_kind("Glow"), std::nullopt); // names are exact
  ir::Result<Scene> outline =
      parse_scene(R"({"effect": "stencil-outline", "size": [8, 8]})", "s.json", "");
  ASSERT_TRUE(outline) << outline.message();
  EXPECT_EQ(outline->effect, EffectKind::StencilOutline);
  ir::Result<Scene> plain = parse_scene(R"({"size": [8, 8]})", "s.json", "");
  ASSERT_TRUE(plain) << plain.message();
  EXPECT_EQ(plain->effect, EffectKind::Glow); // the default
}

} // namespace
} // namespace tierlift::effects
