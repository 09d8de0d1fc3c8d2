// Taps whose coordinates are scaled as well as offset (glow/quad4_coords.vsh and its vs.1.1
// form), passes reading two textures (the glow composite), the reads of a non-linear pass,
// and the full-screen position check. Expected values are the constants put in.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tierlift/analytic/taps.h"
#include "tierlift/assembly/parser.h"

namespace analytic = tierlift::analytic;

namespace {

tierlift::ir::Program load(const std::string& path) {
  std::ifstream f(std::string(TIERLIFT_SOURCE_DIR) + "/listings/" + path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  auto r = tierlift::assembly::parse_text(s.str(), path);
  EXPECT_TRUE(r.program.has_value()) << path << ": " << render_text(r.diags, r.sources);
  return r.program ? *r.program : tierlift::ir::Program{};
}

tierlift::ir::Program parse(const std::string& text) {
  auto r = tierlift::assembly::parse_text(text, "inline");
  EXPECT_TRUE(r.program.has_value()) << render_text(r.diags, r.sources);
  return r.program ? *r.program : tierlift::ir::Program{};
}

analytic::Vec4 splat(float w) {
  return {w, w, w, w};
}

// Offsets c0..c3 and scales c4..c7: oTk = v3 · c(k+4) + ck.
std::vector<analytic::Vec4> quad4_constants() {
  return {{0.125f, -0.25f, 9, 9}, {0.5f, 0.75f, 9, 9}, {-1.0f, 2.0f, 9, 9}, {0.0f, 0.0625f, 9, 9},
          {0.5f, 0.25f, 9, 9},    {1.5f, 1.0f, 9, 9},  {-2.0f, 0.0f, 9, 9}, {1.0f, 0.375f, 9, 9}};
}

void expect_quad4_taps(const std::vector<analytic::Tap>& taps) {
  const auto c = quad4_constants();
  ASSERT_EQ(taps.size(), 4u);
  for (uint32_t k = 0; k < 4; ++k) {
    EXPECT_EQ(taps[k].texcoord, k);
    EXPECT_EQ(taps[k].offset[0], c[k][0]) << k;
    EXPECT_EQ(taps[k].offset[1], c[k][1]) << k;
    EXPECT_EQ(taps[k].scale[0], c[k + 4][0]) << k;
    EXPECT_EQ(taps[k].scale[1], c[k + 4][1]) << k;
  }
}

} // namespace

TEST(ScaledCoords, Quad4CoordsGiveScaleAndOffsetPerAxis) {
  auto vs = load("glow/quad4_coords.vsh");
  auto ps = load("glow/downsample4.psh");
  std::vector<analytic::Vec4> psc = {splat(0.5f), splat(0.25f), splat(0.125f), splat(0.125f)};
  auto t = analytic::extract_taps(vs, quad4_constants(), ps, psc);
  ASSERT_TRUE(t) << t.message();
  expect_quad4_taps(t->taps);
  EXPECT_EQ(t->taps[0].weight[0], 0.5);
  EXPECT_EQ(t->taps[3].weight[3], 0.125);
  for (const analytic::Tap& tap : t->taps) EXPECT_EQ(tap.sampler, 0u); // texld tk, s0
}

TEST(ScaledCoords, Vs11FormGivesTheSameTapsOnFourStages) {
  auto vs = load("glow/quad4_coords_vs11.vsh"); // mul r, v3, c(k+4); add oTk, r, ck
  auto ps = load("glow/downsample4_ps13.psh");
  std::vector<analytic::Vec4> psc = {splat(0.5f), splat(0.25f), splat(0.125f), splat(0.125f)};
  auto t = analytic::extract_taps(vs, quad4_constants(), ps, psc);
  ASSERT_TRUE(t) << t.message();
  expect_quad4_taps(t->taps);
  for (uint32_t k = 0; k < 4; ++k) EXPECT_EQ(t->taps[k].sampler, k); // tex tk: stage k
}

TEST(ScaledCoords, AddListingsKeepScaleOne) {
  auto vs = load("gpugems21/listing1_blur8_coords.vsh");
  auto ps = load("gpugems21/listing2_blur8_weighted_sum.psh");
  std::vector<analytic::Vec4> c(8, splat(0.125f));
  auto t = analytic::extract_taps(vs, c, ps, c);
  ASSERT_TRUE(t) << t.message();
  for (const analytic::Tap& tap : t->taps) {
    EXPECT_EQ(tap.scale[0], 1.0);
    EXPECT_EQ(tap.scale[1], 1.0);
  }
}

// The composite: oC0.rgb = s0 + c0 · s1, oC0.a = s0.a.
TEST(ScaledCoords, CompositeReadsTwoSamplers) {
  auto vs = load("glow/quad4_coords.vsh");
  auto ps = load("glow/composite_add.psh");
  std::vector<analytic::Vec4> psc = {{0.75f, 0.5f, 0.25f, 8.0f}};
  auto t = analytic::extract_taps(vs, quad4_constants(), ps, psc);
  ASSERT_TRUE(t) << t.message();
  ASSERT_EQ(t->taps.size(), 2u);
  EXPECT_EQ(t->taps[0].texcoord, 0u);
  EXPECT_EQ(t->taps[0].sampler, 0u);
  EXPECT_EQ(t->taps[1].texcoord, 1u);
  EXPECT_EQ(t->taps[1].sampler, 1u);
  EXPECT_EQ(t->taps[0].weight, (std::array<double, 4>{1, 1, 1, 1}));
  EXPECT_EQ(t->taps[1].weight, (std::array<double, 4>{0.75, 0.5, 0.25, 0}));
  EXPECT_EQ(t->taps[1].scale[0], 1.5);
  EXPECT_EQ(t->taps[1].offset[1], 0.75);
}

// The ps.1.3 composites: stage 0 + c0 · stage 1, and with _x4 for intensities above 1.
TEST(ScaledCoords, Ps13CompositesReadTwoStages) {
  auto vs = load("glow/quad4_coords_vs11.vsh");
  std::vector<analytic::Vec4> psc = {{0.75f, 0.5f, 0.25f, 1.0f}};
  auto plain =
      analytic::extract_taps(vs, quad4_constants(), load("glow/composite_add_ps13.psh"), psc);
  ASSERT_TRUE(plain) << plain.message();
  ASSERT_EQ(plain->taps.size(), 2u);
  EXPECT_EQ(plain->taps[0].sampler, 0u);
  EXPECT_EQ(plain->taps[1].sampler, 1u);
  EXPECT_EQ(plain->taps[0].weight, (std::array<double, 4>{1, 1, 1, 1}));
  EXPECT_EQ(plain->taps[1].weight, (std::array<double, 4>{0.75, 0.5, 0.25, 0}));
  auto x4 =
      analytic::extract_taps(vs, quad4_constants(), load("glow/composite_add_x4_ps13.psh"), psc);
  ASSERT_TRUE(x4) << x4.message();
  ASSERT_EQ(x4->taps.size(), 2u);
  // Order of first sampling: t0, then t1.
  EXPECT_EQ(x4->taps[0].weight, (std::array<double, 4>{1, 1, 1, 1}));
  EXPECT_EQ(x4->taps[1].weight, (std::array<double, 4>{3, 2, 1, 0}));
}

TEST(ScaledCoords, ReadsOfTheExtractPass) {
  auto vs = load("glow/quad4_coords.vsh");
  for (const char* path : {"glow/extract_sources.psh", "glow/extract_sources_ps11.psh"}) {
    auto ps = load(path);
    // Not a weighted sum (rgb × alpha) …
    auto t = analytic::extract_taps(vs, quad4_constants(), ps, {});
    EXPECT_FALSE(t) << path;
    // … but its one read is placed.
    auto r = analytic::extract_reads(vs, quad4_constants(), ps);
    ASSERT_TRUE(r) << path << ": " << r.message();
    ASSERT_EQ(r->size(), 1u) << path;
    EXPECT_EQ((*r)[0].texcoord, 0u);
    EXPECT_EQ((*r)[0].sampler, 0u);
    EXPECT_EQ((*r)[0].offset[0], 0.125);
    EXPECT_EQ((*r)[0].scale[1], 0.25);
  }
  // A dependent read is an error with its position.
  auto dep = parse("ps.2.0\ndcl t0.xy\ndcl_2d s0\ntexld r0, t0, s0\ntexld r1, r0, s0\n"
                   "mov oC0, r1\n");
  auto r = analytic::extract_reads(vs, quad4_constants(), dep);
  EXPECT_FALSE(r);
  EXPECT_NE(r.message().find("line 5:"), std::string::npos) << r.message();
  EXPECT_NE(r.message().find("dependent read"), std::string::npos) << r.message();
}

TEST(ScaledCoords, PositionMustPassThrough) {
  EXPECT_TRUE(analytic::check_position_passthrough(load("glow/quad4_coords.vsh")));
  EXPECT_TRUE(analytic::check_position_passthrough(load("gpugems21/listing3_blur4_coords.vsh")));
  const std::string head = "vs.2.0\ndcl_position v0\ndcl_texcoord v3\n";
  auto moved = parse(head + "add oPos, v0, c0\nmov oT0, v3\n");
  std::string e = analytic::check_position_passthrough(moved).message();
  EXPECT_NE(e.find("line 4:1"), std::string::npos) << e;
  auto wrong_input = parse(head + "mov oPos, v3\n");
  EXPECT_NE(analytic::check_position_passthrough(wrong_input).message().find("v0"),
            std::string::npos);
  auto swizzled = parse(head + "mov oPos, v0.yxzw\n");
  EXPECT_FALSE(analytic::check_position_passthrough(swizzled));
  auto missing = parse(head + "mov oT0, v3\n");
  EXPECT_NE(analytic::check_position_passthrough(missing).message().find("never written"),
            std::string::npos);
}
