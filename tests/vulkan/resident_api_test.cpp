// TextureSet's contract: new textures read back as zeros, uploads come back with the format's
// store rule, blending reads what the texture holds, and bad calls are messages that change
// nothing. Expected values are worked out by hand in the comments.
#include <cmath>

#include "resident_fixture.h"

namespace tierlift::vulkan::test {
namespace {

constexpr img::Format kFormats[] = {img::Format::RGBA8, img::Format::RGBA16F, img::Format::RGBA32F};

// A pass without programs: the full-screen quad with oD0 = c at every pixel (device.h).
cpu::Pass constant_pass(cpu::Vec4 c, cpu::BlendMode blend) {
  cpu::Pass p;
  p.constant_inputs.color[0] = c;
  p.blend = blend;
  return p;
}

TEST_F(ResidentTest, NewTexturesReadBackAsZeros) {
  TextureSet set(*dev);
  for (img::Format f : kFormats) {
    TextureId id{};
    ASSERT_TRUE(succeeded(set.create(5, 3, f), id));
    EXPECT_NE(id, TextureId::None);
    img::Image out(1, 1); // overwritten
    out.rgba = {9, 9, 9, 9};
    ASSERT_TRUE(succeeded(set.read(id), out));
    EXPECT_EQ(out.width, 5u);
    EXPECT_EQ(out.height, 3u);
    EXPECT_EQ(out.format, f);
    EXPECT_EQ(out.rgba, std::vector<float>(5 * 3 * 4, 0.0f)) << img::format_name(f);
  }
  EXPECT_EQ(set.size(), 3u);
}

TEST_F(ResidentTest, UploadReadsBackWithTheStoreRule) {
  TextureSet set(*dev);
  img::Image im(2, 1);
  im.rgba = {0.2f, 1.5f, -1.0f, 0.5f, 0.25f, 65504.0f, 1e6f, -0.0f};
  struct Want {
    img::Format f;
    std::vector<float> rgba;
  };
  const Want wants[] = {
      // RGBA8: clamp, round(v·255): 0.2 → 51, 1.5 → 255, −1 → 0, 0.5 → 127.5 → 128 (lround),
      // 0.25 → 63.75 → 64, 65504 → 255, 1e6 → 255, −0 → 0.
      {img::Format::RGBA8, {51.0f / 255, 1, 0, 128.0f / 255, 64.0f / 255, 1, 1, 0}},
      // RGBA16F: 0.2 = 1638.4·2^-13 → 1638·2^-13; 1.5, −1, 0.5, 0.25, 65504 exact (65504 is
      // the largest half); 1e6 overflows to +inf; −0 stays −0.
      {img::Format::RGBA16F, {1638.0f / 8192, 1.5f, -1, 0.5f, 0.25f, 65504.0f, INFINITY, -0.0f}},
      {img::Format::RGBA32F, im.rgba},
  };
  for (const Want& w : wants) {
    TextureId id{};
    ASSERT_TRUE(succeeded(set.create(2, 1, w.f), id));
    ASSERT_TRUE(succeeded(set.upload(id, im))); // im says RGBA32F: the texture's format decides
    img::Image out;
    ASSERT_TRUE(succeeded(set.read(id), out));
    img::Image want(2, 1, w.f);
    want.rgba = w.rgba;
    std::string where;
    EXPECT_TRUE(same_bits(out, want, &where)) << img::format_name(w.f) << ": " << where;
  }
}

// ONE/ONE into a texture no pass wrote: the destination is zero, so the first draw stores
// the source and the second doubles it. Source 51/255, 102/255, 0, 1: exact in RGBA8 too.
TEST_F(ResidentTest, BlendingReadsTheStoredTexture) {
  TextureSet set(*dev);
  const cpu::Vec4 c{51.0f / 255, 102.0f / 255, 0, 1};
  for (img::Format f : {img::Format::RGBA8, img::Format::RGBA32F}) {
    TextureId id{};
    ASSERT_TRUE(succeeded(set.create(4, 4, f), id));
    for (int k = 1; k <= 2; ++k) {
      ir::Result<pass::DrawReport> r = set.draw(constant_pass(c, cpu::BlendMode::OneOne), {}, id);
      ASSERT_TRUE(r.ok()) << r.message();
      img::Image out;
      ASSERT_TRUE(succeeded(set.read(id), out));
      const float want[4] = {k * 51.0f / 255, k * 102.0f / 255, 0, float(k)};
      for (uint32_t i = 0; i < 4; ++i) {
        // RGBA8 stores k·51 / 255 and alpha clamps to 1.
        const float w = f == img::Format::RGBA8 ? std::min(want[i], 1.0f) : want[i];
        EXPECT_EQ(out.at(3, 2)[i], w) << img::format_name(f) << " draw " << k << " channel " << i;
      }
    }
  }
}

// The texture a pass samples keeps its float copy current: sample it new (zeros), write,
// sample, write again, sample again — each read sees the latest write.
TEST_F(ResidentTest, SampledCopyFollowsLaterWrites) {
  TextureSet set(*dev);
  for (img::Format f : kFormats) {
    TextureId src{}, dst{};
    ASSERT_TRUE(succeeded(set.create(3, 3, f), src));
    ASSERT_TRUE(succeeded(set.create(3, 3, img::Format::RGBA32F), dst));
    const cpu::Vec4 half{0.5f / 3, 0.5f / 3, 0, 0};
    cpu::Pass copy =
        quad_pass(two_coords_vs(), copy_ps(), {half, half}, {}, cpu::BlendMode::Replace);
    StageTextures stages{};
    stages[0] = src;
    ASSERT_TRUE(set.draw(constant_pass({9, 9, 9, 9}, cpu::BlendMode::Replace), {}, dst).ok());
    ASSERT_TRUE(set.draw(copy, stages, dst).ok()); // src never written: it samples as zeros
    img::Image zeros;
    ASSERT_TRUE(succeeded(set.read(dst), zeros));
    EXPECT_EQ(zeros.rgba, std::vector<float>(3 * 3 * 4, 0.0f)) << img::format_name(f);
    for (float v : {0.25f, 0.75f}) { // RGBA8 stores round(v·255): 64 and 191
      ASSERT_TRUE(set.draw(constant_pass({v, v, v, v}, cpu::BlendMode::Replace), {}, src).ok());
      ir::Result<pass::DrawReport> r = set.draw(copy, stages, dst);
      ASSERT_TRUE(r.ok()) << r.message();
      img::Image out;
      ASSERT_TRUE(succeeded(set.read(dst), out));
      const float want = f == img::Format::RGBA8 ? std::round(v * 255) / 255 : v;
      EXPECT_EQ(out.at(1, 1)[0], want) << img::format_name(f) << " after writing " << v;
    }
  }
}

TEST_F(ResidentTest, BadCallsAreMessages) {
  TextureSet set(*dev);
  EXPECT_FALSE(set.create(0, 4, img::Format::RGBA32F).ok());
  EXPECT_FALSE(set.create(4, 0, img::Format::RGBA8).ok());
  EXPECT_FALSE(set.create(img::kMaxDimension + 1, 1, img::Format::RGBA8).ok());
  EXPECT_EQ(set.size(), 0u);

  const TextureId unknown = static_cast<TextureId>(42);
  img::Image out;
  EXPECT_NE(set.read(unknown).message().find("no texture 42"), std::string::npos);
  EXPECT_FALSE(set.upload(unknown, img::Image(1, 1)).ok());
  ir::Result<pass::DrawReport> r =
      set.draw(constant_pass({1, 1, 1, 1}, cpu::BlendMode::Replace), {}, unknown);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("no texture 42"), std::string::npos) << r.message();

  TextureId t{};
  ASSERT_TRUE(succeeded(set.create(4, 4, img::Format::RGBA32F), t));
  EXPECT_FALSE(set.upload(t, img::Image(4, 5)).ok()); // wrong size
  img::Image broken(4, 4);
  broken.rgba.resize(3); // pixel buffer shorter than its size
  EXPECT_FALSE(set.upload(t, broken).ok());
  StageTextures stages{};
  stages[0] = unknown;
  cpu::Pass copy = quad_pass(two_coords_vs(), copy_ps(), {{0, 0, 0, 0}, {0, 0, 0, 0}}, {},
                             cpu::BlendMode::Replace);
  r = set.draw(copy, stages, t);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("s0"), std::string::npos) << r.message();
  stages[0] = t; // sampling its own target
  r = set.draw(copy, stages, t);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message().find("own render target"), std::string::npos) << r.message();
  // None of it touched the texture.
  ASSERT_TRUE(succeeded(set.read(t), out));
  EXPECT_EQ(out.rgba, std::vector<float>(4 * 4 * 4, 0.0f));

  set.destroy(t);
  EXPECT_FALSE(set.read(t).ok());
  TextureId next{};
  ASSERT_TRUE(succeeded(set.create(4, 4, img::Format::RGBA32F), next));
  EXPECT_NE(next, t); // ids are not reused
  set.clear();
  EXPECT_EQ(set.size(), 0u);
}

// A pass with no resident texture at a stage samples the pass's own host image there, as
// Device::draw does: the same bits either way.
TEST_F(ResidentTest, HostImageStagesMatchDeviceDraw) {
  img::Image tex(4, 4);
  for (size_t i = 0; i < tex.rgba.size(); ++i) tex.rgba[i] = float(i % 13) / 7.0f;
  const cpu::Vec4 off{0.3f / 4, 0.6f / 4, 0, 0};
  cpu::Pass p =
      quad_pass(two_coords_vs(), two_taps_ps(), {off, {-off[0], off[1], 0, 0}},
                {{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f, 0.25f}}, cpu::BlendMode::Replace);
  p.textures[0].image = std::make_shared<const img::Image>(tex);
  p.textures[0].sampler.filter = cpu::Filter::Linear;
  img::Image host(6, 5);
  ASSERT_TRUE(dev->draw(p, host).ok());
  TextureSet set(*dev);
  TextureId t{};
  ASSERT_TRUE(succeeded(set.create(6, 5, img::Format::RGBA32F), t));
  ir::Result<pass::DrawReport> r = set.draw(p, {}, t);
  ASSERT_TRUE(r.ok()) << r.message();
  img::Image out;
  ASSERT_TRUE(succeeded(set.read(t), out));
  std::string where;
  EXPECT_TRUE(same_bits(host, out, &where)) << where;
  EXPECT_NE(out.rgba, img::Image(6, 5).rgba);
}

} // namespace
} // namespace tierlift::vulkan::test
