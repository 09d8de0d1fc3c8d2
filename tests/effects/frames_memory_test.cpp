// Frames (run_frames: setup once, then the passes again and again, textures carried over)
// and the memory planner (plan_memory: bytes from the graph alone), on hand-computed values.
#include <gtest/gtest.h>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/glow/builtin_listing.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/graph/memory_plan.h"
#include "tierlift/effects/scenes/default_scene.h"

namespace tierlift::effects {
namespace {

TEST(FrameTimes, MedianMinMax) {
  FrameTimes t;
  EXPECT_EQ(t.median_ms(), 0);
  t.frame_ms = {5, 1, 3, 2};
  EXPECT_EQ(t.median_ms(), 2.5);
  EXPECT_EQ(t.min_ms(), 1);
  EXPECT_EQ(t.max_ms(), 5);
  t.frame_ms = {3, 9, 2};
  EXPECT_EQ(t.median_ms(), 3);
}

// One pass, ONE/ONE onto "acc" from the input: after N frames acc = N × scene (alpha 1, so
// the extract listing's rgb × alpha is the scene itself). Values k/8: every sum is exact.
EffectGraph accumulate_graph(uint32_t w, uint32_t h) {
  EffectGraph g;
  g.textures = {{"scene", w, h, img::Format::RGBA32F, true}, {"acc", w, h, img::Format::RGBA32F}};
  PassDesc p;
  p.name = "add";
  ListingResult vs = builtin_listing("glow/quad4_coords.vsh");
  ListingResult ps = builtin_listing("glow/extract_sources.psh");
  EXPECT_TRUE(vs) << vs.message();
  EXPECT_TRUE(ps) << ps.message();
  p.draw.vertex_program = vs ? *vs : nullptr;
  p.draw.pixel_program = ps ? *ps : nullptr;
  // Point reads at texel centres: offset ½ texel (c0), scale 1 (c4).
  p.draw.vs_constants.f.assign(8, cpu::Vec4{0, 0, 0, 0});
  p.draw.vs_constants.f[0] = {0.5f / float(w), 0.5f / float(h), 0, 0};
  p.draw.vs_constants.f[4] = {1, 1, 0, 0};
  cpu::SamplerState s;
  s.address_u = s.address_v = cpu::AddressMode::Clamp;
  bind_reads(p, 0, "scene", s, 1, false);
  p.target = "acc";
  p.draw.blend = cpu::BlendMode::OneOne;
  g.passes = {p};
  return g;
}

img::Image eighths(uint32_t w, uint32_t h) {
  img::Image im(w, h, img::Format::RGBA32F);
  for (size_t i = 0; i < im.rgba.size(); ++i) im.rgba[i] = i % 4 == 3 ? 1.0f : float(i % 9) / 8;
  return im;
}

void expect_accumulates(PassDevice& dev) {
  const uint32_t w = 9, h = 5;
  const EffectGraph g = accumulate_graph(w, h);
  ImageMap images{{"scene", eighths(w, h)}};
  ir::Result<FrameTimes> run = run_frames(g, dev, images, 3);
  ASSERT_TRUE(run.ok()) << run.message();
  EXPECT_EQ(run->frame_ms.size(), 3u);
  EXPECT_GE(run->setup_ms, 0);
  const img::Image& acc = images.at("acc");
  const img::Image scene = eighths(w, h);
  ASSERT_EQ(acc.rgba.size(), scene.rgba.size());
  for (size_t i = 0; i < acc.rgba.size(); ++i) ASSERT_EQ(acc.rgba[i], 3 * scene.rgba[i]) << i;
}

TEST(Frames, TexturesCarryIntoTheNextFrameOnTheCpuDevice) {
  CpuPassDevice dev(2);
  expect_accumulates(dev);
}

using FramesVulkan = vulkan::test::VulkanTest; // validation on: any message fails

TEST_F(FramesVulkan, TexturesCarryIntoTheNextFrame) {
  auto vk = make_vulkan_pass_device(*dev);
  expect_accumulates(*vk);
}

// The glow's every texture is first written by a replacing pass: frame N is frame 1.
TEST_F(FramesVulkan, GlowFramesRepeatTheSingleRun) {
  EffectParams p;
  p.width = 96;
  p.height = 48;
  p.downsample = 2;
  p.format = img::Format::RGBA8;
  const PlanResult plan_built = build_glow(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  const EffectPlan& plan = *plan_built;
  const img::Image scene = make_default_scene(p.width, p.height, p.format);
  CpuPassDevice cpu(2);
  const EffectRun once = run_effect(plan, scene, cpu);
  ASSERT_TRUE(once.run.ok()) << once.run.message();
  auto vk = make_vulkan_pass_device(*dev);
  const EffectFrames frames = run_effect_frames(plan, scene, *vk, 4);
  ASSERT_TRUE(frames.run.ok()) << frames.run.message();
  const std::string final_name(kFinalTexture);
  EXPECT_EQ(frames.images.at(final_name).rgba, once.images.at(final_name).rgba);
  EXPECT_NE(frames.images.at(final_name).rgba, scene.rgba); // the glow added something
}

// scene 4×2 RGBA8 (input) → a 4×2 RGBA8 → b 2×1 RGBA32F, the second pass binding `a` on
// two stages. Host images: 16 B/px; the bytes below follow memory_plan.h's model by hand.
TEST(MemoryPlan, HandComputedBytesPerDevice) {
  EffectGraph g;
  g.textures = {{"scene", 4, 2, img::Format::RGBA8, true},
                {"a", 4, 2, img::Format::RGBA8},
                {"b", 2, 1, img::Format::RGBA32F}};
  PassDesc p1, p2;
  p1.name = "p1";
  p1.target = "a";
  p1.textures = {{0, "scene"}};
  p2.name = "p2";
  p2.target = "b";
  p2.textures = {{0, "a"}, {1, "a"}};
  g.passes = {p1, p2};
  // Host copies: scene 8 px·16 = 128, a 128, b 2·16 = 32: 288 for "every texture".
  const MemoryPlan m = plan_memory(g, {"cpu", "vulkan", "analytic"}, false, 1000);
  ASSERT_EQ(m.devices.size(), 3u);
  // cpu: images back 288 + its own 288; a pass draws in place and binds by reference, so
  // the transient is one read's copy of the largest texture (scene or a: 128), no more than
  // begin_run's copy of the input scene (128).
  EXPECT_EQ(m.devices[0].kept, 576u);
  EXPECT_EQ(m.devices[0].transient, 128u);
  // vulkan: 288 + stored 32 + 32 + 32 + two sampled RGBA8 (16 + 20 B/px · 8 px each = 288).
  EXPECT_EQ(m.devices[1].kept, 288u + 96u + 2 * 288u);
  EXPECT_EQ(m.devices[1].transient, 32u + 128u); // staging of a + its host image
  // analytic: 288 + 288 + masks of the RGBA8 textures 8 + 8; during p1 a 128 + scene 128.
  EXPECT_EQ(m.devices[2].kept, 592u);
  EXPECT_EQ(m.devices[2].transient, 256u);
  EXPECT_EQ(m.peak, 1000u + 576u + 960u + 592u + 256u); // the analytic transient is largest
  // Per-pass images kept: one host image of each pass's target more, per device.
  const MemoryPlan keep = plan_memory(g, {"cpu"}, true);
  EXPECT_EQ(keep.devices[0].kept, 576u + 128u + 32u);

  // Point reads with edge clamping fetch RGBA8 bytes in place: no float copy of `scene`;
  // `a` keeps its copy while one of its two reads still wraps.
  pass::SamplerState clamped;
  clamped.address_u = clamped.address_v = pass::AddressMode::Clamp;
  g.passes[0].draw.textures[0].sampler = clamped;
  g.passes[1].draw.textures[0].sampler = clamped;
  EXPECT_EQ(plan_memory(g, {"vulkan"}, false).devices[0].kept, 288u + 96u + 288u);
  g.passes[1].draw.textures[1].sampler = clamped;
  EXPECT_EQ(plan_memory(g, {"vulkan"}, false).devices[0].kept, 288u + 96u);
}

TEST(MemoryPlan, FormatBytes) {
  EXPECT_EQ(format_bytes(3u << 30), "3.0 GiB (3221225472 bytes)");
  EXPECT_EQ(format_bytes(1536u * 1024), "1.5 MiB (1572864 bytes)");
}

} // namespace
} // namespace tierlift::effects
