// ir::Rounding::Llvmpipe (the CPU device's default) reproduces lavapipe's interpolation bit
// for bit: random triangles inside the clip volume (so neither device clips), w = 1 and
// w ≠ 1, D3D9 and modern centres, four random attributes passed straight to the target.
// Every pixel both devices cover must hold identical floats. Rounding::Exact, the control,
// must differ somewhere (else the comparison could not tell the two schemes apart).
#include "diff_harness.h"

namespace tierlift::vulkan::test {
namespace {

constexpr uint32_t kW = 50, kH = 40;
constexpr float kUnwritten = 1e30f; // target contents before the draw

struct Counts {
  uint64_t both = 0, identical = 0;
};

Counts compare_triangles(vulkan::Device& dev, ir::Rounding rounding) {
  const char* vs = "vs.2.0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n";
  const char* ps = "ps.2.0\ndcl t0\nmov r0, t0\nmov oC0, r0\n";
  Counts n;
  Rng rng(99);
  for (int t = 0; t < 24; ++t) {
    const bool perspective = t >= 12;
    cpu::Pass p;
    p.vertex_program = parse_listing(vs, "interp.vsh");
    p.pixel_program = parse_listing(ps, "interp.psh");
    if (!p.vertex_program || !p.pixel_program) return n;
    for (int k = 0; k < 3; ++k) {
      const float w = perspective ? rng.range(0.5f, 3.0f) : 1.0f;
      cpu::VertexInput in;
      in.v[0] = {rng.range(-0.95f, 0.95f) * w, rng.range(-0.95f, 0.95f) * w, 0.5f * w, w};
      in.v[3] = {rng.range(-3, 3), rng.range(-3, 3), rng.range(-3, 3), rng.range(-3, 3)};
      p.vertices.push_back(in);
    }
    p.conventions.pixel_center = t % 2 ? ir::PixelCenter::Modern : ir::PixelCenter::D3D9;
    p.conventions.rounding = rounding;
    img::Image initial(kW, kH, img::Format::RGBA32F);
    for (float& v : initial.rgba) v = kUnwritten;
    TwoWays r = draw_both(dev, p, kW, kH, img::Format::RGBA32F, &initial);
    if (!r.ok) return n;
    for (size_t i = 0; i < r.cpu.rgba.size(); ++i)
      if (r.cpu.rgba[i] != kUnwritten && r.vk.rgba[i] != kUnwritten) {
        ++n.both;
        n.identical += r.cpu.rgba[i] == r.vk.rgba[i];
      }
  }
  return n;
}

TEST_F(VulkanTest, LlvmpipeRoundingInterpolatesBitIdentically) {
  const Counts c = compare_triangles(*dev, ir::Rounding::Llvmpipe);
  EXPECT_GT(c.both, 4u * 2000); // the triangles covered a fair share of the 24 targets
  EXPECT_EQ(c.identical, c.both);
  const Counts exact = compare_triangles(*dev, ir::Rounding::Exact);
  EXPECT_LT(exact.identical, exact.both);
  std::printf("[vk-agreement] interpolation: llvmpipe %llu/%llu values identical, exact "
              "%llu/%llu\n",
              static_cast<unsigned long long>(c.identical), static_cast<unsigned long long>(c.both),
              static_cast<unsigned long long>(exact.identical),
              static_cast<unsigned long long>(exact.both));
}

} // namespace
} // namespace tierlift::vulkan::test
