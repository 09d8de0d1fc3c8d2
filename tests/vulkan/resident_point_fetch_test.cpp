// A point read of a resident RGBA8 texture with edge clamping reads the stored bytes in the
// shader (codegen::CodegenOptions::stage_fetch_unorm8) instead of sampling a float copy. It
// must read the texel the CPU device reads, at every coordinate (texel corners that float
// cannot hold, outside the texture, NaN, infinities), and the value k/255.0f that the float
// copy held: checked here against the CPU device and against values computed in the test.
// Both ways to find the texel are checked on lavapipe: its own point sampler at the clamped
// coordinate (CodegenOptions::point_sampling_floors, lavapipe's default) and the index the
// shader computes, then a fetch (every other device; DeviceOptions::llvmpipe_point_sampling
// off); each with the decode the device chose by reading every level (two multiplies on
// lavapipe) and with the general one (DeviceOptions::choose_unorm8_decode off). The float
// copy other reads sample is drawn by the same in-place read; with in-place reads off
// (DeviceOptions::unorm8_in_place), every read samples the copy the compute shader converts,
// and must read the same texels and values.
#include <cmath>
#include <limits>

#include "resident_fixture.h"
#include "tierlift/cpu/draw.h"

namespace tierlift::vulkan::test {
namespace {

// 13 × 7 texels, every level 0..255 on some channel (odd sizes on purpose).
img::Image levels_texture() {
  img::Image im(13, 7, img::Format::RGBA8);
  for (size_t i = 0; i < im.rgba.size(); ++i)
    im.rgba[i] = static_cast<float>((i * 37) % 256) / 255.0f;
  return im;
}

// t0 = uv·c2 + c0 (uv: the quad's, pixel x at x/W with D3D9 centres): the coordinates of the
// target's pixels sweep the texture as the constants say.
cpu::Pass read_pass(cpu::Vec4 scale, cpu::Vec4 offset, cpu::AddressMode mode) {
  cpu::Pass p = quad_pass(parse_listing("vs_2_0\ndcl_position v0\ndcl_texcoord v1\n"
                                        "mov oPos, v0\nmad oT0, v1, c2, c0\n",
                                        "scaled.vsh"),
                          copy_ps(), {offset, {0, 0, 0, 0}, scale}, {}, cpu::BlendMode::Replace);
  p.textures[0].sampler.filter = cpu::Filter::Point;
  p.textures[0].sampler.address_u = p.textures[0].sampler.address_v = mode;
  return p;
}

img::Image on_cpu(const img::Image& tex, cpu::Pass p, uint32_t w, uint32_t h) {
  p.textures[0].image = std::make_shared<img::Image>(tex);
  img::Image out(w, h, img::Format::RGBA32F);
  EXPECT_TRUE(cpu::draw(p, out, 2).ok());
  return out;
}

struct Sweep {
  const char* what;
  cpu::Vec4 scale, offset;
  uint32_t w, h;
};

// The resident tests' device with the shader-computed index and fetch, as on a GPU.
class ResidentIndexFetchTest : public ResidentTest {
protected:
  const ir::Result<Device*>& acquire_device() override { return sync_validated_device<false>(); }
};
// Both ways to find the texel again with the general decode (round and rebuild), which a
// device whose values no cheaper decode maps exactly keeps.
class ResidentGeneralDecodeTest : public ResidentTest {
protected:
  const ir::Result<Device*>& acquire_device() override {
    return sync_validated_device<true, false>();
  }
};
class ResidentIndexFetchGeneralDecodeTest : public ResidentTest {
protected:
  const ir::Result<Device*>& acquire_device() override {
    return sync_validated_device<false, false>();
  }
};

// No RGBA8 read in place: every one samples the float copy the compute shader converts from
// the stored bytes, as on a device where no decode is exact.
class ResidentComputeCopyTest : public ResidentTest {
protected:
  const ir::Result<Device*>& acquire_device() override {
    return sync_validated_device<true, true, false>();
  }
};

void reads_the_interpreters_texel_everywhere(Device& dev, img::Format format = img::Format::RGBA8) {
  const img::Image tex = levels_texture();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Sweep sweeps[] = {
      // Four pixels per texel: u = x/52 puts every fourth pixel on a texel corner i/13, which
      // float holds only approximately (fl32(u·13) decides the side).
      {"corners", {1, 1, 0, 0}, {0, 0, 0, 0}, 52, 28},
      {"outside on both sides", {2.3f, 1.9f, 0, 0}, {-0.6f, -0.45f, 0, 0}, 61, 29},
      {"far outside", {0, 0, 0, 0}, {1e30f, -1e30f, 0, 0}, 5, 3},
      {"NaN", {1, 1, 0, 0}, {nan, nan, 0, 0}, 5, 3},
      {"infinities", {inf, -inf, 0, 0}, {0, 0, 0, 0}, 5, 3},
  };
  for (const Sweep& s : sweeps) {
    SCOPED_TRACE(s.what);
    const cpu::Pass p = read_pass(s.scale, s.offset, cpu::AddressMode::Clamp);
    const img::Image vk = draw_reading(dev, tex, format, p, s.w, s.h);
    const img::Image cpu = on_cpu(tex, p, s.w, s.h);
    std::string where;
    EXPECT_TRUE(same_bits(cpu, vk, &where)) << where;
  }
}

void gives_k_over_255_for_every_level(Device& dev) {
  // 16 × 16 texels, level (p + 64c) mod 256 on channel c of texel p; read at texel centres
  // with edge clamping (the in-place fetch) and with wrapping (the float copy): both must
  // hold exactly k/255.0f, computed here.
  img::Image im(16, 16, img::Format::RGBA8);
  for (uint32_t p = 0; p < 256; ++p)
    for (uint32_t c = 0; c < 4; ++c) im.rgba[p * 4 + c] = float((p + 64 * c) % 256) / 255.0f;
  for (cpu::AddressMode mode : {cpu::AddressMode::Clamp, cpu::AddressMode::Wrap}) {
    SCOPED_TRACE(static_cast<int>(mode));
    const cpu::Pass p = read_pass({1, 1, 0, 0}, {0.5f / 16, 0.5f / 16, 0, 0}, mode);
    const img::Image out = draw_reading(dev, im, img::Format::RGBA8, p, 16, 16);
    ASSERT_EQ(out.rgba.size(), im.rgba.size());
    for (uint32_t q = 0; q < 256; ++q)
      for (uint32_t c = 0; c < 4; ++c) {
        const uint32_t k = (q + 64 * c) % 256;
        ASSERT_EQ(out.rgba[q * 4 + c], float(k) / 255.0f) << "level " << k;
      }
  }
}

TEST_F(ResidentTest, Rgba8PointFetchReadsTheInterpretersTexelEverywhere) {
  reads_the_interpreters_texel_everywhere(*dev);
}
TEST_F(ResidentIndexFetchTest, Rgba8PointFetchReadsTheInterpretersTexelEverywhere) {
  reads_the_interpreters_texel_everywhere(*dev);
}
TEST_F(ResidentGeneralDecodeTest, Rgba8PointFetchReadsTheInterpretersTexelEverywhere) {
  reads_the_interpreters_texel_everywhere(*dev);
}
TEST_F(ResidentIndexFetchGeneralDecodeTest, Rgba8PointFetchReadsTheInterpretersTexelEverywhere) {
  reads_the_interpreters_texel_everywhere(*dev);
}
// The same reads of a texture passes sample as it is (RGBA32F) and, on the device without
// in-place reads, of RGBA8 through the float copy: the far-outside sweep failed both (texel 0
// where the interpreter reads the last) until sampled point reads clamped their coordinate
// (codegen::CodegenOptions::stage_point_clamped).
TEST_F(ResidentTest, Rgba32fPointReadReadsTheInterpretersTexelEverywhere) {
  reads_the_interpreters_texel_everywhere(*dev, img::Format::RGBA32F);
}
TEST_F(ResidentComputeCopyTest, Rgba8PointReadReadsTheInterpretersTexelEverywhere) {
  reads_the_interpreters_texel_everywhere(*dev);
}
TEST_F(ResidentTest, Rgba8PointFetchGivesKOver255ForEveryLevel) {
  gives_k_over_255_for_every_level(*dev);
}
TEST_F(ResidentIndexFetchTest, Rgba8PointFetchGivesKOver255ForEveryLevel) {
  gives_k_over_255_for_every_level(*dev);
}
TEST_F(ResidentGeneralDecodeTest, Rgba8PointFetchGivesKOver255ForEveryLevel) {
  gives_k_over_255_for_every_level(*dev);
}
TEST_F(ResidentIndexFetchGeneralDecodeTest, Rgba8PointFetchGivesKOver255ForEveryLevel) {
  gives_k_over_255_for_every_level(*dev);
}
TEST_F(ResidentComputeCopyTest, Rgba8ReadsGiveKOver255ForEveryLevel) {
  gives_k_over_255_for_every_level(*dev);
}

// Which decode each device chose (DeviceOptions::choose_unorm8_decode). lavapipe returns
// one of the two values the two-multiply decode is exact for (unorm8_decode.h); a device
// whose values already are k/255.0f would need none. Without the choice: the general one.
TEST_F(ResidentTest, TheDeviceChoosesTheCheapestExactDecode) {
  const bool lavapipe = dev->name().find("llvmpipe") != std::string::npos;
  if (lavapipe) {
    EXPECT_EQ(dev->unorm8_reads(), "two multiplies");
    ASSERT_TRUE(sync_validated_device<false>().ok());
    EXPECT_EQ((*sync_validated_device<false>())->unorm8_reads(), "two multiplies");
  }
  ASSERT_TRUE((sync_validated_device<true, false>().ok()));
  EXPECT_EQ((*sync_validated_device<true, false>())->unorm8_reads(), "round and rebuild");
  ASSERT_TRUE((sync_validated_device<true, true, false>().ok()));
  EXPECT_EQ((*sync_validated_device<true, true, false>())->unorm8_reads(), "float copy");
}

} // namespace
} // namespace tierlift::vulkan::test
