// The half-texel rule, shown both ways (docs/design.md "Three ways, one answer"): the CPU
// device runs Listings 1+2 and 3+4 on an RGBA32F target over seeded noise.
//   * Offsets (k + 0.5)/W: every tap hits a texel centre, and the device output equals the
//     analytic discrete convolution.
//   * Offsets k/W (no half texel): every tap lands on a texel edge/corner; the device output
//     equals the corner model and differs from the plain convolution by what it predicts.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "corner_model.h"
#include "tierlift/analytic/blur_model.h"
#include "tierlift/analytic/taps.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/image/builtin.h"
#include "tierlift/image/compare.h"

namespace cpu = tierlift::cpu;
namespace img = tierlift::img;
namespace analytic = tierlift::analytic;

namespace {

// At power-of-two sizes every coordinate the device computes in float is exact, and the
// device must match the model to 1e-6. At other sizes float texture coordinates are off by
// up to ~size·2^-24 texel, which moves bilinear weights by that much: there the design's
// RGBA32F agreement target (1e-5 of full scale) applies.
constexpr double kTolerance = 1e-6;
constexpr double kDesignTolerance = 1e-5;

std::shared_ptr<const tierlift::ir::Program> listing(const std::string& name) {
  std::ifstream f(std::string(TIERLIFT_SOURCE_DIR) + "/listings/gpugems21/" + name,
                  std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  auto r = tierlift::assembly::parse_text(s.str(), name);
  EXPECT_TRUE(r.program.has_value()) << render_text(r.diags, r.sources);
  return std::make_shared<const tierlift::ir::Program>(r.program ? *r.program
                                                                 : tierlift::ir::Program{});
}

struct Blur {
  std::string vs, ps;
  std::vector<int> taps;       // tap k samples texel i + k along the blur axis
  std::vector<double> weights; // exact binary fractions
  bool vertical = false;
};

Blur listings12() {
  // Horizontal, 8 taps at texels i−4 … i+3, binomial weights C(7, k)/128.
  return {
      "listing1_blur8_coords.vsh",
      "listing2_blur8_weighted_sum.psh",
      {-4, -3, -2, -1, 0, 1, 2, 3},
      {1 / 128.0, 7 / 128.0, 21 / 128.0, 35 / 128.0, 35 / 128.0, 21 / 128.0, 7 / 128.0, 1 / 128.0},
      false};
}
Blur listings34() {
  // Vertical, 4 taps at texels j−2 … j+1, weights 1, 3, 3, 1 over 8.
  return {"listing3_blur4_coords.vsh",
          "listing4_blur4_weighted_sum.psh",
          {-2, -1, 0, 1},
          {0.125, 0.375, 0.375, 0.125},
          true};
}

struct PassSetup {
  std::shared_ptr<const img::Image> source;
  std::vector<analytic::Vec4> vs_consts, ps_consts;
};

// Offsets along the blur axis are (k + half)/size; across it, half/size.
PassSetup make_setup(const Blur& b, const img::Image& source, bool half_texel) {
  PassSetup s;
  s.source = std::make_shared<const img::Image>(source);
  const float half = half_texel ? 0.5f : 0.0f;
  const float w = static_cast<float>(source.width), h = static_cast<float>(source.height);
  for (size_t k = 0; k < b.taps.size(); ++k) {
    float along = (static_cast<float>(b.taps[k]) + half) / (b.vertical ? h : w);
    float across = half / (b.vertical ? w : h);
    s.vs_consts.push_back(b.vertical ? analytic::Vec4{across, along, 0, 0}
                                     : analytic::Vec4{along, across, 0, 0});
    float wk = static_cast<float>(b.weights[k]);
    s.ps_consts.push_back({wk, wk, wk, wk});
  }
  return s;
}

img::Image run_cpu(const Blur& b, const PassSetup& s, std::string& error,
                   img::Format format = img::Format::RGBA32F) {
  cpu::Pass pass;
  pass.vertex_program = listing(b.vs);
  pass.pixel_program = listing(b.ps);
  pass.vs_constants.f = s.vs_consts;
  pass.ps_constants.f = s.ps_consts;
  for (auto& t : pass.textures) { // Listing 4 samples stages 0–3, Listing 2 sampler 0
    t.image = s.source;
    t.sampler.filter = cpu::Filter::Linear;
    t.sampler.address_u = t.sampler.address_v = cpu::AddressMode::Clamp;
  }
  cpu::set_full_screen_quad(pass, 0);                                     // dcl_position v0
  for (size_t i = 0; i < 4; ++i) pass.vertices[i].v[3] = cpu::kQuadUV[i]; // dcl_texcoord v3
  img::Image target(s.source->width, s.source->height, format);
  auto stats = cpu::draw(pass, target, 1);
  if (!stats.ok()) error = stats.message();
  return target;
}

analytic::PassModel clamp_linear_model() {
  analytic::PassModel m;
  m.sampler.filter = analytic::Filter::Linear;
  m.sampler.address_u = m.sampler.address_v = analytic::AddressMode::Clamp;
  return m;
}

double max_abs_difference(const img::Image& a, const img::Image& b) {
  auto c = img::compare(a, b);
  return c ? c->max_abs_all : INFINITY;
}

std::vector<analytic::Tap> taps_of(const Blur& b, const PassSetup& s) {
  auto vs = listing(b.vs);
  auto ps = listing(b.ps);
  auto t = analytic::extract_taps(*vs, s.vs_consts, *ps, s.ps_consts);
  if (!t) {
    ADD_FAILURE() << t.message();
    return {};
  }
  EXPECT_EQ(t->taps.size(), b.taps.size());
  return t->taps;
}

// The analytic model's blur of `noise` by `taps` lies within `tolerance` of `want`.
void expect_model_near(const std::vector<analytic::Tap>& taps, const img::Image& noise,
                       const img::Image& want, double tolerance) {
  auto model = analytic::blur_pass(taps, noise, clamp_linear_model());
  ASSERT_TRUE(model) << model.message();
  EXPECT_LE(max_abs_difference(*model, want), tolerance);
}

// Blur b drawn by the CPU device over `noise` (with or without the half texel), and its taps
// as extracted from the listings; nothing (a failure recorded) when the draw failed.
struct Drawn {
  img::Image device;
  std::vector<analytic::Tap> taps;
};
std::optional<Drawn> draw_blur(const Blur& b, const img::Image& noise, bool half_texel) {
  PassSetup s = make_setup(b, noise, half_texel);
  std::string error;
  img::Image device = run_cpu(b, s, error);
  if (!error.empty()) {
    ADD_FAILURE() << error;
    return std::nullopt;
  }
  return Drawn{std::move(device), taps_of(b, s)};
}

void check_with_half_texel(const Blur& b, uint32_t width = 64, uint32_t height = 32,
                           double tolerance = kTolerance) {
  img::Image noise = img::builtin_noise(width, height, 2026);
  const std::optional<Drawn> drawn = draw_blur(b, noise, true);
  ASSERT_TRUE(drawn);
  const auto& [device, taps] = *drawn;
  auto texel = tierlift::test::intended_texel_taps(taps, noise.width, noise.height);
  for (size_t k = 0; k < texel.size(); ++k) { // the taps are the ones meant
    EXPECT_EQ(b.vertical ? texel[k].dy : texel[k].dx, b.taps[k]);
    EXPECT_EQ(b.vertical ? texel[k].dx : texel[k].dy, 0);
  }
  auto conv = tierlift::test::discrete_convolution(texel, noise, clamp_linear_model());
  ASSERT_TRUE(conv) << conv.message();
  EXPECT_LE(max_abs_difference(device, *conv), tolerance);
  expect_model_near(taps, noise, *conv, tolerance);
}

void check_without_half_texel(const Blur& b, uint32_t width = 64, uint32_t height = 32,
                              double tolerance = kTolerance) {
  img::Image noise = img::builtin_noise(width, height, 7);
  const std::optional<Drawn> drawn = draw_blur(b, noise, false);
  ASSERT_TRUE(drawn);
  const auto& [device, taps] = *drawn;
  auto corner = tierlift::test::corner_model(taps, noise, clamp_linear_model());
  ASSERT_TRUE(corner) << corner.message();
  EXPECT_LE(max_abs_difference(device, *corner), tolerance);
  expect_model_near(taps, noise, device, tolerance);

  // The device differs from the plain convolution by exactly the predicted amount …
  auto plain = tierlift::test::discrete_convolution(
      tierlift::test::intended_texel_taps(taps, width, height), noise, clamp_linear_model());
  auto predicted = tierlift::test::predict_corner_difference(taps, noise, clamp_linear_model());
  ASSERT_TRUE(plain && predicted);
  double worst = 0;
  for (size_t i = 0; i < device.rgba.size(); ++i) {
    double measured = static_cast<double>(device.rgba[i]) - plain->rgba[i];
    worst = std::fmax(worst, std::fabs(measured - predicted->difference.rgba[i]));
  }
  EXPECT_LE(worst, tolerance);
  // … and that amount is far from negligible on noise (half a texel of blur and shift).
  EXPECT_GT(predicted->max_abs, 0.05);
  EXPECT_GT(max_abs_difference(device, *plain), 0.05);
}

} // namespace

TEST(HalfTexel, Listings1And2WithHalfTexelEqualTheDiscreteConvolution) {
  check_with_half_texel(listings12());
}
TEST(HalfTexel, Listings1And2WithoutHalfTexelFollowTheCornerModel) {
  check_without_half_texel(listings12());
}
TEST(HalfTexel, Listings3And4WithHalfTexelEqualTheDiscreteConvolution) {
  check_with_half_texel(listings34());
}
TEST(HalfTexel, Listings3And4WithoutHalfTexelFollowTheCornerModel) {
  check_without_half_texel(listings34());
}
TEST(HalfTexel, NonPowerOfTwoSizesMeetTheDesignTarget) {
  check_with_half_texel(listings12(), 60, 45, kDesignTolerance);
  check_without_half_texel(listings12(), 60, 45, kDesignTolerance);
  check_with_half_texel(listings34(), 37, 48, kDesignTolerance);
  check_without_half_texel(listings34(), 37, 48, kDesignTolerance);
}

TEST(HalfTexel, Rgba8TargetMeetsTheDesignTarget) {
  // The same pass stored to RGBA8 by the device and by the model: at most 1 LSB apart and
  // at least 99.9 % of pixels identical (docs/design.md), with and without the half texel.
  for (bool half : {true, false}) {
    Blur b = listings12();
    img::Image noise = img::builtin_noise(64, 32, 11);
    PassSetup s = make_setup(b, noise, half);
    std::string error;
    img::Image device = run_cpu(b, s, error, img::Format::RGBA8);
    ASSERT_TRUE(error.empty()) << error;
    analytic::PassModel m = clamp_linear_model();
    m.target_format = img::Format::RGBA8;
    auto model = analytic::blur_pass(taps_of(b, s), noise, m);
    ASSERT_TRUE(model) << model.message();
    auto c = img::compare(device, *model);
    ASSERT_TRUE(c);
    auto verdict = img::judge(*c, img::Format::RGBA8);
    RecordProperty(half ? "rgba8_half_texel" : "rgba8_no_half_texel", verdict.summary);
    EXPECT_TRUE(verdict.pass) << (half ? "half texel: " : "no half texel: ") << verdict.summary;
  }
}
