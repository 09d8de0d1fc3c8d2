// corpus::generated_cases: the cases of `tierlift test --generate`, made on several threads.
#include <gtest/gtest.h>

#include "tierlift/corpus/cases.h"

using namespace tierlift::corpus;

// Each program depends on its index alone: one thread and four give the same cases, in order.
TEST(GeneratedCases, TheSameOnAnyNumberOfThreads) {
  auto made_one = generated_cases("ps_2_0", 7, 9, 1);
  auto made_four = generated_cases("ps_2_0", 7, 9, 4);
  ASSERT_TRUE(made_one && made_four);
  const std::vector<Case>& one = *made_one;
  const std::vector<Case>& four = *made_four;
  ASSERT_EQ(one.size(), 9u);
  ASSERT_EQ(four.size(), 9u);
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].id, four[i].id) << i;
    EXPECT_EQ(one[i].text, four[i].text) << i;
    EXPECT_EQ(four[i].gen_index, i);
  }
  EXPECT_NE(one[0].text, one[1].text); // nine different programs, not one nine times
}

// The id: the generator's inputs, then the hash of the text (as discover() names a file).
TEST(GeneratedCases, IdsNameProfileSeedIndexAndText) {
  auto made = generated_cases("vs_1_1", 3, 12, 2);
  ASSERT_TRUE(made);
  const std::vector<Case>& cs = *made;
  ASSERT_EQ(cs.size(), 12u);
  const Case& c = cs[11];
  EXPECT_TRUE(c.generated);
  EXPECT_TRUE(c.path.empty());
  EXPECT_EQ(c.gen_profile, "vs_1_1");
  EXPECT_EQ(c.gen_seed, 3u);
  EXPECT_EQ(c.id, "generated/vs_1_1/seed3/00011@" + hex64(fnv1a64(c.text)));
  EXPECT_EQ(c.text.rfind("vs_1_1", 0), 0u) << c.text; // the listing starts with its version
}

// An unknown profile fails; the shader model 3 ones, refused until the generator wrote
// them, give their cases (listings that start with their version).
TEST(GeneratedCases, AProfileTheGeneratorDoesNotWriteFails) {
  EXPECT_FALSE(generated_cases("ps_9_9", 1, 5, 2));
  for (const char* p : {"vs_2_x", "ps_2_x", "vs_3_0", "ps_3_0"}) {
    auto later = generated_cases(p, 1, 5, 2);
    ASSERT_TRUE(later) << p;
    ASSERT_EQ(later->size(), 5u) << p;
    EXPECT_EQ(later->front().text.rfind(p, 0), 0u) << later->front().text;
  }
  auto none = generated_cases("ps_2_0", 1, 0, 2);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());
}
