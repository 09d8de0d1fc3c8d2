// A multi-pass chain through resident textures (TextureSet) returns the same bits as the same
// chain through Device::draw, pass by pass with host images in between (the path the glow
// took before textures stayed on the device) — in RGBA8, RGBA16F and RGBA32F. And the float
// copy a sampled RGBA8 / RGBA16F texture gets on the device holds exactly k/255 and the
// half's value (checked against values computed here, not by the code under test).
#include <cmath>
#include <map>

#include "resident_fixture.h"

namespace tierlift::vulkan::test {
namespace {

constexpr uint32_t kW = 37, kH = 23, kSmallW = 19, kSmallH = 12; // odd sizes on purpose

// Seeded noise; float formats also get values above 1 and below 0.
img::Image noise(uint32_t w, uint32_t h, img::Format f, uint64_t seed) {
  img::Image im(w, h, f);
  uint64_t s = seed;
  for (float& v : im.rgba) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    const float u = static_cast<float>(s >> 40) / static_cast<float>(1ull << 24); // [0, 1)
    v = f == img::Format::RGBA8 ? u : u * 2.5f - 0.5f;
  }
  img::quantize_in_place(im); // an input as the graph stores it
  return im;
}

struct Step {
  std::string source, target;
  cpu::BlendMode blend;
  std::vector<cpu::Vec4> offsets; // vs c0, c1: tap offsets in uv
  std::vector<cpu::Vec4> weights; // ps c0, c1
  cpu::Filter filter = cpu::Filter::Linear;
};

// in → a → b (+= in) → c (half size) → a again (after being sampled) → d (ONE/ONE into a
// texture no pass wrote before).
std::vector<Step> chain() {
  const float du = 1.0f / kW, dv = 1.0f / kH;
  using cpu::BlendMode;
  return {
      {"in",
       "a",
       BlendMode::Replace,
       {{0.3f * du, -0.2f * dv, 0, 0}, {-1.7f * du, 0.45f * dv, 0, 0}},
       {{0.6f, 0.6f, 0.6f, 0.6f}, {0.5f, 0.5f, 0.5f, 0.5f}}},
      {"a",
       "b",
       BlendMode::Replace,
       {{0.5f * du, 0.5f * dv, 0, 0}, {2.25f * du, -0.75f * dv, 0, 0}},
       {{0.75f, 0.5f, 0.25f, 1}, {0.3f, 0.3f, 0.3f, 0.3f}}},
      {"in",
       "b",
       BlendMode::OneOne,
       {{-0.1f * du, 0.9f * dv, 0, 0}, {0, 0, 0, 0}},
       {{0.2f, 0.2f, 0.2f, 0.2f}, {0.1f, 0.1f, 0.1f, 0.1f}}},
      {"b",
       "c",
       BlendMode::Replace,
       {{0.5f * du, 0.5f * dv, 0, 0}, {-0.5f * du, -0.5f * dv, 0, 0}},
       {{0.5f, 0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f, 0.5f}}},
      {"c",
       "a",
       BlendMode::Replace,
       {{0.13f * du, 0.37f * dv, 0, 0}, {0, 0, 0, 0}},
       {{1, 1, 1, 1}, {0.25f, 0.25f, 0.25f, 0.25f}}},
      {"a",
       "d",
       BlendMode::OneOne,
       {{0.7f * du, 0.1f * dv, 0, 0}, {-0.3f * du, 0.2f * dv, 0, 0}},
       {{0.4f, 0.4f, 0.4f, 0.4f}, {0.7f, 0.7f, 0.7f, 0.7f}}},
  };
}

cpu::Pass step_pass(const Step& s) {
  cpu::Pass p = quad_pass(two_coords_vs(), two_taps_ps(), s.offsets, s.weights, s.blend);
  p.textures[0].sampler.filter = s.filter;
  p.textures[0].sampler.address_u = p.textures[0].sampler.address_v = cpu::AddressMode::Clamp;
  return p;
}

// The chain's textures and their sizes.
const std::map<std::string, std::pair<uint32_t, uint32_t>>& chain_sizes() {
  static const std::map<std::string, std::pair<uint32_t, uint32_t>> sizes = {
      {"in", {kW, kH}},
      {"a", {kW, kH}},
      {"b", {kW, kH}},
      {"c", {kSmallW, kSmallH}},
      {"d", {kW, kH}}};
  return sizes;
}

// Host images of those sizes, zero but for "in" (noise of `seed`).
std::map<std::string, img::Image> host_images(img::Format f, unsigned seed) {
  std::map<std::string, img::Image> host;
  for (const auto& [name, wh] : chain_sizes()) host[name] = img::Image(wh.first, wh.second, f);
  host["in"] = noise(kW, kH, f, seed);
  return host;
}

// A format, and whether the device reads RGBA8 in place (DeviceOptions::unorm8_in_place:
// the float copy drawn by an in-place read, else converted by the compute shader).
struct ChainCase {
  img::Format format;
  bool in_place = true;
};

void PrintTo(const ChainCase& c, std::ostream* os) {
  *os << img::format_name(c.format) << (c.in_place ? "" : ", compute copy");
}

class ResidentChain : public ResidentTest, public ::testing::WithParamInterface<ChainCase> {
protected:
  const ir::Result<Device*>& acquire_device() override {
    return GetParam().in_place ? sync_validated_device()
                               : sync_validated_device<true, true, false>();
  }
};

TEST_P(ResidentChain, EqualsDrawPerPassBitForBit) {
  const img::Format f = GetParam().format;
  const auto& sizes = chain_sizes();

  // Old path: host images between passes, Device::draw per pass.
  std::map<std::string, img::Image> host = host_images(f, 7);
  for (const Step& s : chain()) {
    cpu::Pass p = step_pass(s);
    p.textures[0].image = std::make_shared<const img::Image>(host[s.source]);
    ir::Result<pass::DrawReport> r = dev->draw(p, host[s.target]);
    ASSERT_TRUE(r.ok()) << r.message();
  }

  // New path: every texture resident, the input uploaded once, nothing read until the end.
  TextureSet set(*dev);
  std::map<std::string, TextureId> ids;
  for (const auto& [name, wh] : sizes)
    ASSERT_TRUE(succeeded(set.create(wh.first, wh.second, f), ids[name]));
  ASSERT_TRUE(succeeded(set.upload(ids["in"], noise(kW, kH, f, 7))));
  for (const Step& s : chain()) {
    StageTextures stages{};
    stages[0] = ids[s.source];
    ir::Result<pass::DrawReport> r = set.draw(step_pass(s), stages, ids[s.target]);
    ASSERT_TRUE(r.ok()) << r.message();
  }

  for (const auto& [name, id] : ids) {
    img::Image out;
    ASSERT_TRUE(succeeded(set.read(id), out)) << name;
    std::string where;
    EXPECT_TRUE(same_bits(host[name], out, &where)) << name << ": " << where;
  }
  // The chain is not trivial: the last target is neither zero nor the input.
  EXPECT_NE(host["d"].rgba, img::Image(kW, kH, f).rgba);
  EXPECT_NE(host["d"].rgba, host["in"].rgba);
}

// Two frames of the chain the way an effect's frame loop runs it: every draw prepared ahead
// (TextureSet::prepare), then recorded into one command buffer per frame (batching) with
// the barriers between passes, submitted once. The frames carry the textures over (ONE/ONE
// passes add onto the first frame's result), so frame two differs from frame one; both
// must equal Device::draw pass by pass. The same two programs draw every step with other
// constants and textures, so a prepared draw found under the wrong key shows here. Any
// message of the validation layer (synchronization validation on) fails the test.
TEST_P(ResidentChain, BatchedFramesOfPreparedDrawsEqualDrawPerPass) {
  const img::Format f = GetParam().format;
  const auto& sizes = chain_sizes();
  std::map<std::string, img::Image> host = host_images(f, 11);
  std::vector<img::Image> host_d; // "d" after each frame
  for (int frame = 0; frame < 2; ++frame) {
    for (const Step& s : chain()) {
      cpu::Pass p = step_pass(s);
      p.textures[0].image = std::make_shared<const img::Image>(host[s.source]);
      ir::Result<pass::DrawReport> r = dev->draw(p, host[s.target]);
      ASSERT_TRUE(r.ok()) << r.message();
    }
    host_d.push_back(host["d"]);
  }
  ASSERT_NE(host_d[0].rgba, host_d[1].rgba); // frame two added onto frame one

  TextureSet set(*dev);
  std::map<std::string, TextureId> ids;
  for (const auto& [name, wh] : sizes)
    ASSERT_TRUE(succeeded(set.create(wh.first, wh.second, f), ids[name]));
  ASSERT_TRUE(succeeded(set.upload(ids["in"], noise(kW, kH, f, 11))));
  auto stages_of = [&](const Step& s) {
    StageTextures stages{};
    stages[0] = ids[s.source];
    return stages;
  };
  for (const Step& s : chain())
    ASSERT_TRUE(succeeded(set.prepare(step_pass(s), stages_of(s), ids[s.target])));
  ASSERT_TRUE(succeeded(set.set_batching(true)));
  for (int frame = 0; frame < 2; ++frame) {
    for (const Step& s : chain()) {
      ir::Result<pass::DrawReport> r = set.draw(step_pass(s), stages_of(s), ids[s.target]);
      ASSERT_TRUE(r.ok()) << r.message();
    }
    ASSERT_TRUE(succeeded(set.flush()));
    img::Image out;
    ASSERT_TRUE(succeeded(set.read(ids["d"]), out)); // a read between frames flushes too
    std::string where;
    EXPECT_TRUE(same_bits(host_d[size_t(frame)], out, &where))
        << "frame " << frame << ": " << where;
  }
  for (const auto& [name, id] : ids) {
    img::Image out;
    ASSERT_TRUE(succeeded(set.read(id), out)) << name;
    std::string where;
    EXPECT_TRUE(same_bits(host[name], out, &where)) << name << ": " << where;
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, ResidentChain,
                         ::testing::Values(ChainCase{img::Format::RGBA8},
                                           ChainCase{img::Format::RGBA8, false},
                                           ChainCase{img::Format::RGBA16F},
                                           ChainCase{img::Format::RGBA32F}),
                         [](const auto& info) {
                           return std::string(img::format_name(info.param.format)) +
                                  (info.param.in_place ? "" : "_compute_copy");
                         });

// Point-samples every texel of `im` (stored in `f`) into an RGBA32F texture on the device.
img::Image sampled_copy(Device& dev, const img::Image& im, img::Format f) {
  // Texel centres: the quad's uv (u = i/W at pixel i, D3D9 centres) plus half a texel.
  const cpu::Vec4 half{0.5f / im.width, 0.5f / im.height, 0, 0};
  cpu::Pass p = quad_pass(two_coords_vs(), copy_ps(), {half, half}, {}, cpu::BlendMode::Replace);
  return draw_reading(dev, im, f, p, im.width, im.height);
}

TEST_F(ResidentTest, Rgba8SamplesExactlyKOver255) {
  img::Image im(16, 16, img::Format::RGBA8);
  for (uint32_t p = 0; p < 256; ++p)
    for (uint32_t c = 0; c < 4; ++c) im.rgba[p * 4 + c] = float((p + 64 * c) % 256) / 255.0f;
  img::Image out = sampled_copy(*dev, im, img::Format::RGBA8);
  ASSERT_EQ(out.rgba.size(), im.rgba.size());
  for (uint32_t p = 0; p < 256; ++p)
    for (uint32_t c = 0; c < 4; ++c) {
      const uint32_t k = (p + 64 * c) % 256;
      ASSERT_EQ(out.rgba[p * 4 + c], float(k) / 255.0f) << "level " << k;
    }
}

// The value of half-float bits h, from the definition (sign, 5-bit exponent, 10-bit mantissa).
double half_value(uint32_t h) {
  const double sign = (h & 0x8000u) ? -1.0 : 1.0;
  const int e = int((h >> 10) & 31u);
  const double m = double(h & 1023u);
  if (e == 31) return sign * INFINITY; // NaN patterns are not used
  return e == 0 ? sign * std::ldexp(m, -24) : sign * std::ldexp(1024.0 + m, e - 25);
}

TEST_F(ResidentTest, Rgba16fSamplesEveryHalfExactly) {
  // 128 × 128 × 4 = 65536 values: every half pattern once (NaN patterns replaced by 0).
  img::Image im(128, 128, img::Format::RGBA16F);
  auto is_nan = [](uint32_t h) { return ((h >> 10) & 31u) == 31u && (h & 1023u) != 0; };
  for (uint32_t h = 0; h < 65536; ++h)
    im.rgba[h] = is_nan(h) ? 0.0f : static_cast<float>(half_value(h));
  img::Image out = sampled_copy(*dev, im, img::Format::RGBA16F);
  ASSERT_EQ(out.rgba.size(), im.rgba.size());
  uint32_t checked = 0;
  for (uint32_t h = 0; h < 65536; ++h) {
    if (is_nan(h)) continue;
    const float want = static_cast<float>(half_value(h));
    ASSERT_EQ(std::memcmp(&out.rgba[h], &want, 4), 0)
        << fmt::format("half 0x{:04x}: {} vs {}", h, out.rgba[h], want);
    ++checked;
  }
  EXPECT_EQ(checked, 65536u - 2 * 1023u);
}

} // namespace
} // namespace tierlift::vulkan::test
