// --shard I/N with --shard-costs: a partition of the cases (each in exactly one shard),
// balanced by the earlier run's times (longest first, each to the lightest shard), the same
// whatever order the cases come in.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <unistd.h>

#include "tierlift/corpus/shard.h"

namespace tierlift::corpus {
namespace {

std::vector<Case> named(const std::vector<std::string>& ids) {
  std::vector<Case> out;
  for (const std::string& id : ids) out.push_back(Case{id, {}, {}, false, {}, 0, 0});
  return out;
}
std::vector<std::string> ids(const std::vector<Case>& cases) {
  std::vector<std::string> out;
  for (const Case& c : cases) out.push_back(c.id);
  std::sort(out.begin(), out.end());
  return out;
}

// Costs 7, 5, 4, 3, 2, 1 into two shards, by hand: 7 → A; 5 → B; 4 → B (9); 3 → A (10);
// 2 → B (11); 1 → A (11). Totals 11 and 11, where a split by count could give 16 and 6.
TEST(CorpusShardCosts, LongestFirstToTheLightestShard) {
  const std::map<std::string, uint64_t> costs{{"a", 7}, {"b", 5}, {"c", 4},
                                              {"d", 3}, {"e", 2}, {"f", 1}};
  const std::vector<Case> cases = named({"a", "b", "c", "d", "e", "f"});
  EXPECT_EQ(ids(balanced_shard(cases, costs, 0, 2)), (std::vector<std::string>{"a", "d", "f"}));
  EXPECT_EQ(ids(balanced_shard(cases, costs, 1, 2)), (std::vector<std::string>{"b", "c", "e"}));
}

// Every case in exactly one shard, for several shard counts; the input order does not matter.
TEST(CorpusShardCosts, APartitionIndependentOfTheInputOrder) {
  std::vector<std::string> all;
  std::map<std::string, uint64_t> costs;
  for (int i = 0; i < 40; ++i) {
    all.push_back("case" + std::to_string(i));
    if (i % 3) costs["case" + std::to_string(i)] = static_cast<uint64_t>((i * 37) % 11);
  }
  std::vector<std::string> reversed(all.rbegin(), all.rend());
  for (size_t n = 1; n <= 5; ++n) {
    std::multiset<std::string> seen;
    for (size_t i = 0; i < n; ++i) {
      const std::vector<std::string> shard = ids(balanced_shard(named(all), costs, i, n));
      EXPECT_EQ(shard, ids(balanced_shard(named(reversed), costs, i, n))) << i << "/" << n;
      seen.insert(shard.begin(), shard.end());
    }
    EXPECT_EQ(seen, std::multiset<std::string>(all.begin(), all.end())) << n;
  }
}

// A case the costs do not name costs their median: with known 1, 2 and 9 (median 2), the
// unknown "u" is placed as a 2 — 9 → A; 2 → B; u (2) → B (4); 1 → B (5).
TEST(CorpusShardCosts, UnknownCasesCostTheMedian) {
  const std::map<std::string, uint64_t> costs{{"a", 9}, {"b", 2}, {"c", 1}};
  const std::vector<Case> cases = named({"a", "b", "c", "u"});
  EXPECT_EQ(ids(balanced_shard(cases, costs, 0, 2)), (std::vector<std::string>{"a"}));
  EXPECT_EQ(ids(balanced_shard(cases, costs, 1, 2)), (std::vector<std::string>{"b", "c", "u"}));
}

TEST(CorpusShardCosts, ReadsTheFirstAttemptsTimesInMicroseconds) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("tierlift_shard_costs_" + std::to_string(::getpid()) + ".jsonl");
  std::ofstream(path) << R"({"id":"x","ms":1.5,"attempt":1})"
                      << "\n"
                      << R"({"id":"x","ms":90,"attempt":2})"
                      << "\n"
                      << "not json\n"
                      << R"({"id":"y","ms":0.25})"
                      << "\n";
  auto costs = read_costs(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(costs) << costs.message();
  EXPECT_EQ(*costs, (std::map<std::string, uint64_t>{{"x", 1500}, {"y", 250}}));
  EXPECT_FALSE(read_costs("/nonexistent/results.jsonl"));
}

} // namespace
} // namespace tierlift::corpus
