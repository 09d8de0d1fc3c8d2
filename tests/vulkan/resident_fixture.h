// Shared by the resident-texture tests (resident_*.cpp): a device with the validation layer
// AND its synchronization validation on (TextureSet's barriers are what these tests check),
// a fixture that fails a test on any message, and passes built from small ps_2_0 listings.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <fmt/format.h>
#include <string>
#include <utility>

#include "tierlift/cpu/draw.h"
#include "tierlift/vulkan/texture_set.h"
#include "vk_test_util.h"

namespace tierlift::vulkan::test {

// Owned by the program and destroyed at its end, like shared_device (vk_test_util.h). One per
// value of DeviceOptions::llvmpipe_point_sampling (false: RGBA8 point reads compute their
// index and fetch on lavapipe too, as on every other device) and of
// DeviceOptions::choose_unorm8_decode (false: the general decode, as where no cheaper one
// is exact) and of DeviceOptions::unorm8_in_place (false: every RGBA8 read samples the float
// copy the compute conversion makes, as where no decode is exact).
template <bool LlvmpipePointSampling = true, bool ChooseDecode = true, bool InPlace = true>
inline const ir::Result<Device*>& sync_validated_device() {
  static const ir::Result<Device*> shared = [] {
    DeviceOptions o;
    o.synchronization_validation = true;
    o.llvmpipe_point_sampling = LlvmpipePointSampling;
    o.choose_unorm8_decode = ChooseDecode;
    o.unorm8_in_place = InPlace;
    return program_device(o);
  }();
  return shared;
}

// VulkanTest's checks (skip without a device, fail on any message) on that device.
class ResidentTest : public VulkanTest {
protected:
  const ir::Result<Device*>& acquire_device() override { return sync_validated_device(); }
};

// ASSERT_TRUE(succeeded(set.upload(id, image))): a failure prints the set's message.
template <class T>::testing::AssertionResult succeeded(const ir::Result<T>& r) {
  if (r) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << r.message();
}
// The same for a call that yields a value (a new texture, an image read back): on success
// the value is moved into `out`, so a test keeps its variables across calls.
template <class T>::testing::AssertionResult succeeded(ir::Result<T> r, T& out) {
  if (!r) return ::testing::AssertionFailure() << r.message();
  out = std::move(r).value();
  return ::testing::AssertionSuccess();
}

// vs_2_0: oPos = v0, oT0 = v1 + c0, oT1 = v1 + c1 (v1: the quad's uv).
inline std::shared_ptr<const ir::Program> two_coords_vs() {
  return parse_listing("vs_2_0\ndcl_position v0\ndcl_texcoord v1\nmov oPos, v0\n"
                       "add oT0, v1, c0\nadd oT1, v1, c1\n",
                       "two_coords.vsh");
}
// ps_2_0: oC0 = tex(s0, t0)·c0 + tex(s0, t1)·c1.
inline std::shared_ptr<const ir::Program> two_taps_ps() {
  return parse_listing("ps_2_0\ndcl t0.xy\ndcl t1.xy\ndcl_2d s0\ntexld r0, t0, s0\n"
                       "texld r1, t1, s0\nmul r0, r0, c0\nmad r0, r1, c1, r0\nmov oC0, r0\n",
                       "two_taps.psh");
}
// ps_2_0: oC0 = tex(s0, t0) (no arithmetic: inf and -0 pass through).
inline std::shared_ptr<const ir::Program> copy_ps() {
  return parse_listing("ps_2_0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n", "copy.psh");
}

// A full-screen pass: v0 the quad's corners, v1 its uv (0,0) top-left … (1,1) bottom-right.
inline cpu::Pass quad_pass(std::shared_ptr<const ir::Program> vs,
                           std::shared_ptr<const ir::Program> ps, std::vector<cpu::Vec4> vs_c,
                           std::vector<cpu::Vec4> ps_c, cpu::BlendMode blend) {
  cpu::Pass p;
  p.vertex_program = std::move(vs);
  p.pixel_program = std::move(ps);
  p.vs_constants.f = std::move(vs_c);
  p.ps_constants.f = std::move(ps_c);
  cpu::set_full_screen_quad(p, 0);
  for (size_t c = 0; c < 4; ++c) p.vertices[c].v[1] = cpu::kQuadUV[c];
  p.blend = blend;
  return p;
}

// `pass` drawn into a new w × h RGBA32F texture while stage 0 reads `tex`, resident in
// `format` (uploaded first); the target read back.
inline img::Image draw_reading(Device& dev, const img::Image& tex, img::Format format,
                               const cpu::Pass& pass, uint32_t w, uint32_t h) {
  TextureSet set(dev);
  TextureId src{}, dst{};
  EXPECT_TRUE(succeeded(set.create(tex.width, tex.height, format), src));
  EXPECT_TRUE(succeeded(set.create(w, h, img::Format::RGBA32F), dst));
  EXPECT_TRUE(succeeded(set.upload(src, tex)));
  StageTextures stages{};
  stages[0] = src;
  ir::Result<pass::DrawReport> r = set.draw(pass, stages, dst);
  EXPECT_TRUE(r.ok()) << r.message();
  img::Image out;
  EXPECT_TRUE(succeeded(set.read(dst), out));
  return out;
}

// Bit-for-bit equality of two images (NaN equals NaN only with the same bits); the first
// difference in *where.
inline bool same_bits(const img::Image& a, const img::Image& b, std::string* where) {
  if (a.width != b.width || a.height != b.height || a.format != b.format ||
      a.rgba.size() != b.rgba.size()) {
    *where = "size or format";
    return false;
  }
  for (size_t i = 0; i < a.rgba.size(); ++i)
    if (std::memcmp(&a.rgba[i], &b.rgba[i], sizeof(float)) != 0) {
      const size_t px = i / 4;
      *where = fmt::format("pixel ({}, {}) channel {}: {} vs {}", px % a.width, px / a.width, i % 4,
                           a.rgba[i], b.rgba[i]);
      return false;
    }
  return true;
}

// `ps` with the pixel constants `bank`, reading `tex` (resident in `format`; POINT, CLAMP) at
// t0 = the pixel's texel and t1 = the next one, drawn into RGBA32F by the interpreter and by
// `dev` under `conventions`: {cpu, vulkan}.
inline std::pair<img::Image, img::Image> draw_both_ways(Device& dev, const img::Image& tex,
                                                        std::shared_ptr<const ir::Program> ps,
                                                        const std::vector<cpu::Vec4>& bank,
                                                        img::Format format = img::Format::RGBA32F,
                                                        const ir::Conventions& conventions = {}) {
  const cpu::Vec4 off{0.5f / tex.width, 0.5f / tex.height, 0, 0};
  cpu::Pass p = quad_pass(two_coords_vs(), std::move(ps), {off, {1.5f / tex.width, off[1], 0, 0}},
                          bank, cpu::BlendMode::Replace);
  p.conventions = conventions;
  p.textures[0].sampler.filter = cpu::Filter::Point;
  p.textures[0].sampler.address_u = p.textures[0].sampler.address_v = cpu::AddressMode::Clamp;
  img::Image vk = draw_reading(dev, tex, format, p, tex.width, tex.height);
  p.textures[0].image = std::make_shared<img::Image>(tex);
  img::Image cpu(tex.width, tex.height, img::Format::RGBA32F);
  EXPECT_TRUE(cpu::draw(p, cpu, 2).ok());
  return {std::move(cpu), std::move(vk)};
}

} // namespace tierlift::vulkan::test
