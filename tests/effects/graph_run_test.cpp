// Running graphs on the CPU device: the graph checks, the extract and composite passes, and
// the separable blur of one lit texel against the outer product of the taps.
#include <gtest/gtest.h>

#include <cmath>

#include "tierlift/effects/glow/builtin_listing.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/scenes/default_scene.h"

namespace tierlift::effects {
namespace {

EffectPlan small_plan(unsigned n, img::Format f, BlurProfile profile = default_blur_profile()) {
  EffectParams p;
  p.width = 128;
  p.height = 64;
  p.downsample = n;
  p.format = f;
  p.profile = std::move(profile);
  PlanResult plan_built = build_glow_dx9(p);
  if (!plan_built) {
    ADD_FAILURE() << plan_built.message();
    return {};
  }
  return std::move(*plan_built);
}

TEST(Graph, ChecksNamesAndTargets) {
  EffectPlan plan = small_plan(2, img::Format::RGBA32F);
  EXPECT_TRUE(check_graph(plan.graph).ok()) << check_graph(plan.graph).message();
  EffectGraph g = plan.graph;
  g.passes[0].textures[0].texture = "nowhere";
  EXPECT_NE(check_graph(g).message().find("unknown texture 'nowhere'"), std::string::npos);
  g = plan.graph;
  g.passes[0].textures[0].texture = g.passes[0].target;
  EXPECT_NE(check_graph(g).message().find("reads its own target"), std::string::npos);
  g = plan.graph;
  g.passes[0].target = std::string(kSceneTexture);
  EXPECT_NE(check_graph(g).message().find("input texture"), std::string::npos);
  g = plan.graph;
  g.passes[1].name = g.passes[0].name;
  EXPECT_NE(check_graph(g).message().find("appears twice"), std::string::npos);
}

TEST(Graph, MissingOrWrongSizedInputIsAnError) {
  EffectPlan plan = small_plan(2, img::Format::RGBA32F);
  CpuPassDevice dev(2);
  ImageMap images;
  ir::Result<GraphRun> r = run_graph(plan.graph, dev, images);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("'scene' was not given"), std::string::npos) << r.message();
  EffectRun g = run_effect(plan, img::Image(10, 10), dev);
  EXPECT_FALSE(g.run.ok());
  EXPECT_NE(g.run.message().find("expects 128x64"), std::string::npos) << g.run.message();
}

TEST(BuiltinListing, UnknownAndKnown) {
  ListingResult none = builtin_listing("glow/nothing.psh");
  EXPECT_FALSE(none);
  EXPECT_NE(none.message().find("no built-in listing"), std::string::npos);
  for (const char* p :
       {"glow/quad4_coords.vsh", "glow/extract_sources.psh", "glow/extract_sources_ps11.psh",
        "glow/downsample4.psh", "glow/composite_add.psh"}) {
    ListingResult r = builtin_listing(p);
    EXPECT_TRUE(r && *r != nullptr) << p << ": " << r.message();
  }
}

// With alpha 0 everywhere nothing glows: the composite must return the scene exactly.
TEST(GlowCpu, NothingGlowsGivesTheSceneBack) {
  for (img::Format f : {img::Format::RGBA32F, img::Format::RGBA8}) {
    img::Image scene = make_default_scene(128, 64, f);
    for (size_t i = 3; i < scene.rgba.size(); i += 4) scene.rgba[i] = 0.0f;
    CpuPassDevice dev(2);
    EffectRun g = run_effect(small_plan(2, f), scene, dev);
    ASSERT_TRUE(g.run.ok()) << g.run.message();
    EXPECT_EQ(g.images.at(std::string(kFinalTexture)).rgba, scene.rgba);
    for (float v : g.images.at(std::string(kGlowTexture)).rgba) ASSERT_EQ(v, 0.0f);
  }
}

// One glowing texel, no downsampling, σ = 1: the glow is w_i·w_j·colour·alpha around it
// (the separable convolution), and the final frame is scene + glow where the glow texel
// is read at a texel centre (n = 1: exactly).
void one_texel_glows_as_the_outer_product(Tier tier) {
  img::Image scene(32, 16);
  for (size_t i = 0; i < scene.rgba.size(); i += 4) scene.rgba[i + 3] = 0.0f;
  float* lit = scene.at(12, 7);
  lit[0] = 1.0f, lit[1] = 0.5f, lit[2] = 0.25f, lit[3] = 0.5f;
  EffectParams p;
  p.width = 32;
  p.height = 16;
  p.downsample = 1;
  p.intensity = 1; // final = scene + glow
  p.profile = BlurProfile{{{1.0, 1.0}}, std::nullopt, 0};
  p.tier = tier;
  PlanResult plan_built = build_glow(p);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  ASSERT_EQ(plan.taps.size(), 7u);
  CpuPassDevice dev(2);
  EffectRun g = run_effect(plan, scene, dev);
  ASSERT_TRUE(g.run.ok()) << g.run.message();
  const img::Image& glow = g.images.at(std::string(kGlowTexture));
  const img::Image& final_frame = g.images.at(std::string(kFinalTexture));
  const double norm = 1 + 2 * (std::exp(-0.5) + std::exp(-2.0) + std::exp(-4.5));
  auto w = [&](int k) { return std::abs(k) > 3 ? 0.0 : std::exp(-k * k / 2.0) / norm; };
  const double src[3] = {0.5, 0.25, 0.125}; // rgb × alpha
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) {
        const double want = w(int(x) - 12) * w(int(y) - 7) * src[c];
        ASSERT_NEAR(glow.at(x, y)[c], want, 1e-6) << x << "," << y << " c" << c;
        ASSERT_NEAR(final_frame.at(x, y)[c], scene.at(x, y)[c] + want, 1e-6);
      }
}

TEST(GlowCpu, OneTexelGlowsAsTheOuterProductOfTheTaps) {
  one_texel_glows_as_the_outer_product(Tier::Dx9);
}
// Tier dx9c: the same blur as one ps_3_0 loop of texldl reads per axis.
TEST(GlowCpu, Dx9cOneTexelGlowsAsTheOuterProductOfTheTaps) {
  one_texel_glows_as_the_outer_product(Tier::Dx9c);
}

} // namespace
} // namespace tierlift::effects
