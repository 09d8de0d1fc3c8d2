// NUMERICS.md rule 39, measured: lavapipe's sine and cosine (GLSL.std.450 Sin and Cos, which
// `sincos` becomes) against rounding::sin_llvmpipe / cos_llvmpipe, bit for bit, over 102,400
// arguments: the sincos range [−π, π], the octant boundaries k·π/4 and their neighbours,
// arguments up to 1e4 and log-spread magnitudes up to FLT_MAX (where the reduction's octant
// overflows int32), denormals, ±0, ±inf and NaN. The CPU device under Rounding::Llvmpipe
// must store the same bits; under Rounding::Exact it must not (the sweep reaches the cases
// where the two sines part).
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "tierlift/rounding/rounding.h"
#include "vk_test_util.h"

namespace tierlift::vulkan::test {
namespace {

constexpr uint32_t kW = 320, kH = 320; // one argument per pixel

std::vector<float> arguments() {
  std::vector<float> a;
  const float inf = std::numeric_limits<float>::infinity();
  for (float v : {0.0f, -0.0f, 1e-40f, -1e-40f, std::numeric_limits<float>::min(), inf, -inf,
                  std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::max(),
                  -std::numeric_limits<float>::max(), 1e30f, -1e30f, 65504.0f, 2.0e9f, 3.0e9f})
    a.push_back(v);
  for (int k = -64; k <= 64; ++k) { // octant boundaries and the floats around them
    float b = static_cast<float>(k * std::numbers::pi / 4);
    for (int s = 0; s < 4; ++s) {
      a.push_back(b);
      a.push_back(-b);
      b = std::nextafter(b, inf);
    }
  }
  uint64_t state = 39;
  auto unit = [&] { return static_cast<double>(img::unit_float24(img::splitmix64(state))); };
  const size_t n = size_t{kW} * kH;
  while (a.size() < n / 2) a.push_back(static_cast<float>((2 * unit() - 1) * std::numbers::pi));
  while (a.size() < 3 * n / 4) a.push_back(static_cast<float>((2 * unit() - 1) * 1e4));
  while (a.size() < n) { // |a| from 2^-30 to 2^127, both signs
    const double m = std::exp2(-30 + 157 * unit());
    a.push_back(static_cast<float>(unit() < 0.5 ? -m : m));
  }
  return a;
}

TEST_F(VulkanTest, SincosMatchesTheLlvmpipeModelBitForBit) {
  // The model is lavapipe's; on another Vulkan device (a GPU picked with --gpu) there is
  // nothing to compare it with. CI's device is lavapipe, so the test runs there and can fail.
  TIERLIFT_SKIP_UNLESS_LAVAPIPE(dev);
  const std::vector<float> args = arguments();
  auto tex = std::make_shared<img::Image>(kW, kH, img::Format::RGBA32F);
  for (size_t i = 0; i < args.size(); ++i) tex->rgba[4 * i] = args[i];
  const cpu::Pass pass =
      per_texel_pass(tex,
                     "ps_3_0\ndef c0, 0, 0, 0, 1\ndcl_texcoord v0\ndcl_2d s0\ntexld r0, v0, s0\n"
                     "mov r1, c0\nsincos r1.xy, r0.x\nmov r1.z, r0.x\nmov oC0, r1\n",
                     "sincos");
  ASSERT_TRUE(pass.vertex_program && pass.pixel_program);
  const ThreeWays t = draw_three_ways(*dev, pass, img::Image(kW, kH, img::Format::RGBA32F));
  ASSERT_TRUE(t.ok);
  const img::Image &vk = t.vk, &cpu_llvmpipe = t.cpu, &cpu_exact = t.cpu_exact;

  size_t model_off = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    const float* px = &vk.rgba[4 * i];
    ASSERT_TRUE(same_float_bits(px[2], args[i])) << "pixel " << i << " read another texel";
    const float want_cos = rounding::cos_llvmpipe(args[i]);
    const float want_sin = rounding::sin_llvmpipe(args[i]);
    if (!same_float_bits(px[0], want_cos) || !same_float_bits(px[1], want_sin)) {
      if (model_off++ < 8)
        ADD_FAILURE() << fmt::format("sincos({:a}): lavapipe ({:a}, {:a}), model ({:a}, {:a})",
                                     args[i], px[0], px[1], want_cos, want_sin);
    }
  }
  const size_t cpu_off = values_off(cpu_llvmpipe, vk, 2), exact_off = values_off(cpu_exact, vk, 2);
  EXPECT_EQ(model_off, 0u);
  EXPECT_EQ(cpu_off, 0u);
  EXPECT_GT(exact_off, 1000u);
  std::printf("[vk-agreement] sincos over %zu arguments: the llvmpipe model and the CPU device "
              "match lavapipe in every bit; the exact rule differs in %zu of %zu values\n",
              args.size(), exact_off, 2 * args.size());
}

} // namespace
} // namespace tierlift::vulkan::test
