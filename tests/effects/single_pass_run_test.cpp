// run_single_pass (single_pass.h): `tierlift run`'s graph of one pass on the ways asked for;
// graph_draw (run_graph.h): the draw a device is handed for a pass of a graph.
// The pass here has no listings: D3D9's fixed function passes its constant colour (oD0) to
// every pixel, so the expected image is that colour everywhere, known before the run.
#include <gtest/gtest.h>

#include <cstdlib>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/glow/builtin_listing.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/single_pass.h"
#include "tierlift/ir/result_diagnostics.h"

namespace tierlift::effects {
namespace {

constexpr pass::Vec4 kColour{0.25f, 0.5f, 0.75f, 1.0f};

EffectGraph constant_colour_graph(uint32_t w, uint32_t h) {
  pass::Pass p;
  p.constant_inputs.color[0] = kColour;
  ir::Result<EffectGraph> g = single_pass_graph(p, w, h, img::Format::RGBA32F);
  EXPECT_TRUE(g) << g.message();
  return g ? *g : EffectGraph{};
}

BackendChoice ways(const char* text) {
  ir::Result<BackendChoice> b = parse_backends(text, {"cpu", "vulkan"});
  EXPECT_TRUE(b) << b.message();
  return b ? *b : BackendChoice{};
}

TEST(SinglePassRun, TheCpuDrawsTheConstantColourEverywhere) {
  ir::Result<SinglePassRun> run = run_single_pass(constant_colour_graph(5, 3), ways("cpu"), {}, 1);
  ASSERT_TRUE(run) << run.message();
  ASSERT_EQ(run->draws.size(), 1u);
  const SinglePassDraw& d = run->draws[0];
  EXPECT_EQ(d.device, "cpu");
  ASSERT_EQ(d.image.width, 5u);
  ASSERT_EQ(d.image.height, 3u);
  for (size_t i = 0; i < d.image.rgba.size(); ++i) ASSERT_EQ(d.image.rgba[i], kColour[i % 4]) << i;
  EXPECT_EQ(d.report.pixels_shaded, 15u);
  EXPECT_FALSE(run->agreement); // one way: nothing to compare
  EXPECT_TRUE(run->vulkan_device.empty());
}

// run_graph_reading reads back only the textures it is asked for (the corpus's differential
// run: its target, not the inputs it uploaded); run_graph reads back every texture.
class CountingReads final : public PassDevice {
public:
  std::string name() const override { return "counting"; }
  ir::Status begin_run(const EffectGraph& g, const ImageMap& in) override {
    return cpu_.begin_run(g, in);
  }
  ir::Result<pass::DrawReport> draw(const PassDesc& p) override { return cpu_.draw(p); }
  ir::Result<img::Image> read_texture(const std::string& name) override {
    read.push_back(name);
    return cpu_.read_texture(name);
  }
  std::vector<std::string> read;

private:
  CpuPassDevice cpu_{1};
};

TEST(SinglePassRun, RunGraphReadingReadsBackOnlyWhatItIsAsked) {
  EffectGraph g = constant_colour_graph(2, 2);
  g.textures.push_back({"unused_input", 2, 2, img::Format::RGBA32F, true});
  const std::string target(kSinglePassTarget);
  CountingReads all, one;
  ImageMap in_all{{"unused_input", img::Image(2, 2, img::Format::RGBA32F)}}, in_one = in_all;
  ASSERT_TRUE(run_graph(g, all, in_all));
  ASSERT_TRUE(run_graph_reading(g, one, in_one, {target}));
  EXPECT_EQ(all.read.size(), g.textures.size()); // every texture, the input too
  EXPECT_EQ(one.read, std::vector<std::string>{target});
  ASSERT_TRUE(in_one.contains(target));
  EXPECT_EQ(in_one.at(target).rgba, in_all.at(target).rgba); // the same image
  EXPECT_EQ(in_one.at(target).rgba[1], kColour[1]);
}

TEST(SinglePassRun, FailuresNameTheirRule) {
  // The refused run creates and destroys a Vulkan instance; a device the program keeps
  // (vk_test_util.h) keeps lavapipe loaded, so LeakSanitizer can still name the driver's
  // lifetime allocations (tests/lsan.supp) instead of an "<unknown module>".
  (void)vulkan::test::program_device({});
  vulkan::DeviceOptions nowhere;
  nowhere.gpu_filter = "no device is called this";
  ir::Result<SinglePassRun> no_device =
      run_single_pass(constant_colour_graph(4, 4), ways("vulkan"), nowhere, 1);
  ASSERT_FALSE(no_device);
  EXPECT_TRUE(ir::failed_with(no_device, "device")) << no_device.message();

  ASSERT_EQ(setenv("TIERLIFT_MEMORY_LIMIT", "1048576", 1), 0); // 1 MiB: below the program
  ir::Result<SinglePassRun> too_big =
      run_single_pass(constant_colour_graph(4, 4), ways("cpu"), {}, 1);
  unsetenv("TIERLIFT_MEMORY_LIMIT");
  ASSERT_FALSE(too_big);
  EXPECT_TRUE(ir::failed_with(too_big, "memory")) << too_big.message();
}

// The draw a device is handed for a pass of a graph is the pass's own draw — banks (c#, i#,
// b#) and each stage's sampler state as given — with what the graph decides put in (its
// conventions, one colour target per named target) and no image, however many stages are
// bound: the device that owns the textures binds its own (no copy, no placeholder).
TEST(GraphDraw, IsThePassesDrawWithWhatTheGraphDecides) {
  PassDesc d;
  d.name = "p";
  d.target = "t";
  d.more_targets = {"u", "v"};
  d.draw.ps_constants.f = {{1, 2, 3, 4}};
  d.draw.ps_constants.i[3] = {5, 6, 7, 8};
  d.draw.vs_constants.b[2] = true;
  pass::SamplerState linear;
  linear.filter = pass::Filter::Linear;
  linear.address_u = pass::AddressMode::Clamp;
  bind_reads(d, 2, "a", linear, 1, false);
  d.textures.push_back({5, "a"});
  ir::Conventions conventions;
  conventions.subtexel_bits = 4;
  const pass::Pass p = graph_draw(d, conventions);
  EXPECT_EQ(p.ps_constants.f.at(0)[3], 4.0f);
  EXPECT_EQ(p.ps_constants.i[3][1], 6);
  EXPECT_TRUE(p.vs_constants.b[2]);
  EXPECT_EQ(p.textures[2].sampler.filter, pass::Filter::Linear);
  EXPECT_EQ(p.textures[2].sampler.address_u, pass::AddressMode::Clamp);
  EXPECT_EQ(p.textures[5].sampler.filter, pass::Filter::Point);
  for (const pass::TextureBinding& b : p.textures) EXPECT_EQ(b.image, nullptr);
  EXPECT_EQ(p.color_targets, 3u);
  EXPECT_EQ(p.conventions.subtexel_bits, 4);
  EXPECT_TRUE(p.vertices.empty()); // no vertex listing: the quad with constant inputs
}

// A vertex listing without vertices draws the full-screen quad: the corners (−1, 1) … (1, −1)
// at its dcl_position input (v0), the uv (0, 0) … (1, 1) at its dcl_texcoord input (v3).
TEST(GraphDraw, AVertexListingWithoutVerticesDrawsTheQuad) {
  ListingResult vs = builtin_listing("glow/quad4_coords.vsh");
  ASSERT_TRUE(vs) << vs.message();
  PassDesc d;
  d.draw.vertex_program = *vs;
  const pass::Pass p = graph_draw(d, {});
  ASSERT_EQ(p.vertices.size(), 4u);
  EXPECT_EQ(p.vertices[0].v[0], (pass::Vec4{-1, 1, 0, 1}));
  EXPECT_EQ(p.vertices[3].v[0], (pass::Vec4{1, -1, 0, 1}));
  EXPECT_EQ(p.vertices[3].v[3], (pass::Vec4{1, 1, 0, 1}));
  ASSERT_EQ(p.triangles.size(), 2u);
}

} // namespace
} // namespace tierlift::effects
