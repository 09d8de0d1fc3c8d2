// What the Vulkan device tells the code generator about the constants it binds:
// * codegen::CodegenOptions::known_*_constants: a constant whose four components hold
//   the same bits is read as one float and replicated;
// * the same known constants: in a product with a constant none of whose
//   components is ±0 or a denormal, the "0 × anything = +0" rule tests only the other factor;
// * ir::zero_constant_products: a product with a constant that is ±0 where the result is kept
//   reads nothing else, and what fed only it is pruned.
// The image must be the interpreter's, bit for bit, whether or not a constant qualifies:
// replicated weights, weights that differ per channel, zeros of both signs (equal as floats,
// not as bits), denormals (zeros to lavapipe and to the interpreter's default rounding),
// NaN and infinities, against texels that are zeros of both signs, denormals, tiny values
// whose products underflow, NaN and infinities.
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
    const auto [cpu, vk] = draw_both_ways(*dev, tex, ps, bank);
    std::string where;
    EXPECT_TRUE(same_bits(cpu, vk, &where)) << where;
  }
}

// Bit for bit, except that any NaN matches any NaN: lavapipe's compiler moves a negation past
// a product (a × −b becomes −(a × b)), which flips the sign of a NaN the product passes on;
// the interpreter negates first. Zeros still compare by their bits.
bool same_bits_but_nan_signs(img::Image a, img::Image b, std::string* where) {
  for (img::Image* im : {&a, &b})
    for (float& x : im->rgba)
      if (std::isnan(x)) x = std::numeric_limits<float>::quiet_NaN();
  return same_bits(a, b, where);
}

TEST_F(ResidentTest, NonZeroConstantsKeepTheZeroRule) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float specials[] = {0.0f, -0.0f, 1e-39f, -1e-39f, 1e-30f, -1e-30f, nan, inf, -inf, 0.75f};
  img::Image tex(17, 9, img::Format::RGBA32F);
  for (size_t i = 0; i < tex.rgba.size(); ++i)
    tex.rgba[i] = specials[(i * 7) % std::size(specials)];
  const std::vector<cpu::Vec4> banks[] = {
      // Every constant qualifies; products with the tiny texels underflow to zeros of their sign.
      {{1e-10f, 1e-10f, 1e-10f, 1e-10f}, {-3, 0.5f, -1e-38f, 2}, {inf, -inf, nan, 1}},
      // None qualifies: a zero or a denormal component in each.
      {{0.5f, 0, 1, 2}, {1e-40f, 1e-40f, 1e-40f, 1e-40f}, {-0.0f, 1, 1, 1}},
      // Zero factors (ir::zero_constant_products: the first texture read is then dead).
      {{0, -0.0f, 0, -0.0f}, {-0.0f, 0, 0, 0}, {0.5f, 2, 1, 3}},
  };
  // Products with the constant second, negated and swizzled, first, and in a dot product.
  const auto ps = parse_listing("ps_2_0\ndcl t0.xy\ndcl t1.xy\ndcl_2d s0\ntexld r0, t0, s0\n"
                                "texld r1, t1, s0\nmul r0, r0, c0\nmad r0, r1, -c1.yzxw, r0\n"
                                "mul r0, c2, r0\ndp3 r2.x, r1, c1\nadd r0.y, r0.y, r2.x\n"
                                "mov oC0, r0\n",
                                "nonzero.psh");
  for (const auto& bank : banks) {
    const auto [cpu, vk] = draw_both_ways(*dev, tex, ps, bank);
    std::string where;
    EXPECT_TRUE(same_bits_but_nan_signs(cpu, vk, &where)) << where;
  }
}

} // namespace
} // namespace tierlift::vulkan::test
