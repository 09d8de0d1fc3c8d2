// The CPU device's RGBA8 store and blend under ir::Rounding::Llvmpipe (NUMERICS.md rule 34)
// against lavapipe itself: every blend mode, on source values chosen where the float→UNORM8
// rounding and the 8-bit blend arithmetic differ from the exact rule, must give the same
// bytes on both devices. Rounding::Exact must not (which shows the values hit those cases).
#include <cmath>
#include <cstdio>
#include <limits>

#include <fmt/format.h>

#include "vk_test_util.h"

namespace tierlift::vulkan::test {
namespace {

constexpr uint32_t kW = 64, kH = 32;

// Texture values: for every midpoint (k + ½)/255 the nearest float and its three neighbours
// on each side (among them the 128 floats where the rules differ), byte pairs whose rounded
// product is off by one, hand-picked values of
// tests/cpu_draw/rgba8_store_llvmpipe_test.cpp, out-of-range and non-finite values, then
// uniform random values in [0, 1).
std::shared_ptr<img::Image> source_values() {
  auto im = std::make_shared<img::Image>(kW, kH);
  size_t i = 0;
  for (int k = 0; k < 255; ++k) {
    const float mid = static_cast<float>((k + 0.5) / 255.0);
    float lo = mid, hi = mid;
    im->rgba[i++] = mid;
    for (int s = 0; s < 3; ++s) {
      lo = std::nextafter(lo, 0.0f);
      hi = std::nextafter(hi, 1.0f);
      im->rgba[i++] = lo;
      im->rgba[i++] = hi;
    }
  }
  // Whole pixels (colour, alpha) whose byte product (t + (t >> 8) + 128) >> 8 is not the
  // nearest integer to t/255: 152·229, 191·253, 173·241, 169·212, 188·196.
  i = (i + 3) / 4 * 4;
  for (auto [c, a] : {std::pair{152, 229}, {191, 253}, {173, 241}, {169, 212}, {188, 196}}) {
    for (int ch = 0; ch < 3; ++ch) im->rgba[i++] = static_cast<float>(c) / 255.0f;
    im->rgba[i++] = static_cast<float>(a) / 255.0f;
  }
  const float inf = std::numeric_limits<float>::infinity();
  for (float v : {0.3f, 0.9f, 0.05f, 0.1f, 0.4f, 0.5f, 0.25f, 1.0f, 0.0f, -0.0f, -0.5f, 1.5f, inf,
                  -inf, std::numeric_limits<float>::quiet_NaN(), 3e38f, -3e38f})
    im->rgba[i++] = v;
  uint64_t state = 2024;
  while (i < im->rgba.size()) im->rgba[i++] = img::unit_float24(img::splitmix64(state));
  return im;
}

cpu::Pass pass_reading(std::shared_ptr<const img::Image> tex, cpu::BlendMode blend) {
  cpu::Pass p = per_texel_pass(
      std::move(tex), "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n", "store");
  p.blend = blend;
  return p;
}

size_t differing_values(const img::Image& a, const img::Image& b, std::string* first) {
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (a.rgba[i] == b.rgba[i]) continue;
    if (n++ == 0 && first)
      *first = fmt::format("value {} (pixel {}, channel {}): cpu {} vulkan {}", i, i / 4, i % 4,
                           a.rgba[i] * 255.0f, b.rgba[i] * 255.0f);
  }
  return n;
}

TEST_F(VulkanTest, Rgba8StoreAndBlendMatchLavapipeByteForByte) {
  TIERLIFT_SKIP_UNLESS_LAVAPIPE(dev);
  const auto tex = source_values();
  img::Image dst(kW, kH, img::Format::RGBA8);
  uint64_t state = 77;
  for (float& v : dst.rgba) v = static_cast<float>(img::splitmix64(state) % 256) / 255.0f;

  // Least number of values where the exact rule must differ from lavapipe: Replace and
  // ONE/ONE at the 128 midpoint floats (some saturate against the destination under
  // ONE/ONE), the SRCALPHA modes far more often (rounded byte products).
  const std::pair<cpu::BlendMode, size_t> modes[] = {{cpu::BlendMode::Replace, 128},
                                                     {cpu::BlendMode::OneOne, 60},
                                                     {cpu::BlendMode::SrcAlphaOne, 500},
                                                     {cpu::BlendMode::SrcAlphaInvSrcAlpha, 1000}};
  for (const auto& [mode, min_exact_diffs] : modes) {
    SCOPED_TRACE(static_cast<int>(mode));
    const cpu::Pass pass = pass_reading(tex, mode);
    const ThreeWays t = draw_three_ways(*dev, pass, dst);
    ASSERT_TRUE(t.ok);
    const img::Image &vk = t.vk, &cpu_llvmpipe = t.cpu, &cpu_exact = t.cpu_exact;

    std::string first;
    EXPECT_EQ(differing_values(cpu_llvmpipe, vk, &first), 0u) << first;
    const size_t exact_diffs = differing_values(cpu_exact, vk, nullptr);
    EXPECT_GE(exact_diffs, min_exact_diffs);
    std::printf("[vk-agreement] rgba8 blend mode %d: Rounding::Exact differs from lavapipe in "
                "%zu of %zu values, Llvmpipe in none\n",
                static_cast<int>(mode), exact_diffs, vk.rgba.size());
  }
}

} // namespace
} // namespace tierlift::vulkan::test
