// compare_runs on hand-made runs: RGBA8 pixels that differ by one 8-bit step at most, where
// either run's device flagged a rounding midpoint, count as identical for the verdict (both
// roundings are right there); any other difference counts against it. The figures expected
// are counted by hand from the images below (RGBA8 target: max 1 LSB and ≥ 99.9 % of the
// pixels identical).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "tierlift/effects/graph/agreement.h"

namespace tierlift::effects {
namespace {

constexpr float kStep = 1.0f / 255;

// Every channel of every pixel at `steps` 8-bit steps.
img::Image flat(uint32_t w, uint32_t h, int steps, img::Format f = img::Format::RGBA8) {
  img::Image im(w, h, f);
  for (float& v : im.rgba) v = float(steps) * kStep;
  return im;
}

// One pass "p" into texture "t", which is also the frame.
GraphRun one_pass_run(const img::Image& result, std::vector<uint8_t> mask = {}) {
  GraphRun run;
  PassRecord rec;
  rec.pass = "p";
  rec.target = "t";
  rec.result = result;
  rec.midpoints = mask;
  run.passes.push_back(std::move(rec));
  if (!mask.empty()) run.midpoints["t"] = std::move(mask);
  return run;
}

struct Compared {
  RunAgreement agree;
  const PassAgreement& pass() const { return agree.passes.at(0); }
  const PassAgreement& frame() const { return agree.passes.at(1); }
};

Compared compare(const img::Image& a, std::vector<uint8_t> mask_a, const img::Image& b,
                 std::vector<uint8_t> mask_b) {
  const GraphRun ra = one_pass_run(a, std::move(mask_a)), rb = one_pass_run(b, std::move(mask_b));
  const ImageMap ia{{"t", a}}, ib{{"t", b}};
  ir::Result<RunAgreement> compared = compare_runs(ra, ia, rb, ib, "t");
  EXPECT_TRUE(compared.ok()) << compared.message();
  Compared c{compared ? *compared : RunAgreement{}};
  EXPECT_EQ(c.agree.passes.size(), 2u);
  return c;
}

// 2 × 2 at 100 steps; b's pixel 3 (x 1, y 1) is one step higher in red.
struct OneStep {
  img::Image a = flat(2, 2, 100), b = flat(2, 2, 100);
  OneStep() { b.at(1, 1)[0] += kStep; }
};

TEST(AgreementMidpoints, OneStepAtAFlaggedPixelCountsAsIdentical) {
  const OneStep s;
  for (int side = 0; side < 2; ++side) { // the mask from either run
    SCOPED_TRACE(side);
    const std::vector<uint8_t> mask{0, 0, 0, 1}, none;
    Compared c = side == 0 ? compare(s.a, mask, s.b, none) : compare(s.a, none, s.b, mask);
    for (const PassAgreement* row : {&c.pass(), &c.frame()}) {
      SCOPED_TRACE(row->pass);
      EXPECT_EQ(row->comparison.identical_pixels, 3u); // the plain comparison is unchanged
      EXPECT_DOUBLE_EQ(row->comparison.identical_share, 0.75);
      EXPECT_EQ(row->midpoint_pixels, 1u);
      EXPECT_DOUBLE_EQ(row->identical_share_with_midpoints, 1.0);
      EXPECT_TRUE(row->verdict.pass) << row->verdict.summary;
    }
    EXPECT_TRUE(c.agree.all_pass);
  }
}

TEST(AgreementMidpoints, OneStepAtAnUnflaggedPixelCountsAgainst) {
  const OneStep s;
  // Flags elsewhere (pixels 0..2), or no mask at all: 3 of 4 identical, below 99.9 %.
  for (const std::vector<uint8_t>& mask : {std::vector<uint8_t>{1, 1, 1, 0}, {}}) {
    Compared c = compare(s.a, mask, s.b, mask);
    for (const PassAgreement* row : {&c.pass(), &c.frame()}) {
      EXPECT_EQ(row->midpoint_pixels, 0u) << row->pass;
      EXPECT_DOUBLE_EQ(row->identical_share_with_midpoints, 0.75) << row->pass;
      EXPECT_FALSE(row->verdict.pass) << row->pass;
    }
    EXPECT_FALSE(c.agree.all_pass);
  }
}

TEST(AgreementMidpoints, TwoStepsAtAFlaggedPixelCountAgainst) {
  const std::vector<uint8_t> mask{0, 0, 0, 1};
  {
    OneStep s;
    s.b.at(1, 1)[0] += kStep; // red two steps up
    Compared c = compare(s.a, mask, s.b, {});
    EXPECT_EQ(c.pass().midpoint_pixels, 0u);
    EXPECT_DOUBLE_EQ(c.pass().identical_share_with_midpoints, 0.75);
    EXPECT_FALSE(c.pass().verdict.pass);
  }
  {
    OneStep s;
    s.b.at(1, 1)[2] -= 2 * kStep; // red one step up, blue two down: the pixel is no tie
    Compared c = compare(s.a, mask, s.b, mask);
    EXPECT_EQ(c.pass().midpoint_pixels, 0u);
    EXPECT_DOUBLE_EQ(c.pass().identical_share_with_midpoints, 0.75);
    EXPECT_FALSE(c.pass().verdict.pass);
  }
}

TEST(AgreementMidpoints, EachFlaggedPixelCountsTowardTheShare) {
  // 40 × 40 = 1600 pixels, three of them one step apart: 1597/1600 = 99.81 % identical
  // (fails); one flagged: 1598/1600 = 99.875 % (fails); two flagged: 1599/1600 = 99.94 %
  // (passes the 99.9 % target).
  img::Image a = flat(40, 40, 7), b = a;
  const std::pair<uint32_t, uint32_t> at[3] = {{0, 0}, {17, 5}, {39, 39}};
  for (const auto& [x, y] : at) b.at(x, y)[1] -= kStep;
  const std::pair<size_t, bool> cases[] = {{0, false}, {1, false}, {2, true}, {3, true}};
  for (const auto& [flagged, pass] : cases) {
    SCOPED_TRACE(flagged);
    std::vector<uint8_t> mask(1600, 0);
    for (size_t k = 0; k < flagged; ++k) mask[size_t(at[k].second) * 40 + at[k].first] = 1;
    Compared c = compare(a, {}, b, mask);
    EXPECT_EQ(c.pass().comparison.identical_pixels, 1597u);
    EXPECT_EQ(c.pass().midpoint_pixels, flagged);
    EXPECT_DOUBLE_EQ(c.pass().identical_share_with_midpoints, double(1597 + flagged) / 1600);
    EXPECT_EQ(c.pass().verdict.pass, pass) << c.pass().verdict.summary;
  }
}

TEST(AgreementMidpoints, FlaggedIdenticalPixelsAreNotMidpointPixels) {
  const img::Image a = flat(2, 2, 50);
  Compared c = compare(a, {1, 1, 1, 1}, a, {1, 1, 1, 1});
  EXPECT_EQ(c.pass().midpoint_pixels, 0u);
  EXPECT_EQ(c.pass().comparison.identical_pixels, 4u);
  EXPECT_TRUE(c.agree.all_pass);
}

TEST(AgreementMidpoints, MasksOfTheWrongSizeOrFormatAreIgnored) {
  const OneStep s;
  Compared wrong_size = compare(s.a, {0, 0, 0, 1, 1}, s.b, {1});
  EXPECT_EQ(wrong_size.pass().midpoint_pixels, 0u);
  EXPECT_FALSE(wrong_size.pass().verdict.pass);
  // RGBA32F has no 8-bit rounding: a 1/255 difference is far beyond 1e-5, flag or not.
  img::Image fa = flat(2, 2, 100, img::Format::RGBA32F), fb = fa;
  fb.at(1, 1)[0] += kStep;
  Compared f = compare(fa, {0, 0, 0, 1}, fb, {0, 0, 0, 1});
  EXPECT_EQ(f.pass().midpoint_pixels, 0u);
  EXPECT_FALSE(f.pass().verdict.pass);
}

TEST(AgreementMidpoints, TheFrameRowReadsTheRunsTextureMasks) {
  // The pass records carry no mask; the run's mask of texture "t" flags pixel 3, and a mask
  // of another texture must not be taken for it.
  const OneStep s;
  GraphRun ra = one_pass_run(s.a), rb = one_pass_run(s.b);
  ra.midpoints["other"] = {0, 0, 0, 1};
  const ImageMap ia{{"t", s.a}}, ib{{"t", s.b}};
  const RunAgreement before = *compare_runs(ra, ia, rb, ib, "t");
  ASSERT_EQ(before.passes.size(), 2u);
  EXPECT_EQ(before.passes[1].midpoint_pixels, 0u);
  EXPECT_FALSE(before.passes[1].verdict.pass);
  rb.midpoints["t"] = {0, 0, 0, 1};
  const RunAgreement after = *compare_runs(ra, ia, rb, ib, "t");
  ASSERT_EQ(after.passes.size(), 2u);
  EXPECT_EQ(after.passes[0].midpoint_pixels, 0u) << "the pass row keeps its own (empty) mask";
  EXPECT_FALSE(after.passes[0].verdict.pass);
  EXPECT_EQ(after.passes[1].pass, "frame");
  EXPECT_EQ(after.passes[1].midpoint_pixels, 1u);
  EXPECT_TRUE(after.passes[1].verdict.pass) << after.passes[1].verdict.summary;
  EXPECT_FALSE(after.all_pass);
}

} // namespace
} // namespace tierlift::effects
