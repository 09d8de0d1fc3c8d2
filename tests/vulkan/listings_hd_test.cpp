// NOT TIMED, but slow (~2–4 s): Listings 1+2 (8 bilinear taps of seeded noise) at 1280×720,
// a size where u = i/1280 is not a float. The CPU device, with its default
// ir::Rounding::Llvmpipe, must meet docs/design.md's agreement targets against lavapipe there too:
// RGBA32F max abs ≤ 1e-5; RGBA8 at most 1 LSB apart and ≥ 99.9 % of pixels identical; with
// and without the half-texel offset, with D3D9 and modern pixel centres. (With
// Rounding::Exact the same pass missed them: 7.5e-5 and 99.50 % at 1920×1080.) The CPU device
// samples with subtexel_bits = 0: lavapipe weights float textures with full float fractions,
// whatever subTexelPrecisionBits it reports.
#include <fmt/format.h>

#include "vk_test_util.h"

namespace tierlift::vulkan::test {
namespace {

// Tap k at ((k − 4 + half)/W, half/H), weights (8 − k)/36 (a falling ramp summing to 1),
// bilinear, clamp, noise the size of the target.
cpu::Pass listing12_pass(uint32_t w, uint32_t h, double half, ir::PixelCenter centre) {
  cpu::Pass p;
  p.vertex_program = gpugems_listing("listing1_blur8_coords.vsh");
  p.pixel_program = gpugems_listing("listing2_blur8_weighted_sum.psh");
  cpu::set_full_screen_quad(p, 0);
  for (size_t k = 0; k < p.vertices.size(); ++k) p.vertices[k].v[3] = cpu::kQuadUV[k];
  for (int k = 0; k < 8; ++k) {
    p.vs_constants.f.push_back({float((k - 4 + half) / w), float(half / h), 0, 0});
    const float wk = float((8 - k) / 36.0);
    p.ps_constants.f.push_back({wk, wk, wk, wk});
  }
  p.textures[0].image = std::make_shared<const img::Image>(img::builtin_noise(w, h, 7));
  p.textures[0].sampler.filter = cpu::Filter::Linear;
  p.textures[0].sampler.address_u = p.textures[0].sampler.address_v = cpu::AddressMode::Clamp;
  p.conventions.pixel_center = centre;
  p.conventions.subtexel_bits = 0;
  p.conventions.rounding = ir::Rounding::Llvmpipe;
  return p;
}

struct HdCase {
  uint32_t w, h;
  double half;
  img::Format format;
  ir::PixelCenter centre;
};

class ListingsHd : public VulkanTest, public ::testing::WithParamInterface<HdCase> {};

TEST_P(ListingsHd, MeetTheAgreementTargets) {
  const HdCase c = GetParam();
  cpu::Pass pass = listing12_pass(c.w, c.h, c.half, c.centre);
  ASSERT_TRUE(pass.vertex_program && pass.pixel_program);
  TwoWays t = draw_both(*dev, pass, c.w, c.h, c.format);
  ASSERT_TRUE(t.ok);
  if (c.format == img::Format::RGBA32F) {
    EXPECT_LE(t.cmp.max_abs_all, 1e-5) << img::describe(t.cmp);
  } else {
    EXPECT_LE(t.cmp.max_abs_all, 1.0 / 255 + 1e-7) << img::describe(t.cmp);
    EXPECT_GE(t.cmp.identical_share, 0.999) << img::describe(t.cmp);
  }
  report(fmt::format("listings 1+2 {}x{} {} {} {}", c.w, c.h, c.half ? "half-texel" : "no-offset",
                     c.centre == ir::PixelCenter::D3D9 ? "d3d9" : "modern",
                     img::format_name(c.format)),
         t.cmp);
  EXPECT_GT(t.vk.at(c.w / 2, c.h / 2)[0], 0.0f); // something was drawn
}

// How a case prints in test listings (GetParam): "1280x720, half-texel offset, D3D9
// centres, rgba32f".
void PrintTo(const HdCase& c, std::ostream* os) {
  *os << c.w << "x" << c.h << (c.half != 0 ? ", half-texel offset, " : ", no offset, ")
      << (c.centre == ir::PixelCenter::D3D9 ? "D3D9" : "modern") << " centres, "
      << img::format_name(c.format);
}

INSTANTIATE_TEST_SUITE_P(
    Slow720p, ListingsHd,
    ::testing::Values(HdCase{1280, 720, 0.5, img::Format::RGBA32F, ir::PixelCenter::D3D9},
                      HdCase{1280, 720, 0.0, img::Format::RGBA32F, ir::PixelCenter::D3D9},
                      HdCase{1280, 720, 0.5, img::Format::RGBA8, ir::PixelCenter::D3D9},
                      HdCase{1280, 720, 0.0, img::Format::RGBA8, ir::PixelCenter::D3D9},
                      HdCase{1280, 720, 0.5, img::Format::RGBA32F, ir::PixelCenter::Modern},
                      HdCase{1280, 720, 0.5, img::Format::RGBA8, ir::PixelCenter::Modern}),
    [](const ::testing::TestParamInfo<HdCase>& info) {
      return fmt::format("Listings1and2_{}x{}_{}_{}_{}", info.param.w, info.param.h,
                         info.param.half ? "HalfTexel" : "NoOffset",
                         info.param.centre == ir::PixelCenter::D3D9 ? "D3D9" : "Modern",
                         img::format_name(info.param.format));
    });

} // namespace
} // namespace tierlift::vulkan::test
