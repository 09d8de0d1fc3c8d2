// `tierlift run`'s draw (run_job: prepare_pass, cpu::draw, the probes) on the article's listings
// over built-in textures. Expected values are hand-derived from the ramp texture: texel x holds (x
// + 0.5)/16, so a tap that lands on texel centre t reads (t + 0.5)/16 and a tap on the corner
// between t−1 and t reads their mean t/16 (clamped at the edges).
#include <gtest/gtest.h>

#include <bit>
#include <limits>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "program_helpers.h"
#include "run_flags.h"
#include "tierlift/assembly/constant_table.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/ir/result_diagnostics.h"

#include "run_job.h"

namespace tierlift::cpu {
namespace {

using pass::ConstSetting;
using pass::ProbePoint;
using pass::RegisterSetting;
using pass::RunDiagnostics;
using pass::RunRequest;
using pass::StageMask;
using pass::TextureSetting;
using ::tierlift::test::kRunRule;
using ::tierlift::test::run_job;
using ::tierlift::test::run_pass;
using ::tierlift::test::RunResult;

using namespace tierlift::cli; // the flag parsers

constexpr uint32_t N = 16;

std::shared_ptr<const ir::Program> listing(const std::string& name) {
  return test::listing_file("gpugems21/" + name);
}

ConstSetting cst(std::string_view text) {
  auto c = parse_const_setting(text);
  EXPECT_TRUE(c) << c.message();
  return c ? *c : ConstSetting{};
}

// Listings 3+4 (or 1+2 with taps = 8): tap k offset by (k + dx)/16 horizontally and dy/16
// vertically, weight 1/taps, ramp texture on every stage, bilinear, clamp.
RunRequest blur_request(int taps, double dx, double dy, img::Format format) {
  RunRequest r;
  r.vs = listing(taps == 4 ? "listing3_blur4_coords.vsh" : "listing1_blur8_coords.vsh");
  r.ps = listing(taps == 4 ? "listing4_blur4_weighted_sum.psh" : "listing2_blur8_weighted_sum.psh");
  r.width = r.height = N;
  r.format = format;
  for (int k = 0; k < taps; ++k) {
    r.constants.push_back(cst(fmt::format("vs:c{}={},{},0,0", k, (k + dx) / N, dy / N)));
    double w = 1.0 / taps;
    r.constants.push_back(cst(fmt::format("ps:c{}={},{},{},{}", k, w, w, w, w)));
  }
  r.attrs.push_back(*parse_attr_setting("v3=quad-uv"));
  for (uint32_t s = 0; s < (taps == 4 ? 4u : 1u); ++s)
    r.textures.push_back({s, "builtin:ramp:16x16"});
  r.filter = Filter::Linear;
  r.address = AddressMode::Clamp;
  r.threads = 2;
  return r;
}

double texel(int t) {
  return (std::clamp(t, 0, int(N) - 1) + 0.5) / N;
}

// The blur's value at pixel i: the mean over the taps k of read(i + k).
double tap_mean(int taps, int i, const std::function<double(int)>& read) {
  double s = 0;
  for (int k = 0; k < taps; ++k) s += read(i + k);
  return s / taps;
}

void expect_rows(const img::Image& im, const std::function<double(int)>& want, double tol) {
  for (uint32_t y = 0; y < im.height; ++y)
    for (uint32_t x = 0; x < im.width; ++x) {
      const float* p = im.at(x, y);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], want(int(x)), tol) << x << "," << y;
      ASSERT_NEAR(p[3], 1.0, tol) << x << "," << y;
    }
}

// With the half-texel offset, D3D9 pixel i's tap k lands on texel centre i + k.
TEST(RunJob, Listings3And4HalfTexelHitCentres) {
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(blur_request(4, 0.5, 0.5, img::Format::RGBA32F), d);
  ASSERT_TRUE(out.ok()) << ir::render_text(d.other, {});
  EXPECT_EQ(d.vs.error_count() + d.ps.error_count() + d.other.warning_count(), 0u);
  expect_rows(
      out->image, [](int i) { return tap_mean(4, i, texel); }, 1e-6);
  // Spot values: pixel 0 = (0.5+1.5+2.5+3.5)/64 = 0.125; pixel 15 = 15.5/16.
  EXPECT_NEAR(out->image.at(0, 0)[0], 0.125, 1e-7);
  EXPECT_NEAR(out->image.at(15, 3)[0], 0.96875, 1e-7);
}

// Without the offset, D3D9 pixel i's tap k lands on the corner between texels i+k−1 and
// i+k: the mean of the two.
TEST(RunJob, Listings3And4WithoutOffsetHitCorners) {
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(blur_request(4, 0.0, 0.0, img::Format::RGBA32F), d);
  ASSERT_TRUE(out.ok());
  expect_rows(
      out->image,
      [](int i) { return tap_mean(4, i, [](int j) { return (texel(j - 1) + texel(j)) / 2; }); },
      1e-6);
  EXPECT_NEAR(out->image.at(0, 0)[0], (1.0 / 32 + 1.0 / 16 + 2.0 / 16 + 3.0 / 16) / 4, 1e-7);
}

// Modern centres with the D3D9 offset: the taps move half a texel past the centres, onto
// the corners between texels i+k and i+k+1.
TEST(RunJob, ModernCentresShiftTheTaps) {
  RunRequest r = blur_request(4, 0.5, 0.5, img::Format::RGBA32F);
  r.conventions.pixel_center = ir::PixelCenter::Modern;
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(r, d);
  ASSERT_TRUE(out.ok());
  expect_rows(
      out->image,
      [](int i) { return tap_mean(4, i, [](int j) { return (texel(j) + texel(j + 1)) / 2; }); },
      1e-6);
}

// Listings 1+2 (vs_2_0 / ps_2_0, 8 taps from one sampler).
TEST(RunJob, Listings1And2EightTaps) {
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(blur_request(8, 0.5, 0.5, img::Format::RGBA32F), d);
  ASSERT_TRUE(out.ok());
  expect_rows(
      out->image, [](int i) { return tap_mean(8, i, texel); }, 1e-6);
}

// RGBA8: every stored value is k/255 within half an LSB of the exact result.
TEST(RunJob, Rgba8StoresRoundedValues) {
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(blur_request(4, 0.5, 0.5, img::Format::RGBA8), d);
  ASSERT_TRUE(out.ok());
  for (uint32_t x = 0; x < N; ++x) {
    double exact = 0;
    for (int k = 0; k < 4; ++k) exact += texel(int(x) + k) / 4;
    double stored = out->image.at(x, 7)[0] * 255.0;
    EXPECT_NEAR(stored, std::round(stored), 1e-4) << x;
    EXPECT_LE(std::abs(stored - exact * 255.0), 0.5 + 1e-4) << x;
  }
}

TEST(RunJob, ThreadCountDoesNotChangeTheImage) {
  RunRequest r = blur_request(8, 0.3, 0.7, img::Format::RGBA32F);
  r.textures = {{0, "builtin:noise:37x23"}};
  r.width = 41;
  r.height = 29;
  RunDiagnostics d1, d2;
  r.threads = 1;
  ir::Result<RunResult> one = run_job(r, d1);
  r.threads = 4;
  ir::Result<RunResult> four = run_job(r, d2);
  ASSERT_TRUE(one.ok() && four.ok());
  EXPECT_TRUE(one->image.rgba == four->image.rgba);
}

TEST(RunJob, MissingConstantIsAnErrorNamingTheRegister) {
  RunRequest r = blur_request(4, 0.5, 0.5, img::Format::RGBA32F);
  r.constants.erase(r.constants.begin() + 2); // vs:c1
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(r, d);
  EXPECT_FALSE(out.ok());
  ASSERT_EQ(d.vs.error_count(), 1u);
  EXPECT_EQ(d.vs.all()[0].rule, "constant-not-set");
  EXPECT_NE(d.vs.all()[0].message.find("c1"), std::string::npos);
  EXPECT_EQ(d.vs.all()[0].loc.line, 10u); // "add oT1, v3, c1"
  EXPECT_EQ(d.ps.error_count(), 0u);
}

// No texture: each tex reads (0,0,0,1), so r0 = Σ 0.25·(0,0,0,1) = (0,0,0,1), with a warning
// per stage.
TEST(RunJob, UnboundSamplersWarnAndReadOpaqueBlack) {
  RunRequest r = blur_request(4, 0.5, 0.5, img::Format::RGBA32F);
  r.textures.clear();
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(r, d);
  ASSERT_TRUE(out.ok());
  EXPECT_EQ(d.ps.warning_count(), 4u);
  EXPECT_EQ(out->image.at(3, 3)[0], 0.0f);
  EXPECT_NEAR(out->image.at(3, 3)[3], 1.0f, 1e-7);
}

// No listings: the pixel inputs pass through (oD0 = v0), probes read the stored value.
TEST(RunJob, NoListingsPassInputsThrough) {
  RunRequest r;
  r.width = 5;
  r.height = 3;
  r.format = img::Format::RGBA8;
  r.inputs.push_back(*parse_input_setting("v0=0.5,0.25,1,1"));
  r.probes.push_back({4, 2});
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(r, d);
  ASSERT_TRUE(out.ok());
  ASSERT_EQ(out->probes.size(), 1u);
  EXPECT_EQ(out->probes[0].value, (Vec4{128.0f / 255, 64.0f / 255, 1, 1})); // 127.5→128, 63.75→64
}

TEST(RunJob, BadTextureIsAnError) {
  RunRequest r = blur_request(4, 0.5, 0.5, img::Format::RGBA32F);
  r.textures[0].source = "/nonexistent/dir/tex.png";
  r.textures[1].source = "builtin:nosuchthing";
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(r, d);
  EXPECT_TRUE(ir::failed_with(out, kRunRule));
  ASSERT_EQ(d.other.error_count(), 2u);
  EXPECT_EQ(d.other.all()[0].rule, pass::kRuleTextureMissing);
  EXPECT_EQ(d.other.all()[1].rule, pass::kRuleTextureSpec); // a builtin word: usage
  EXPECT_EQ(out.message(), d.other.all()[0].message);       // the first error, rendered from `d`
}

// Errors after the pass is prepared (a probe outside the image, a draw the device refuses)
// go to diags.other, and the run's failure carries the same message.
TEST(RunJob, ProbeOutsideTheImageAndRefusedDrawFailTheRun) {
  RunRequest r;
  r.width = 5;
  r.height = 3;
  r.inputs.push_back(*parse_input_setting("v0=0.5,0.25,1,1"));
  r.probes.push_back({5, 0});
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(r, d);
  EXPECT_TRUE(ir::failed_with(out, kRunRule));
  ASSERT_EQ(d.other.error_count(), 1u);
  EXPECT_EQ(d.other.all()[0].rule, "probe");
  EXPECT_EQ(out.message(), "--probe 5,0 lies outside the 5x3 image");
  EXPECT_EQ(d.other.all()[0].message, out.message());

  Pass p;
  p.transformed.resize(3);
  p.triangles = {{0, 1, 7}};
  RunDiagnostics d2;
  ir::Result<RunResult> drawn = run_pass(p, 4, 4, img::Format::RGBA32F, {}, 1, d2);
  EXPECT_TRUE(ir::failed_with(drawn, kRunRule));
  ASSERT_EQ(d2.other.error_count(), 1u);
  EXPECT_EQ(d2.other.all()[0].rule, std::string(kDrawRule));
  EXPECT_EQ(drawn.message(), "triangle index out of range");
  EXPECT_EQ(d2.other.all()[0].message, drawn.message());
}

// Listing 2 without a vertex listing: t0..t7 are given constants, the texture an in-memory
// 4×4 image whose texel (x, y) holds x + 4y. Every tap at (0.375, 0.375) is exactly texel
// (1, 1) (§10.1), so with weights 1/8 the result is 5.
TEST(RunJob, PixelListingAloneOverAnInMemoryTexture) {
  auto tex = std::make_shared<img::Image>(4, 4, img::Format::RGBA32F);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x)
      for (int c = 0; c < 4; ++c) tex->at(x, y)[c] = static_cast<float>(x + 4 * y);
  RunRequest r;
  r.ps = listing("listing2_blur8_weighted_sum.psh");
  r.width = 3;
  r.height = 2;
  r.format = img::Format::RGBA32F;
  r.filter = Filter::Linear;
  for (int k = 0; k < 8; ++k) {
    r.inputs.push_back(*parse_input_setting(fmt::format("t{}=0.375,0.375,0,1", k)));
    r.constants.push_back(cst(fmt::format("c{}=0.125,0.125,0.125,0.125", k)));
  }
  r.textures.emplace_back(0, "numbered", tex);
  RunDiagnostics d;
  ir::Result<RunResult> out = run_job(r, d);
  ASSERT_TRUE(out.ok()) << ir::render_text(d.other, {});
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 3; ++x) EXPECT_FLOAT_EQ(out->image.at(x, y)[0], 5.0f);
}

std::shared_ptr<const ir::Program> program_text(const std::string& text) {
  return test::parsed(text, "<test>", true);
}

// The fragile case of §9.2: a D3D9 quad with u = 0..1 and no offset puts pixel i exactly on
// the corner u = i/W; point sampling, i = floor(u·W), picks texel i. That is determinate
// only where i/W is exact in float (power-of-two sizes; elsewhere float(i/W) may round
// below the corner and any fp32 device reads texel i − 1), so D3D9 is checked on those.
// With modern centres u = (i + 0.5)/W lies mid-texel: texel i at every size.
TEST(RunJob, PointSamplingOnTheD3D9QuadPicksTexelI) {
  auto vs = program_text("vs_1_1\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n");
  auto ps = program_text("ps_2_0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n");
  ASSERT_TRUE(vs && ps);
  for (auto [w, h] : {std::pair{8u, 4u}, std::pair{1u, 1u}, std::pair{1024u, 2u}, std::pair{7u, 5u},
                      std::pair{100u, 9u}, std::pair{33u, 1u}}) {
    const bool pow2 = (w & (w - 1)) == 0 && (h & (h - 1)) == 0;
    auto tex = std::make_shared<img::Image>(w, h, img::Format::RGBA32F);
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        tex->at(x, y)[0] = static_cast<float>(x);
        tex->at(x, y)[1] = static_cast<float>(y);
      }
    for (auto centre : {ir::PixelCenter::D3D9, ir::PixelCenter::Modern}) {
      if (centre == ir::PixelCenter::D3D9 && !pow2) continue;
      RunRequest r;
      r.vs = vs;
      r.ps = ps;
      r.width = w;
      r.height = h;
      r.format = img::Format::RGBA32F;
      r.conventions.pixel_center = centre;
      r.attrs.push_back(*parse_attr_setting("v3=quad-uv"));
      r.textures.emplace_back(0, "numbered", tex);
      RunDiagnostics d;
      ir::Result<RunResult> out = run_job(r, d);
      ASSERT_TRUE(out.ok());
      for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
          ASSERT_EQ(out->image.at(x, y)[0], static_cast<float>(x)) << w << "x" << h << " " << x;
          ASSERT_EQ(out->image.at(x, y)[1], static_cast<float>(y)) << w << "x" << h << " " << y;
        }
    }
  }
}

// --const parsed once (parse_const_assignment): a CTAB name becomes typed register settings
// directly. g_m (c4..c6, float4x3) takes 4 numbers per register; vs: picks the vertex
// table, no prefix tries both (g_both is in each); bools take one value; samplers refuse.
TEST(ConstAssignment, NamedConstantsBecomeTypedRegisters) {
  assembly::ConstantTable vs, ps;
  vs.constants = {{"g_m", assembly::ConstantSet::Float4, 4, 3, "float4x3"},
                  {"g_both", assembly::ConstantSet::Int4, 2, 1, "int4"},
                  {"g_on", assembly::ConstantSet::Bool, 5, 1, "bool"}};
  ps.constants = {{"g_both", assembly::ConstantSet::Float4, 9, 1, "float4"},
                  {"g_tex", assembly::ConstantSet::Sampler, 0, 1, "sampler2D"}};
  auto m = parse_const_assignment("g_m=1,2,3,4,5,6,7,8", &vs, &ps);
  ASSERT_TRUE(m) << m.message();
  ASSERT_EQ(m->size(), 2u); // two of the three registers given
  EXPECT_EQ((*m)[0].stage, StageMask::Vertex);
  EXPECT_EQ((*m)[0].file, ir::RegFile::Const);
  EXPECT_EQ((*m)[0].index, 4u);
  EXPECT_EQ((*m)[1].index, 5u);
  EXPECT_EQ((*m)[1].f, (Vec4{5, 6, 7, 8}));
  auto both = parse_const_assignment("g_both=1,2,3,4", &vs, &ps);
  ASSERT_TRUE(both) << both.message();
  ASSERT_EQ(both->size(), 2u);
  EXPECT_EQ((*both)[0].file, ir::RegFile::ConstInt);
  EXPECT_EQ((*both)[0].index, 2u);
  EXPECT_EQ((*both)[0].i, (std::array<int32_t, 4>{1, 2, 3, 4}));
  EXPECT_EQ((*both)[1].stage, StageMask::Pixel);
  EXPECT_EQ((*both)[1].file, ir::RegFile::Const);
  EXPECT_EQ((*both)[1].index, 9u);
  auto ps_only = parse_const_assignment("ps:g_both=1,2,3,4", &vs, &ps);
  ASSERT_TRUE(ps_only);
  ASSERT_EQ(ps_only->size(), 1u);
  EXPECT_EQ((*ps_only)[0].stage, StageMask::Pixel);
  auto on = parse_const_assignment("vs:g_on=true", &vs, &ps);
  ASSERT_TRUE(on);
  EXPECT_EQ((*on)[0].file, ir::RegFile::ConstBool);
  EXPECT_EQ((*on)[0].index, 5u);
  EXPECT_TRUE((*on)[0].b);
  // A register name is a register, tables or not.
  auto reg = parse_const_assignment("ps:c3=1,1,1,1", &vs, &ps);
  ASSERT_TRUE(reg);
  EXPECT_EQ((*reg)[0].index, 3u);
  for (const char* bad : {"g_m=1,2,3", "g_m=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16", "g_m=1,2,3,x",
                          "ps:g_m=1,2,3,4", "g_on=1,0", "g_tex=0,0,0,0", "g_nope=1,2,3,4"})
    EXPECT_FALSE(parse_const_assignment(bad, &vs, &ps)) << bad;
  EXPECT_NE(parse_const_assignment("g_tex=0", &vs, &ps).message().find("--texture"),
            std::string::npos);
}

TEST(RunOptions, ParsersAcceptAndRefuse) {
  auto c = parse_const_setting("ps:c7=1,-2.5,0,1e-3");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->stage, StageMask::Pixel);
  EXPECT_EQ(c->index, 7u);
  EXPECT_EQ(c->f, (Vec4{1, -2.5f, 0, 1e-3f}));
  auto i = parse_const_setting("vs:i3=1,2,3,-4");
  ASSERT_TRUE(i);
  EXPECT_EQ(i->file, ir::RegFile::ConstInt);
  EXPECT_EQ(i->i[3], -4);
  auto b = parse_const_setting("b2=true");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->stage, StageMask::Both);
  EXPECT_TRUE(b->b);
  for (const char* bad : {"c0=1,2,3", "c0", "x0=1,2,3,4", "c0=a,b,c,d", "b1=maybe", "i0=1.5,0,0,0",
                          "c99999=0,0,0,0", "gs:c0=0,0,0,0"})
    EXPECT_FALSE(parse_const_setting(bad)) << bad;
  // Numbers as def reads them: raw bit patterns, names, an 'f' suffix, denormals kept.
  auto d = parse_const_setting("c0=0x7fc00000,-inf,1e-40f,+0.5");
  ASSERT_TRUE(d) << d.message();
  EXPECT_EQ(std::bit_cast<uint32_t>(d->f[0]), 0x7fc00000u);
  EXPECT_EQ(d->f[1], -std::numeric_limits<float>::infinity());
  EXPECT_EQ(std::bit_cast<uint32_t>(d->f[2]), 71362u); // 1e-40 / 2^-149 = 71362.4 → 71362
  EXPECT_EQ(d->f[3], 0.5f);
  auto neg_zero = parse_const_setting("c0=-0,nan,NaN,0x0");
  ASSERT_TRUE(neg_zero) << neg_zero.message();
  EXPECT_EQ(std::bit_cast<uint32_t>(neg_zero->f[0]), 0x80000000u);
  for (const char* bad : {"c0=1e39,0,0,0", "c0=-0x1,0,0,0", "c0=0x,0,0,0", "c0=0x100000000,0,0,0"})
    EXPECT_FALSE(parse_const_setting(bad)) << bad;
  EXPECT_TRUE(parse_attr_setting("v15=quad-uv"));
  EXPECT_FALSE(parse_attr_setting("v16=quad-uv"));
  EXPECT_TRUE(parse_input_setting("t7=0,0,0,0"));
  EXPECT_FALSE(parse_input_setting("t8=0,0,0,0"));
  EXPECT_FALSE(parse_input_setting("v2=0,0,0,0"));
  EXPECT_TRUE(parse_texture_setting("s15=builtin:checker"));
  EXPECT_FALSE(parse_texture_setting("s16=a.png"));
  EXPECT_FALSE(parse_texture_setting("s0="));
  auto sz = parse_size("7x5");
  ASSERT_TRUE(sz);
  EXPECT_EQ((*sz)[0], 7u);
  EXPECT_TRUE(parse_size("16384x16384"));
  EXPECT_FALSE(parse_size("16385x1"));
  EXPECT_FALSE(parse_size("0x5"));
  EXPECT_FALSE(parse_size("99999999999999x1"));
  EXPECT_FALSE(parse_size("7"));
  EXPECT_TRUE(parse_probe("3,4"));
  EXPECT_FALSE(parse_probe("-1,4"));
  EXPECT_EQ(parse_filter("linear"), Filter::Linear);
  EXPECT_FALSE(parse_filter("anisotropic"));
  EXPECT_EQ(parse_address("mirror"), AddressMode::Mirror);
  EXPECT_EQ(parse_pixel_center("modern"), ir::PixelCenter::Modern);
}

} // namespace
} // namespace tierlift::cpu
