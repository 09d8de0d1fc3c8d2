// TextureSet::set_reuse_programs: one compile and one pipeline for a program drawn with
// several sets of constants (what `tierlift test` draws K times per case), each image the one
// its own constants give. Expected values are worked out by hand in the comments.
#include <cmath>
#include <limits>

#include "resident_fixture.h"
#include "tierlift/vulkan/pipeline_stats.h"

namespace tierlift::vulkan::test {
namespace {

TEST_F(ResidentTest, ReuseDrawsEveryConstantSetWithOnePipeline) {
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // oC0 = c0 · c1, per component, under rule 8 (NUMERICS.md: a ±0 factor gives +0).
  const auto ps = parse_listing("ps_2_0\nmul r0, c0, c1\nmov oC0, r0\n", "product.psh");
  const auto vs = two_coords_vs();
  struct Set {
    std::vector<cpu::Vec4> ps_constants;
    cpu::Vec4 want;
  };
  const Set sets[] = {
      // 1.5·2 = 3, 2·0.25 = 0.5, −1·3 = −3, 0.5·4 = 2.
      {{{1.5f, 2, -1, 0.5f}, {2, 0.25f, 3, 4}}, {3, 0.5f, -3, 2}},
      // Zero factors: +0 whatever the other one is (inf, NaN, −3: not −0).
      {{{0, 0, -0.0f, 0}, {inf, nan, -3, 5}}, {0, 0, 0, 0}},
      // A replicated c0 (the specialisation a per-set pipeline would take): 1·−0 = +0 (a ±0
      // factor), 1·7 = 7, 1·1e30 = 1e30, 1·−inf = −inf.
      {{{1, 1, 1, 1}, {-0.0f, 7, 1e30f, -inf}}, {0, 7, 1e30f, -inf}},
  };
  TextureSet set(*dev);
  set.set_reuse_programs(true);
  const long pipelines_before = pipeline_creations();
  for (const Set& s : sets) {
    TextureId target{};
    ASSERT_TRUE(succeeded(set.create(2, 2, img::Format::RGBA32F), target));
    const cpu::Pass p =
        quad_pass(vs, ps, {{0, 0, 0, 0}, {0, 0, 0, 0}}, s.ps_constants, cpu::BlendMode::Replace);
    ir::Result<pass::DrawReport> drawn = set.draw(p, StageTextures{}, target);
    ASSERT_TRUE(drawn.ok()) << drawn.message();
    img::Image out;
    ASSERT_TRUE(succeeded(set.read(target), out));
    img::Image want(2, 2, img::Format::RGBA32F);
    for (size_t px = 0; px < 4; ++px)
      for (size_t c = 0; c < 4; ++c) want.rgba[4 * px + c] = s.want[c];
    std::string where;
    EXPECT_TRUE(same_bits(want, out, &where)) << where;
    set.clear(); // the next set starts with new textures, as `tierlift test` does
  }
  EXPECT_EQ(pipeline_creations() - pipelines_before, 1);
  EXPECT_EQ(set.reused_pipelines(), 1u);
}

// draw_submission_ms (the second floor of bench/corpus_bench.cpp) counts the submissions that
// carry draws, and only those: one per draw when each is submitted alone, one for a batch of
// draws, none for uploads and read-backs (queue_submissions counts every submission).
TEST_F(ResidentTest, DrawSubmissionsCountOnlyTheSubmitsThatDraw) {
  const auto ps = parse_listing("ps_2_0\nmov oC0, c0\n", "constant.psh");
  const cpu::Pass p = quad_pass(two_coords_vs(), ps, {{0, 0, 0, 0}, {0, 0, 0, 0}},
                                {{0.5f, 0.25f, 1, 1}}, cpu::BlendMode::Replace);
  TextureSet set(*dev);
  TextureId target{};
  ASSERT_TRUE(succeeded(set.create(2, 2, img::Format::RGBA32F), target));
  const long before = draw_submissions();
  const double ms_before = draw_submission_ms();
  ASSERT_TRUE(set.upload(target, img::Image(2, 2, img::Format::RGBA32F)).ok());
  EXPECT_EQ(draw_submissions() - before, 0); // an upload draws nothing
  for (int i = 0; i < 2; ++i) ASSERT_TRUE(set.draw(p, StageTextures{}, target).ok());
  EXPECT_EQ(draw_submissions() - before, 2); // each draw submitted alone
  ASSERT_TRUE(set.set_batching(true).ok());
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(set.draw(p, StageTextures{}, target).ok());
  EXPECT_EQ(draw_submissions() - before, 2); // recorded, not submitted yet
  img::Image out;
  const long submits = queue_submissions();
  ASSERT_TRUE(succeeded(set.read(target), out));
  EXPECT_EQ(draw_submissions() - before, 3);   // the batch, at the read; the read-back not
  EXPECT_EQ(queue_submissions() - submits, 2); // but counted among all submissions
  EXPECT_GT(draw_submission_ms(), ms_before);
  EXPECT_EQ(out.rgba[0], 0.5f);
}

} // namespace
} // namespace tierlift::vulkan::test
