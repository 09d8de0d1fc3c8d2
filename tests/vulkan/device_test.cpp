// The device itself: creation, the name filter, error reporting, and plain passes whose
// result is known by hand (no shaders: the pass-through programs).
#include <cmath>

#include "run_flags.h"
#include "vk_test_util.h"

namespace tierlift::vulkan::test {
namespace {

TEST_F(VulkanTest, PicksACpuDeviceByDefault) {
  EXPECT_NE(dev->name().find("llvmpipe"), std::string::npos) << dev->name();
  EXPECT_GE(dev->subtexel_bits(), 4u);
}

TEST_F(VulkanTest, UnknownFilterIsAClearError) {
  DeviceOptions o;
  o.gpu_filter = "no-such-gpu-xyz";
  auto d = Device::create(o);
  ASSERT_FALSE(d.ok());
  EXPECT_FALSE(ir::failed_with(d, kNoDeviceRule)); // a device is there, just not that one
  EXPECT_NE(d.message().find("no-such-gpu-xyz"), std::string::npos) << d.message();
}

TEST_F(VulkanTest, FilterSelectsByNameCaseInsensitively) {
  DeviceOptions o;
  o.gpu_filter = "LLVMPIPE";
  auto d = Device::create(o);
  ASSERT_TRUE(d.ok()) << d.message();
  EXPECT_NE((*d)->name().find("llvmpipe"), std::string::npos);
}

// constant_inputs and no pixel program: oD0 passes through to every pixel, quantised by the
// target format. 0.2 and 0.6 are 51 and 153 LSB of RGBA8; 0.3f·255 = 76.500003 is a
// near-tie (lavapipe stores 76, exact rounding 77); 0.3 in RGBA16F lies 0.8 of the way from
// 1228·2^-12 to 1229·2^-12 and Vulkan lets a half store round to nearest or toward zero.
TEST_F(VulkanTest, ConstantColourFillsTheTarget) {
  cpu::Pass p;
  p.constant_inputs.color[0] = {0.2f, 0.6f, 0.3f, 1.0f};
  for (img::Format f : {img::Format::RGBA8, img::Format::RGBA16F, img::Format::RGBA32F}) {
    img::Image t(5, 3, f);
    ir::Result<pass::DrawReport> r = dev->draw(p, t);
    ASSERT_TRUE(r.ok()) << r.message();
    for (uint32_t y = 0; y < 3; ++y)
      for (uint32_t x = 0; x < 5; ++x) {
        const float* px = t.at(x, y);
        if (f == img::Format::RGBA8) {
          EXPECT_EQ(px[0], 51.0f / 255);
          EXPECT_EQ(px[1], 153.0f / 255);
          EXPECT_TRUE(px[2] == 76.0f / 255 || px[2] == 77.0f / 255) << px[2];
        } else if (f == img::Format::RGBA16F) {
          EXPECT_EQ(px[0], 1638.0f / 8192); // 0.2 = 1638.4·2^-13: both rules give 1638
          EXPECT_TRUE(px[1] == 1228.0f / 2048 || px[1] == 1229.0f / 2048) << px[1]; // 1228.8
          EXPECT_TRUE(px[2] == 1228.0f / 4096 || px[2] == 1229.0f / 4096) << px[2];
        } else {
          EXPECT_EQ(px[0], 0.2f);
          EXPECT_EQ(px[1], 0.6f);
          EXPECT_EQ(px[2], 0.3f);
        }
        EXPECT_EQ(px[3], 1.0f);
      }
  }
}

// Blend modes against the stored destination: dst 0.5 everywhere, src (0.25, 0.25, 0.25, 0.5).
TEST_F(VulkanTest, BlendModesUseTheStoredDestination) {
  struct Case {
    cpu::BlendMode mode;
    float rgb, a;
  } cases[] = {
      {cpu::BlendMode::Replace, 0.25f, 0.5f},
      {cpu::BlendMode::OneOne, 0.75f, 1.0f},
      {cpu::BlendMode::SrcAlphaOne, 0.625f, 0.75f},
      {cpu::BlendMode::SrcAlphaInvSrcAlpha, 0.375f, 0.5f},
  };
  for (const Case& c : cases) {
    cpu::Pass p;
    p.blend = c.mode;
    p.constant_inputs.color[0] = {0.25f, 0.25f, 0.25f, 0.5f};
    img::Image t(4, 4, img::Format::RGBA32F);
    for (float& v : t.rgba) v = 0.5f;
    ASSERT_TRUE(dev->draw(p, t).ok());
    EXPECT_EQ(t.at(2, 1)[0], c.rgb) << int(c.mode);
    EXPECT_EQ(t.at(2, 1)[3], c.a) << int(c.mode);
  }
}

// A pre-transformed triangle: the CPU device and Vulkan draw the same pixels (top-left rule,
// both pixel-centre conventions) and the same interpolated colours. The corners lie on the
// 1/256-pixel grid: for off-grid vertices lavapipe interpolates attributes with the unsnapped
// positions while the CPU device uses the snapped ones (differences up to ~1.5e-4 measured
// for a vertex 0.0016 pixel off the grid); coverage uses snapped positions in both.
TEST_F(VulkanTest, TransformedTriangleMatchesTheCpuDevice) {
  cpu::Pass p;
  auto vert = [](float x, float y, cpu::Vec4 c) {
    cpu::VertexOutput v;
    v.pos = {x, y, 0, 1};
    v.color[0] = c;
    return v;
  };
  p.transformed = {vert(-1, 1, {1, 0, 0, 1}), vert(0.25f, 1, {0, 1, 0, 1}),
                   vert(-1, -1, {0, 0, 1, 1})};
  for (auto center : {ir::PixelCenter::D3D9, ir::PixelCenter::Modern}) {
    p.conventions.pixel_center = center;
    TwoWays t = draw_both(*dev, p, 16, 16, img::Format::RGBA32F);
    ASSERT_TRUE(t.ok);
    // Coverage must be identical (alpha 1 inside, 0 outside); colours within float rounding.
    for (uint32_t i = 0; i < 16 * 16; ++i)
      ASSERT_EQ(t.cpu.rgba[i * 4 + 3], t.vk.rgba[i * 4 + 3]) << i;
    EXPECT_LE(t.cmp.max_abs_all, 1e-5) << img::describe(t.cmp);
  }
}

// D3D9 clamps the viewport depth range to [0, 1]; passing 2 straight to Vulkan is a
// validation error (VUID-VkViewport-minDepth-01234), which the fixture would report.
TEST_F(VulkanTest, ViewportDepthRangeIsClamped) {
  cpu::Pass p;
  p.constant_inputs.color[0] = {1, 0, 0, 1};
  p.viewport.min_z = 2.0f;
  p.viewport.max_z = -1.0f;
  img::Image t(4, 4);
  ASSERT_TRUE(dev->draw(p, t).ok());
  EXPECT_EQ(t.at(3, 3)[0], 1.0f);
}

// A D3D9 viewport smaller than the target: only its pixels are drawn, on both devices.
TEST_F(VulkanTest, ViewportLimitsThePixelsDrawn) {
  cpu::Pass p;
  p.constant_inputs.color[0] = {1, 1, 1, 1};
  p.viewport = {3, 2, 5, 4, 0, 1};
  TwoWays t = draw_both(*dev, p, 12, 10, img::Format::RGBA8);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.cmp.identical_pixels, t.cmp.pixels) << img::describe(t.cmp);
  EXPECT_EQ(t.vk.at(3, 2)[0], 1.0f);
  EXPECT_EQ(t.vk.at(7, 5)[0], 1.0f);
  EXPECT_EQ(t.vk.at(8, 5)[0], 0.0f);
  EXPECT_EQ(t.vk.at(7, 6)[0], 0.0f);
  EXPECT_EQ(t.vk.at(2, 2)[0], 0.0f);
}

TEST_F(VulkanTest, BadInputIsAnErrorNotACrash) {
  cpu::Pass p;
  p.transformed.resize(3);
  p.triangles = {{0, 1, 7}};
  img::Image t(4, 4);
  ir::Result<pass::DrawReport> r = dev->draw(p, t);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("out of range"), std::string::npos) << r.message();
  img::Image empty;
  EXPECT_FALSE(dev->draw(p, empty).ok());
  cpu::Pass q;
  q.textures[0].sampler.border_color = {0.5f, 0, 0, 1};
  q.pixel_program =
      parse_listing("ps.2.0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n", "b");
  r = dev->draw(q, t);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("border"), std::string::npos) << r.message();
}

} // namespace
} // namespace tierlift::vulkan::test
