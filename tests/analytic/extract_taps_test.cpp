// Taps read off Listings 1+2 and 3+4 with hand-chosen constants, and listings that are
// not of the linear blur form.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tierlift/analytic/taps.h"
#include "tierlift/assembly/parser.h"

namespace analytic = tierlift::analytic;
namespace assembly = tierlift::assembly;

namespace {

std::string read_listing(const std::string& name) {
  std::ifstream f(std::string(TIERLIFT_SOURCE_DIR) + "/listings/gpugems21/" + name,
                  std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

tierlift::ir::Program parse(const std::string& text, const std::string& name) {
  auto r = assembly::parse_text(text, name);
  EXPECT_TRUE(r.program.has_value()) << name << ": " << render_text(r.diags, r.sources);
  return r.program ? *r.program : tierlift::ir::Program{};
}

} // namespace

TEST(ExtractTaps, Listings1And2GiveTheConstantsBack) {
  auto vs = parse(read_listing("listing1_blur8_coords.vsh"), "listing1");
  auto ps = parse(read_listing("listing2_blur8_weighted_sum.psh"), "listing2");
  std::vector<analytic::Vec4> vsc, psc;
  for (int k = 0; k < 8; ++k) {
    vsc.push_back({(k - 3.5f) / 64.0f, 0.5f / 32.0f, 0.0f, 0.0f});
    float w = 0.03125f * static_cast<float>(k + 1);
    psc.push_back({w, 2 * w, 0.5f * w, 0.25f});
  }
  auto t = analytic::extract_taps(vs, vsc, ps, psc);
  ASSERT_TRUE(t) << t.message();
  EXPECT_EQ(t->texcoord_input, 3u);
  ASSERT_EQ(t->taps.size(), 8u);
  for (uint32_t k = 0; k < 8; ++k) {
    const analytic::Tap& tap = t->taps[k];
    EXPECT_EQ(tap.texcoord, k);
    EXPECT_EQ(tap.sampler, 0u);
    EXPECT_EQ(tap.offset[0], (static_cast<double>(k) - 3.5) / 64.0) << k;
    EXPECT_EQ(tap.offset[1], 0.5 / 32.0);
    double w = 0.03125 * (k + 1);
    EXPECT_EQ(tap.weight[0], w);
    EXPECT_EQ(tap.weight[1], 2 * w);
    EXPECT_EQ(tap.weight[2], 0.5 * w);
    EXPECT_EQ(tap.weight[3], 0.25);
  }
}

TEST(ExtractTaps, Listings3And4GiveTheConstantsBackClampedForPs13) {
  auto vs = parse(read_listing("listing3_blur4_coords.vsh"), "listing3");
  auto ps = parse(read_listing("listing4_blur4_weighted_sum.psh"), "listing4");
  std::vector<analytic::Vec4> vsc = {{-1.5f / 16, 0.5f / 16, 0, 0},
                                     {-0.5f / 16, 0.5f / 16, 0, 0},
                                     {0.5f / 16, 0.5f / 16, 0, 0},
                                     {1.5f / 16, 0.5f / 16, 0, 0}};
  std::vector<analytic::Vec4> psc = {{0.125f, 0.125f, 0.125f, 0.125f},
                                     {0.375f, 0.375f, 0.375f, 0.375f},
                                     {0.375f, 0.375f, 0.375f, 1.5f}, // alpha clamps to 1
                                     {0.125f, 0.125f, 0.125f, -0.5f}};
  auto t = analytic::extract_taps(vs, vsc, ps, psc);
  ASSERT_TRUE(t) << t.message();
  ASSERT_EQ(t->taps.size(), 4u);
  const double w[4] = {0.125, 0.375, 0.375, 0.125};
  for (uint32_t k = 0; k < 4; ++k) {
    EXPECT_EQ(t->taps[k].texcoord, k);
    EXPECT_EQ(t->taps[k].sampler, k); // ps_1_3: tex tN samples stage N
    EXPECT_EQ(t->taps[k].offset[0], (k - 1.5) / 16);
    EXPECT_EQ(t->taps[k].offset[1], 0.5 / 16);
    EXPECT_EQ(t->taps[k].weight[0], w[k]);
  }
  EXPECT_EQ(t->taps[2].weight[3], 1.0);
  EXPECT_EQ(t->taps[3].weight[3], -0.5);
  bool clamp_note = false;
  for (const auto& n : t->notes) clamp_note |= n.find("clamped") != std::string::npos;
  EXPECT_TRUE(clamp_note);
}

TEST(ExtractTaps, DefsOverrideApiConstantsAndModifiersAreFollowed) {
  auto vs = parse("vs.1.1\ndcl_position v0\ndcl_texcoord v7\ndef c1, 0.25, -0.5, 0, 0\n"
                  "mov oPos, v0\nadd r0, v7, c1\nsub oT0, r0, -c2\nmov oT1, v7\n",
                  "vs");
  auto ps = parse("ps.2.0\ndcl t0\ndcl t1\ndcl_2d s3\ntexld r0, t0, s3\ntexld r1, t1, s3\n"
                  "mul r2, r0, c0\nadd r2, r2, r1\nmul_x2 r2, r2, c1\nmov oC0, r2\n",
                  "ps");
  // c1 from the API is overridden by the def; c2 is added through "- -c2".
  std::vector<analytic::Vec4> vsc = {{9, 9, 9, 9}, {9, 9, 9, 9}, {0.125f, 0, 0, 0}};
  std::vector<analytic::Vec4> psc = {{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f, 0.25f}};
  auto t = analytic::extract_taps(vs, vsc, ps, psc);
  ASSERT_TRUE(t) << t.message();
  EXPECT_EQ(t->texcoord_input, 7u);
  ASSERT_EQ(t->taps.size(), 2u);
  EXPECT_EQ(t->taps[0].offset[0], 0.375);
  EXPECT_EQ(t->taps[0].offset[1], -0.5);
  EXPECT_EQ(t->taps[0].sampler, 3u);
  EXPECT_EQ(t->taps[0].weight[0], 0.25); // 0.5 · 0.25 · 2
  EXPECT_EQ(t->taps[1].offset[0], 0.0);
  EXPECT_EQ(t->taps[1].weight[2], 0.5); // 1 · 0.25 · 2
}

TEST(ExtractTaps, NonLinearListingsAreErrors) {
  auto vs = parse(read_listing("listing1_blur8_coords.vsh"), "listing1");
  std::vector<analytic::Vec4> c(8, analytic::Vec4{0.1f, 0.1f, 0.1f, 0.1f});
  // The message of extract_taps on a pair it must refuse.
  auto refusal = [&](const tierlift::ir::Program& v, const tierlift::ir::Program& p) {
    auto t = analytic::extract_taps(v, c, p, c);
    EXPECT_FALSE(t);
    return t ? std::string() : t.message();
  };
  struct Case {
    const char* ps;
    const char* needle;
  } cases[] = {
      {"ps.2.0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmul r0, r0, r0\nmov oC0, r0\n",
       "product of two samples"},
      {"ps.2.0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nadd r0, r0, c0\nmov oC0, r0\n",
       "constant term"},
      {"ps.2.0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0.bgra\n", "channel"},
      {"ps.2.0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\ntexld r1, r0, s0\nmov oC0, r1\n",
       "dependent read"},
      {"ps.2.0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nrcp r0.x, r0.x\nmov oC0, r0\n", "not linear"},
      {"ps.2.0\ndcl t0\ndcl_2d s0\ntexld_sat r0, t0, s0\nmov_sat oC0, r0\n", "_sat"},
      {"ps.2.0\ndcl t0\nmov oC0, t0\n", "t0"},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.ps);
    const std::string message = refusal(vs, parse(k.ps, "ps"));
    EXPECT_NE(message.find(k.needle), std::string::npos) << message;
  }
  // A vertex listing that swaps the texcoord's axes is not "texcoord · scale + offset"
  // (scaling alone is: scaled_coords_test.cpp).
  auto ps = parse(read_listing("listing2_blur8_weighted_sum.psh"), "listing2");
  auto swapped = parse("vs.2.0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                       "mul oT0, v3.yxzw, c0\n",
                       "vs");
  const std::string t = refusal(swapped, ps);
  EXPECT_NE(t.find("oT0.x is not texcoord.x"), std::string::npos) << t;
  EXPECT_NE(t.find("reads texcoord.y"), std::string::npos) << t;
  // oT1..oT7 never written.
  auto partial = parse("vs.2.0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                       "add oT0, v3, c0\n",
                       "vs");
  const std::string u = refusal(partial, ps);
  EXPECT_NE(u.find("never written"), std::string::npos) << u;
  // Wrong stages.
  EXPECT_FALSE(analytic::extract_taps(ps, c, vs, c));
}

TEST(ExtractTaps, Ps14TexldSamplesTheStageOfItsDestination) {
  auto vs = parse("vs.1.1\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                  "add oT0, v3, c0\nadd oT1, v3, c1\n",
                  "vs");
  auto ps = parse("ps.1.4\ntexld r2, t0\ntexld r5, t1\nmul r0, r2, c2\nmad r0, r5, c5, r0\n", "ps");
  std::vector<analytic::Vec4> vsc = {{0.25f, 0, 0, 0}, {-0.25f, 0.5f, 0, 0}};
  std::vector<analytic::Vec4> psc(6, analytic::Vec4{0, 0, 0, 0});
  psc[2] = {0.75f, 0.75f, 0.75f, 0.75f};
  psc[5] = {0.25f, 0.25f, 0.25f, 0.25f};
  auto t = analytic::extract_taps(vs, vsc, ps, psc);
  ASSERT_TRUE(t) << t.message();
  ASSERT_EQ(t->taps.size(), 2u);
  EXPECT_EQ(t->taps[0].texcoord, 0u);
  EXPECT_EQ(t->taps[0].sampler, 2u);
  EXPECT_EQ(t->taps[0].weight[1], 0.75);
  EXPECT_EQ(t->taps[1].texcoord, 1u);
  EXPECT_EQ(t->taps[1].sampler, 5u);
  EXPECT_EQ(t->taps[1].offset[0], -0.25);
  EXPECT_EQ(t->taps[1].offset[1], 0.5);
}
