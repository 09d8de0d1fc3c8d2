// run_scene (scene_run.h): a scene run on the ways asked for, compared pair by pair, with
// its frames; failures carry their rule. Expected values are facts of the scene worked out by
// hand (an intensity of 0 adds nothing to the scene; N frames give N times), never an
// earlier output of run_scene.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/effects/scenes/scene_run.h"
#include "tierlift/image/image.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::effects {
namespace {

Scene scene_from(const char* json) {
  ir::Result<Scene> s = parse_scene(json, "s.json", "");
  EXPECT_TRUE(s) << s.message();
  return s ? *s : Scene{};
}

SceneRunOptions cpu_and_analytic() {
  SceneRunOptions o;
  ir::Result<BackendChoice> b = parse_backends("cpu,analytic", {"cpu", "vulkan", "analytic"});
  EXPECT_TRUE(b) << b.message();
  if (b) o.backends = *b;
  o.threads = 1;
  return o;
}

// final = scene + intensity × glow: with intensity 0 the final image is the scene image as
// the target format stores it, on every way, and every pair agrees.
TEST(SceneRun, IntensityZeroLeavesTheSceneAsItWasOnEveryWay) {
  const Scene scene = scene_from(R"({"size": [24, 16], "glow": {"intensity": 0,
                                     "format": "rgba32f"}})");
  ir::Result<SceneRun> run = run_scene(scene, cpu_and_analytic());
  ASSERT_TRUE(run) << run.message();
  ASSERT_EQ(run->ways.size(), 2u);
  EXPECT_EQ(run->ways[0].name, "cpu");
  EXPECT_EQ(run->ways[1].name, "analytic");
  img::ImageResult image = load_scene_image(scene);
  ASSERT_TRUE(image) << image.message();
  for (const WayRun& way : run->ways) {
    const img::Image& final_image = way.glow.images.at(std::string(kFinalTexture));
    ASSERT_EQ(final_image.width, 24u);
    ASSERT_EQ(final_image.height, 16u);
    for (size_t i = 0; i < final_image.rgba.size(); ++i) {
      if (i % 4 == 3) continue; // rgb: the scene's; alpha is the glow mask's business
      ASSERT_EQ(final_image.rgba[i], image->rgba[i]) << way.name << " value " << i;
    }
  }
  ASSERT_EQ(run->pairs.size(), 1u);
  EXPECT_EQ(run->pairs[0].a, "cpu");
  EXPECT_EQ(run->pairs[0].b, "analytic");
  EXPECT_TRUE(run->all_within());
  EXPECT_GT(run->planned_bytes, uint64_t{24 * 16 * 16}); // at least the scene in floats
  EXPECT_FALSE(run->moves);
  EXPECT_TRUE(run->frames.empty());
}

// frames on a still scene: each way once more, setup apart from exactly N frames.
TEST(SceneRun, FramesOnAStillSceneTimeNFramesPerWay) {
  SceneRunOptions o = cpu_and_analytic();
  o.frames = 3;
  ir::Result<SceneRun> run = run_scene(scene_from(R"({"size": [16, 16]})"), o);
  ASSERT_TRUE(run) << run.message();
  ASSERT_EQ(run->frames.size(), 2u);
  EXPECT_EQ(run->frames[0].device, "cpu");
  EXPECT_EQ(run->frames[1].device, "analytic");
  for (const FrameReport& r : run->frames) EXPECT_EQ(r.times.frame_ms.size(), 3u) << r.device;
  EXPECT_FALSE(run->animated);
}

// A moving scene without frames runs frame 1 and says so, as a warning of the result; with
// frames every frame of every way is compared.
TEST(SceneRun, AMovingSceneWarnsWithoutFramesAndIsComparedFrameByFrameWithThem) {
  const char* json = R"({"size": [16, 16], "glow": {"format": "rgba16f",
                         "afterimage": {"mode": "sources", "gain": 0.5}}})";
  ir::Result<SceneRun> once = run_scene(scene_from(json), cpu_and_analytic());
  ASSERT_TRUE(once) << once.message();
  EXPECT_TRUE(once->moves);
  bool told = false;
  for (const ir::Diagnostic& d : once.diagnostics())
    told = told || (d.severity == ir::Severity::Warning && d.rule == "scene" &&
                    d.message.find("shows frame 1 only") != std::string::npos);
  EXPECT_TRUE(told);

  SceneRunOptions o = cpu_and_analytic();
  o.frames = 4;
  ir::Result<SceneRun> run = run_scene(scene_from(json), o);
  ASSERT_TRUE(run) << run.message();
  EXPECT_TRUE(run->animated);
  ASSERT_EQ(run->animation.times.size(), 2u);
  ASSERT_EQ(run->animation.pairs.size(), 1u);
  EXPECT_EQ(run->animation.pairs[0].frames, 4u);
  EXPECT_EQ(run->animation.pairs[0].frames_within, 4u);
}

// The failures carry their rule: a Vulkan device asked for by a filter nothing matches
// ("device"), a memory budget below the scene's peak ("memory").
TEST(SceneRun, FailuresNameTheirRule) {
  // The refused run creates and destroys a Vulkan instance; a device the program keeps
  // (vk_test_util.h) keeps lavapipe loaded, so LeakSanitizer can still name the driver's
  // lifetime allocations (tests/lsan.supp) instead of an "<unknown module>".
  (void)vulkan::test::program_device({});
  SceneRunOptions o;
  ir::Result<BackendChoice> vk = parse_backends("vulkan", {"cpu", "vulkan", "analytic"});
  ASSERT_TRUE(vk) << vk.message();
  o.backends = *vk;
  o.vulkan.gpu_filter = "no device is called this";
  ir::Result<SceneRun> no_device = run_scene(scene_from(R"({"size": [16, 16]})"), o);
  ASSERT_FALSE(no_device);
  EXPECT_TRUE(ir::failed_with(no_device, "device")) << no_device.message();

  ASSERT_EQ(setenv("TIERLIFT_MEMORY_LIMIT", "1048576", 1), 0); // 1 MiB: below the program
  ir::Result<SceneRun> too_big = run_scene(scene_from(R"({"size": [16, 16]})"), cpu_and_analytic());
  unsetenv("TIERLIFT_MEMORY_LIMIT");
  ASSERT_FALSE(too_big);
  EXPECT_TRUE(ir::failed_with(too_big, "memory")) << too_big.message();
}

} // namespace
} // namespace tierlift::effects
