// `tierlift run`'s path: a prepared pass (pass::prepare_pass) as a graph of one pass
// (single_pass_graph), run by run_graph on the effect devices. Each device must draw the
// same bits as a direct draw of the prepared pass (cpu::draw, vulkan::Device::draw) and
// report the same counters; the graph rules take the listing-less forms `tierlift run`
// draws and nothing else.
#include <gtest/gtest.h>

#include <cstring>

#include "../vulkan/vk_test_util.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/graph/single_pass.h"
#include "tierlift/pass/setup.h"

namespace tierlift::effects {
namespace {

using vulkan::test::gpugems_listing;
using vulkan::test::parse_listing;

// Listings 3 + 4 over one noise texture bound to all four stages (as `tierlift run` binds
// one --texture source given four times), linear, clamped.
pass::RunRequest blur_request(img::Format format) {
  pass::RunRequest r;
  r.vs = gpugems_listing("listing3_blur4_coords.vsh");
  r.ps = gpugems_listing("listing4_blur4_weighted_sum.psh");
  r.width = 29;
  r.height = 23;
  r.format = format;
  for (uint32_t k = 0; k < 4; ++k) {
    const float dx = (float(k) + 0.5f) / 31.0f;
    r.constants.push_back({pass::StageMask::Vertex, ir::RegFile::Const, k, {dx, 0.03125f, 0, 0}});
    r.constants.push_back(
        {pass::StageMask::Pixel, ir::RegFile::Const, k, {0.25f, 0.25f, 0.25f, 0.25f}});
    r.textures.push_back({k, "builtin:noise:31x17"});
  }
  r.attrs.push_back({ir::RegFile::Input, 3, {0, 0, 0, 1}, true});
  r.filter = pass::Filter::Linear;
  r.address = pass::AddressMode::Clamp;
  return r;
}

// A vs_2_0 listing whose colour depends on i0 (a rep count) and b0 (an if).
const char* kFlowVs = "vs_2_0\n"
                      "dcl_position v0\n"
                      "dcl_texcoord v3\n"
                      "mov oPos, v0\n"
                      "mov r0, c10\n"
                      "rep i0\n"
                      "add r0, r0, c1\n"
                      "endrep\n"
                      "if b0\n"
                      "add r0, r0, c2\n"
                      "endif\n"
                      "mul oD0, r0, v3.x\n";

pass::RunRequest flow_request(int32_t reps, bool branch) {
  pass::RunRequest r;
  r.vs = parse_listing(kFlowVs, "flow.vsh");
  r.width = 17;
  r.height = 9;
  r.format = img::Format::RGBA32F;
  r.constants.push_back({pass::StageMask::Vertex, ir::RegFile::Const, 10, {0.1f, 0, 0, 1}});
  r.constants.push_back({pass::StageMask::Vertex, ir::RegFile::Const, 1, {0.05f, 0.1f, 0, 0}});
  r.constants.push_back({pass::StageMask::Vertex, ir::RegFile::Const, 2, {0, 0, 0.5f, 0}});
  pass::ConstSetting i0{pass::StageMask::Vertex, ir::RegFile::ConstInt, 0};
  i0.i = {reps, 0, 1, 0};
  pass::ConstSetting b0{pass::StageMask::Vertex, ir::RegFile::ConstBool, 0};
  b0.b = branch;
  r.constants.push_back(i0);
  r.constants.push_back(b0);
  r.attrs.push_back({ir::RegFile::Input, 3, {0, 0, 0, 1}, true});
  return r;
}

pass::Pass prepare(const pass::RunRequest& r) {
  ir::Result<pass::Pass> p = pass::prepare_pass(r);
  EXPECT_TRUE(p) << p.message();
  return p ? std::move(p).value() : pass::Pass{};
}

struct GraphDraw {
  img::Image image;
  PassRecord record;
};

GraphDraw run_single(PassDevice& device, const pass::Pass& p, const pass::RunRequest& r) {
  ir::Result<EffectGraph> graph = single_pass_graph(p, r.width, r.height, r.format);
  EXPECT_TRUE(graph) << graph.message();
  if (!graph) return {};
  ImageMap images;
  ir::Result<GraphRun> run = run_graph(*graph, device, images);
  EXPECT_TRUE(run) << run.message();
  if (!run) return {};
  return {images.at(std::string(kSinglePassTarget)), run->passes.at(0)};
}

void expect_same_bits(const img::Image& a, const img::Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(0, std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)));
}

TEST(SinglePassGraph, OneTexturePerImageAndTheRequestsTarget) {
  const pass::RunRequest r = blur_request(img::Format::RGBA8);
  const pass::Pass p = prepare(r);
  ir::Result<EffectGraph> g = single_pass_graph(p, r.width, r.height, r.format);
  ASSERT_TRUE(g) << g.message();
  ASSERT_EQ(g->textures.size(), 2u); // the noise once, bound four times; the target
  EXPECT_EQ(g->textures[0].name, "s0");
  EXPECT_TRUE(g->textures[0].input);
  EXPECT_EQ(g->textures[0].contents.get(), p.textures[0].image.get()); // shared, not copied
  EXPECT_EQ(g->textures[0].format, p.textures[0].image->format);
  const TextureDesc* target = g->find_texture(kSinglePassTarget);
  ASSERT_NE(target, nullptr);
  EXPECT_EQ(target->width, r.width);
  EXPECT_EQ(target->format, img::Format::RGBA8);
  ASSERT_EQ(g->passes.size(), 1u);
  EXPECT_EQ(g->passes[0].textures.size(), 4u);
  EXPECT_EQ(g->passes[0].draw.vertices.size(), 4u); // the quad's corners with --attr's uv
  // The pass is the draw itself, moved in: the same listings; its images left it for the
  // graph's textures, which the device binds by name.
  EXPECT_EQ(g->passes[0].draw.pixel_program.get(), p.pixel_program.get());
  for (const pass::TextureBinding& b : g->passes[0].draw.textures) EXPECT_EQ(b.image, nullptr);
  EXPECT_TRUE(check_graph(*g));
}

TEST(SinglePassGraph, CpuDeviceDrawsWhatCpuDrawDraws) {
  for (img::Format f : {img::Format::RGBA8, img::Format::RGBA16F, img::Format::RGBA32F}) {
    const pass::RunRequest r = blur_request(f);
    const pass::Pass p = prepare(r);
    img::Image direct(r.width, r.height, r.format);
    const ir::Result<cpu::DrawStats> stats = cpu::draw(p, direct, 2);
    ASSERT_TRUE(stats.ok()) << stats.message();
    CpuPassDevice device(2);
    const GraphDraw g = run_single(device, p, r);
    expect_same_bits(g.image, direct);
    EXPECT_EQ(g.record.report.pixels_shaded, stats->pixels_shaded);
    EXPECT_EQ(g.record.report.pixels_shaded, uint64_t{r.width} * r.height);
    EXPECT_TRUE(g.record.warnings.empty());
  }
}

TEST(SinglePassGraph, IntegerAndBooleanConstantsReachTheDevice) {
  img::Image images[2];
  for (int k = 0; k < 2; ++k) {
    const pass::RunRequest r = flow_request(3, k == 1);
    const pass::Pass p = prepare(r);
    img::Image direct(r.width, r.height, r.format);
    ASSERT_TRUE(cpu::draw(p, direct, 1).ok());
    CpuPassDevice device(1);
    images[k] = run_single(device, p, r).image;
    expect_same_bits(images[k], direct);
  }
  EXPECT_NE(images[0].rgba, images[1].rgba); // b0 took the branch
}

TEST(SinglePassGraph, WithoutListingsTheQuadCarriesTheInputs) {
  pass::RunRequest r;
  r.width = 3;
  r.height = 2;
  r.format = img::Format::RGBA32F;
  r.inputs.push_back({ir::RegFile::Input, 0, {1, 0.5f, 0.25f, 1}});
  const pass::Pass p = prepare(r);
  CpuPassDevice device;
  const GraphDraw g = run_single(device, p, r);
  ASSERT_EQ(g.image.width, 3u);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(g.image.at(2, 1)[c], r.inputs[0].value[c]);
  EXPECT_EQ(g.record.report.pixels_shaded, 6u);
}

TEST(SinglePassGraph, NothingDrawnIsAWarningOfThePass) {
  pass::RunRequest r;
  r.vs = parse_listing("vs_2_0\ndcl_position v0\nmov oPos, c0\nmov oD0, c1\n", "degenerate.vsh");
  r.width = r.height = 4;
  r.constants.push_back({pass::StageMask::Vertex, ir::RegFile::Const, 0, {0, 0, 0, 0}});
  r.constants.push_back({pass::StageMask::Vertex, ir::RegFile::Const, 1, {1, 1, 1, 1}});
  CpuPassDevice device;
  const GraphDraw g = run_single(device, prepare(r), r);
  ASSERT_EQ(g.record.warnings.size(), 1u);
  EXPECT_EQ(g.record.warnings[0].rule, "nothing-drawn");
  EXPECT_EQ(g.record.report.pixels_shaded, 0u);
}

TEST(SinglePassGraph, RefusesWhatAPassDescCannotCarry) {
  const pass::RunRequest r = blur_request(img::Format::RGBA32F);
  pass::Pass mrt = prepare(r);
  mrt.color_targets = 5; // D3D9 has four
  pass::Pass transformed = prepare(r);
  transformed.transformed.resize(3);
  for (const pass::Pass* p : {&mrt, &transformed}) {
    ir::Result<EffectGraph> g = single_pass_graph(*p, 4, 4, img::Format::RGBA32F);
    ASSERT_FALSE(g);
    EXPECT_EQ(g.diagnostics()[0].rule, "graph");
  }
}

// A pass with n colour targets (MRT, `run --output1..3`) gets n − 1 more targets of the
// target's size and format, named target1 …, drawn into by the one pass.
TEST(SinglePassGraph, CarriesFurtherColourTargets) {
  const pass::RunRequest r = blur_request(img::Format::RGBA32F);
  pass::Pass mrt = prepare(r);
  mrt.color_targets = 3;
  ir::Result<EffectGraph> g = single_pass_graph(mrt, 4, 2, img::Format::RGBA16F);
  ASSERT_TRUE(g) << g.message();
  ASSERT_EQ(g->passes[0].more_targets, (std::vector<std::string>{"target1", "target2"}));
  for (const char* name : {"target1", "target2"}) {
    const TextureDesc* t = g->find_texture(name);
    ASSERT_NE(t, nullptr) << name;
    EXPECT_EQ(t->width, 4u);
    EXPECT_EQ(t->height, 2u);
    EXPECT_EQ(t->format, img::Format::RGBA16F);
  }
}

// Texture-stage state (texbem's bump matrix, `run --bump-matrix`) stays with the draw's stage.
TEST(SinglePassGraph, CarriesTextureStageState) {
  const pass::RunRequest r = blur_request(img::Format::RGBA32F);
  pass::Pass stage = prepare(r);
  stage.textures[1].stage.projected = true;
  stage.textures[1].stage.bumpenv_mat = {0.5f, -0.25f, 0.125f, 2.0f};
  ir::Result<EffectGraph> g = single_pass_graph(stage, 4, 4, img::Format::RGBA32F);
  ASSERT_TRUE(g) << g.message();
  bool found = false;
  for (const TextureBind& b : g->passes[0].textures) {
    if (b.stage != 1) continue;
    found = true;
    EXPECT_TRUE(g->passes[0].binding(b).stage.projected);
    EXPECT_EQ(g->passes[0].binding(b).stage.bumpenv_mat,
              (std::array<float, 4>{0.5f, -0.25f, 0.125f, 2.0f}));
  }
  EXPECT_TRUE(found);
}

// check_graph takes a missing listing only in the forms the devices draw.
TEST(SinglePassGraph, ListingLessFormsInTheGraphRules) {
  pass::RunRequest r;
  r.inputs.push_back({ir::RegFile::Input, 0, {1, 1, 1, 1}});
  ir::Result<EffectGraph> base = single_pass_graph(prepare(r), 4, 4, img::Format::RGBA32F);
  ASSERT_TRUE(base);
  EXPECT_TRUE(check_graph(*base)); // neither listing: constant inputs, oD0 passes through
  auto refused = [&](auto change, std::string_view why) {
    EffectGraph g = *base;
    change(g.passes[0]);
    ir::Status s = check_graph(g);
    ASSERT_FALSE(s) << why;
    EXPECT_NE(s.message().find(why), std::string::npos) << s.message();
  };
  refused([](PassDesc& p) { p.draw.vertices.resize(3); }, "vertices without a vertex listing");
  refused([](PassDesc& p) { p.more_targets = {"target2"}; }, "need a pixel listing");
  // What the graph decides itself, or no graph device draws.
  refused([](PassDesc& p) { p.draw.transformed.resize(3); }, "pre-transformed vertices");
  refused([](PassDesc& p) { p.draw.viewport.width = 2; }, "a viewport other than");
  refused([](PassDesc& p) { p.draw.color_targets = 2; }, "2 colour targets counted");
  refused([](PassDesc& p) { p.draw.executor = pass::Executor::Scalar; }, "the scalar executor");
}

TEST(SinglePassGraph, AnalyticDeviceRefusesWhatItDoesNotModel) {
  pass::RunRequest r;
  r.inputs.push_back({ir::RegFile::Input, 0, {1, 1, 1, 1}});
  ir::Result<EffectGraph> g = single_pass_graph(prepare(r), 4, 4, img::Format::RGBA32F);
  ASSERT_TRUE(g);
  std::unique_ptr<PassDevice> analytic = make_analytic_pass_device();
  ImageMap images;
  ir::Result<GraphRun> run = run_graph(*g, *analytic, images);
  ASSERT_FALSE(run);
  EXPECT_NE(run.message().find("needs a vertex and a pixel listing"), std::string::npos);

  const pass::RunRequest flow = flow_request(2, true);
  ir::Result<EffectGraph> fg =
      single_pass_graph(prepare(flow), flow.width, flow.height, flow.format);
  ASSERT_TRUE(fg);
  fg->passes[0].draw.pixel_program = gpugems_listing("listing4_blur4_weighted_sum.psh");
  ir::Result<GraphRun> frun = run_graph(*fg, *analytic, images);
  ASSERT_FALSE(frun);
  EXPECT_NE(frun.message().find("no integer or boolean constants"), std::string::npos)
      << frun.message();
}

// A device's refusal reaches run_graph's caller twice: in the run's summary and, as notes,
// in the device's own words (what `tierlift run` prints).
TEST(SinglePassGraph, RunFailureKeepsTheDevicesOwnWords) {
  class Refusing final : public PassDevice {
  public:
    std::string name() const override { return "refusing"; }
    ir::Status begin_run(const EffectGraph&, const ImageMap&) override { return ir::ok_status(); }
    ir::Result<pass::DrawReport> draw(const PassDesc&) override {
      return device_error("no such thing");
    }
    ir::Result<img::Image> read_texture(const std::string&) override { return img::Image(); }
  };
  pass::RunRequest r;
  r.inputs.push_back({ir::RegFile::Input, 0, {1, 1, 1, 1}});
  ir::Result<EffectGraph> g = single_pass_graph(prepare(r), 4, 4, img::Format::RGBA32F);
  ASSERT_TRUE(g);
  Refusing device;
  ImageMap images;
  ir::Result<GraphRun> run = run_graph(*g, device, images);
  ASSERT_FALSE(run);
  EXPECT_EQ(run.message(), "pass 'run' on refusing: no such thing");
  ASSERT_EQ(run.diagnostics().size(), 2u);
  const ir::Diagnostic& cause = run.diagnostics()[1];
  EXPECT_EQ(cause.severity, ir::Severity::Note);
  EXPECT_EQ(cause.subject, "refusing");
  EXPECT_EQ(cause.message, "no such thing");
}

using SinglePassVulkan = vulkan::test::VulkanTest;

// The Vulkan device through the graph (resident textures, TextureSet) draws what
// Device::draw draws from the prepared pass's host images, bit for bit.
TEST_F(SinglePassVulkan, DrawsWhatDeviceDrawDraws) {
  std::vector<pass::RunRequest> requests = {
      blur_request(img::Format::RGBA8), blur_request(img::Format::RGBA16F), flow_request(2, true)};
  pass::RunRequest inputs;
  inputs.width = 5;
  inputs.height = 3;
  inputs.format = img::Format::RGBA8;
  inputs.inputs.push_back({ir::RegFile::Input, 0, {0.3f, 0.5f, 0.25f, 1}});
  requests.push_back(inputs);
  for (const pass::RunRequest& r : requests) {
    const pass::Pass p = prepare(r);
    img::Image direct(r.width, r.height, r.format);
    const ir::Result<pass::DrawReport> drawn = dev->draw(p, direct);
    ASSERT_TRUE(drawn.ok()) << drawn.message();
    std::unique_ptr<PassDevice> device = make_vulkan_pass_device(*dev);
    const GraphDraw g = run_single(*device, p, r);
    expect_same_bits(g.image, direct);
    EXPECT_EQ(g.record.report.pixels_shaded, 0u); // the GPU counts nothing
  }
}

} // namespace
} // namespace tierlift::effects
