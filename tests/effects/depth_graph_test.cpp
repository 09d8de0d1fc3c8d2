// A depth buffer in an effect graph (TextureDesc::depth, PassDesc::depth; NUMERICS.md D1-D5):
// single_pass_graph carries one for a pass with a depth state, the CPU device starts it at the
// clear value or the given image and hands it back with the depth in red, and check_graph
// refuses a depth state and a depth texture that do not go together.
#include <gtest/gtest.h>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/single_pass.h"

namespace tierlift::effects {
namespace {

using vulkan::test::parse_listing;

// oDepth = 0.5 over a 4x1 quad, colour 1, under `func`.
pass::Pass half_depth(pass::CompareFunc func) {
  pass::Pass p;
  p.vertex_program = parse_listing("vs_2_0\ndcl_position v0\nmov oPos, v0\n", "pos.vsh");
  p.pixel_program = parse_listing(
      "ps_2_0\ndef c0, 0.5, 1, 1, 1\ndef c1, 1, 1, 1, 1\nmov oC0, c1\nmov oDepth, c0.x\n", "z.psh");
  pass::set_full_screen_quad(p, 0);
  p.depth_stencil.depth_test = true;
  p.depth_stencil.depth_write = true;
  p.depth_stencil.depth_func = func;
  return p;
}

// Starting from 0.25, 0.75, 0.25, 0.75 (--depth-in), LESS lets columns 1 and 3 through (0.5 <
// 0.75): the buffer becomes 0.25, 0.5, 0.25, 0.5 and the colour 0, 1, 0, 1.
TEST(DepthGraph, SinglePassCarriesTheDepthBuffer) {
  auto start = std::make_shared<img::Image>(4, 1);
  for (uint32_t x = 0; x < 4; ++x) start->at(x, 0)[0] = x % 2 ? 0.75f : 0.25f;
  ir::Result<EffectGraph> g = single_pass_graph(half_depth(pass::CompareFunc::Less), 4, 1,
                                                img::Format::RGBA32F, {0.0f, start});
  ASSERT_TRUE(g) << g.message();
  const TextureDesc* z = g->find_texture(kSinglePassDepth);
  ASSERT_NE(z, nullptr);
  EXPECT_TRUE(z->depth);
  EXPECT_EQ(g->passes[0].depth, kSinglePassDepth);
  CpuPassDevice cpu(1);
  ImageMap images;
  ir::Result<GraphRun> run = run_graph(*g, cpu, images);
  ASSERT_TRUE(run) << run.message();
  const img::Image& depth = images.at(std::string(kSinglePassDepth));
  const img::Image& color = images.at(std::string(kSinglePassTarget));
  for (uint32_t x = 0; x < 4; ++x) {
    EXPECT_EQ(depth.at(x, 0)[0], x % 2 ? 0.5f : 0.25f) << x;
    EXPECT_EQ(color.at(x, 0)[0], x % 2 ? 1.0f : 0.0f) << x;
  }
  // Without an image: the clear value everywhere, so GREATER against 0.25 passes them all.
  g = single_pass_graph(half_depth(pass::CompareFunc::Greater), 4, 1, img::Format::RGBA32F,
                        {0.25f, nullptr});
  ASSERT_TRUE(g) << g.message();
  ImageMap cleared;
  ASSERT_TRUE(run_graph(*g, cpu, cleared));
  for (uint32_t x = 0; x < 4; ++x)
    EXPECT_EQ(cleared.at(std::string(kSinglePassDepth)).at(x, 0)[0], 0.5f) << x;
}

TEST(DepthGraph, CheckGraphRefusesMismatchedDepth) {
  ir::Result<EffectGraph> g =
      single_pass_graph(half_depth(pass::CompareFunc::Less), 4, 1, img::Format::RGBA32F);
  ASSERT_TRUE(g) << g.message();
  auto refused = [](const EffectGraph& graph, const char* why) {
    ir::Status s = check_graph(graph);
    EXPECT_FALSE(s) << why;
    if (!s) {
      EXPECT_NE(s.message().find(why), std::string::npos) << s.message();
    }
  };
  EffectGraph no_texture = *g;
  no_texture.passes[0].depth.clear();
  refused(no_texture, "a depth state without a depth texture");
  EffectGraph no_state = *g;
  no_state.passes[0].draw.depth_stencil = {};
  refused(no_state, "a depth texture without a depth state");
  EffectGraph colour = *g;
  colour.passes[0].depth = std::string(kSinglePassTarget);
  refused(colour, "is not a depth texture");
  EffectGraph sampled = *g;
  sampled.passes[0].textures.push_back({0, std::string(kSinglePassDepth)});
  refused(sampled, "samples the depth texture");
  auto small = std::make_shared<img::Image>(3, 1);
  EXPECT_FALSE(single_pass_graph(half_depth(pass::CompareFunc::Less), 4, 1, img::Format::RGBA32F,
                                 {1.0f, small}));
}

} // namespace
} // namespace tierlift::effects
