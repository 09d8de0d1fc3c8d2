// Constants whose four components hold the same bits are read as one float and replicated
// (codegen::CodegenOptions::replicated_*_constants, set by the Vulkan device from the bank it
// binds). The image must be the interpreter's, bit for bit, whether or not a constant
// qualifies: replicated weights, weights that differ per channel, zeros of both signs (equal
// as floats, not as bits), NaN and infinities.
#include <cmath>
#include <limits>

#include "resident_fixture.h"
#include "tierlift/cpu/draw.h"

namespace tierlift::vulkan::test {
namespace {

TEST_F(ResidentTest, ReplicatedConstantsGiveTheInterpretersImage) {
  img::Image tex(23, 11, img::Format::RGBA32F);
  for (size_t i = 0; i < tex.rgba.size(); ++i)
    tex.rgba[i] = static_cast<float>((i * 7919) % 1000) / 250.0f - 1.0f; // [-1, 3), zeros too
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<cpu::Vec4> banks[] = {
      {{0.3f, 0.3f, 0.3f, 0.3f}, {0.75f, 0.5f, 0.25f, 1}, {2, 2, 2, 2}},
      {{-0.0f, -0.0f, -0.0f, -0.0f}, {0, -0.0f, 0, 0}, {0.5f, 0.5f, 0.5f, 0.5f}},
      {{nan, nan, nan, nan}, {inf, inf, inf, inf}, {-inf, 1, -inf, 1}},
  };
  // oC0 = tex·c0 + tex·c1 (two taps), then · c2: every component reads every constant.
  const auto ps = parse_listing("ps_2_0\ndcl t0.xy\ndcl t1.xy\ndcl_2d s0\ntexld r0, t0, s0\n"
                                "texld r1, t1, s0\nmul r0, r0, c0\nmad r0, r1, c1, r0\n"
                                "mul r0, r0, c2\nmov oC0, r0\n",
                                "replicated.psh");
  for (const auto& bank : banks) {
    const cpu::Vec4 off{0.5f / tex.width, 0.5f / tex.height, 0, 0};
    cpu::Pass p = quad_pass(two_coords_vs(), ps, {off, {1.5f / tex.width, off[1], 0, 0}}, bank,
                            cpu::BlendMode::Replace);
    p.textures[0].sampler.filter = cpu::Filter::Point;
    const img::Image vk = draw_reading(*dev, tex, img::Format::RGBA32F, p, tex.width, tex.height);
    p.textures[0].image = std::make_shared<img::Image>(tex);
    img::Image cpu(tex.width, tex.height, img::Format::RGBA32F);
    ASSERT_TRUE(cpu::draw(p, cpu, 2).ok());
    std::string where;
    EXPECT_TRUE(same_bits(cpu, vk, &where)) << where;
  }
}

} // namespace
} // namespace tierlift::vulkan::test
