// The article's listings (GPU Gems ch. 21, listings/gpugems21/) run through the VM, with
// results computed by hand. The fake texture unit echoes the coordinate it is given.
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "vm_test_util.h"

using namespace vmtest;

namespace {
std::string read_listing(const char* name) {
  std::ifstream f(std::string(TIERLIFT_SOURCE_DIR) + "/listings/gpugems21/" + name);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}
} // namespace

TEST(VmListings, Listing3OffsetsTheTexcoord) {
  // oTi = v3 + ci: v3 = (0.5, 0.5, 0, 1); c0..c3 = (±1/64, 0) offsets.
  ShaderVM vm = vm_of(parse(read_listing("listing3_blur4_coords.vsh")), {});
  VertexInput in;
  in.v[0] = {-1, 1, 0, 1};
  in.v[3] = {0.5f, 0.5f, 0, 1};
  auto c = bank(
      {{0.015625f, 0, 0, 0}, {-0.015625f, 0, 0, 0}, {0, 0.015625f, 0, 0}, {0, -0.015625f, 0, 0}});
  auto o = vm.run_vertex(in, c);
  EXPECT_VEC4(o.pos, -1, 1, 0, 1);
  EXPECT_VEC4(o.tex[0], 0.515625f, 0.5f, 0, 1);
  EXPECT_VEC4(o.tex[1], 0.484375f, 0.5f, 0, 1);
  EXPECT_VEC4(o.tex[2], 0.5f, 0.515625f, 0, 1);
  EXPECT_VEC4(o.tex[3], 0.5f, 0.484375f, 0, 1);
  EXPECT_EQ(o.tex_written, 0xF);
}

TEST(VmListings, Listing4WeightedSumClampsWeights) {
  // ps.1.3: r0 = Σ ti·ci with ti = TCi (echo). Weights c = 0.25 each; TCi.x = 0.5, 0.25,
  // 1, 0.75 → r0.x = 0.25·(0.5 + 0.25 + 1 + 0.75) = 0.625. A weight of 2 reads as 1
  // (constant clamp): with c0 = 2 → 0.5·1 + 0.25·(0.25 + 1 + 0.75) = 1.0.
  ShaderVM vm = vm_of(parse(read_listing("listing4_blur4_weighted_sum.psh")), {});
  EchoTextures tex;
  PixelInput in = coords({{0.5f, 0, 0, 0}, {0.25f, 0, 0, 0}, {1, 0, 0, 0}, {0.75f, 0, 0, 0}});
  Vec4 q{0.25f, 0.25f, 0.25f, 0.25f};
  EXPECT_FLOAT_EQ(vm.run_pixel(in, bank({q, q, q, q}), tex).color[0][0], 0.625f);
  EXPECT_FLOAT_EQ(vm.run_pixel(in, bank({{2, 2, 2, 2}, q, q, q}), tex).color[0][0], 1.0f);
}

TEST(VmListings, Listing2EightTapSum) {
  // ps.2.0: oC0 = Σ texld(ti)·ci; TCi.x = i/8, ci = 0.125 → Σ i/64 = 28/64 = 0.4375.
  ShaderVM vm = vm_of(parse(read_listing("listing2_blur8_weighted_sum.psh")), {});
  EchoTextures tex;
  PixelInput in;
  ConstantBank c;
  for (int i = 0; i < 8; ++i) {
    in.tex[i] = {static_cast<float>(i) / 8, 1, 0, 0};
    c.f.push_back({0.125f, 0.125f, 0.125f, 0.125f});
  }
  auto out = vm.run_pixel(in, c, tex);
  EXPECT_FLOAT_EQ(out.color[0][0], 0.4375f);
  EXPECT_FLOAT_EQ(out.color[0][1], 1.0f); // 8 · 0.125
  EXPECT_EQ(out.color_written, 1);
}

TEST(VmListings, ConcurrentRunsAgree) {
  // The run methods are const and keep their state on the stack: two threads running the
  // same VM on different pixels get what a single thread gets. Pixel i: TCk.x = i/1024,
  // weights 0.125 → oC0.x = 8 · 0.125 · i/1024 = i/1024.
  ShaderVM vm = vm_of(parse(read_listing("listing2_blur8_weighted_sum.psh")), {});
  ConstantBank c;
  c.f.assign(8, Vec4{0.125f, 0.125f, 0.125f, 0.125f});
  auto work = [&](int first, std::vector<float>& out) {
    EchoTextures tex;
    for (int i = first; i < 1024; i += 2) {
      PixelInput in;
      for (auto& t : in.tex) t = {static_cast<float>(i) / 1024, 0, 0, 0};
      out[static_cast<size_t>(i)] = vm.run_pixel(in, c, tex).color[0][0];
    }
  };
  std::vector<float> a(1024), b(1024);
  std::thread t1(work, 0, std::ref(a)), t2(work, 1, std::ref(b));
  t1.join();
  t2.join();
  for (int i = 0; i < 1024; ++i)
    EXPECT_FLOAT_EQ(i % 2 ? b[static_cast<size_t>(i)] : a[static_cast<size_t>(i)],
                    static_cast<float>(i) / 1024);
}
