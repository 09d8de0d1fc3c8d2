// Baselines, flakes, results.jsonl and the merge of shard folders (tierlift/corpus/report.h).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unistd.h>

#include <gtest/gtest.h>

#include "tierlift/corpus/report.h"

namespace fs = std::filesystem;
using namespace tierlift::corpus;

namespace {

CaseResult result(const std::string& id, Verdict v) {
  CaseResult r;
  r.id = id;
  r.profile = "ps_2_0";
  r.verdict = v;
  r.stages.push_back({std::string(kStageParse), v == Verdict::Fail ? v : Verdict::Pass, "", 1});
  return r;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

fs::path fresh_dir(const std::string& name) {
  fs::path d =
      fs::temp_directory_path() / ("tierlift_report_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

} // namespace

TEST(CorpusExpectations, BaselineFlakesAndFixed) {
  Expectations e;
  e.baseline = {"known@1", "gone@2"};
  e.flakes.emplace_back("^wobbly/");
  EXPECT_EQ(classify(result("known@1", Verdict::Fail), e), Outcome::ExpectedFailure);
  EXPECT_EQ(classify(result("gone@2", Verdict::Pass), e), Outcome::Fixed);
  EXPECT_EQ(classify(result("new@3", Verdict::Crash), e), Outcome::NewFailure);
  EXPECT_EQ(classify(result("wobbly/x@4", Verdict::Fail), e), Outcome::Flake);
  CaseResult rerun = result("y@5", Verdict::Pass);
  rerun.flaky = true;
  EXPECT_EQ(classify(rerun, e), Outcome::Flake);
  EXPECT_EQ(classify(result("u@6", Verdict::Unsupported), e), Outcome::Unsupported);

  EXPECT_EQ(tally({result("known@1", Verdict::Fail)}, e).exit_code(), 0);
  EXPECT_EQ(tally({result("gone@2", Verdict::Pass)}, e).exit_code(), 1);
  EXPECT_EQ(tally({result("new@3", Verdict::Fail)}, e).exit_code(), 1);
}

TEST(CorpusExpectations, FailuresCsvReadsBackAsTheBaseline) {
  Expectations none;
  std::string csv = failures_csv(
      {result("a@1", Verdict::Fail), result("b@2", Verdict::Pass), result("c@3", Verdict::Timeout)},
      none);
  EXPECT_EQ(csv, "id,verdict,stage\na@1,fail,parse\nc@3,timeout,worker\n");
  fs::path p = fresh_dir("baseline") / "failures.csv";
  std::ofstream(p) << csv;
  auto ids = read_baseline(p.string());
  ASSERT_TRUE(ids);
  EXPECT_EQ(*ids, (std::set<std::string>{"a@1", "c@3"}));
}

TEST(CorpusExpectations, BadPatternNamesItsLine) {
  fs::path p = fresh_dir("patterns") / "skips.txt";
  std::ofstream(p) << "# comment\nok.*\n([unclosed\n";
  auto patterns = read_patterns(p.string());
  ASSERT_FALSE(patterns);
  EXPECT_NE(patterns.message().find("skips.txt:3:"), std::string::npos) << patterns.message();
}

TEST(CorpusResults, JsonlKeepsTheLastLineOfAnIdAndSkipsACutLine) {
  fs::path dir = fresh_dir("jsonl");
  CaseResult first = result("a@1", Verdict::Fail), again = result("a@1", Verdict::Pass);
  again.attempt = 2;
  again.flaky = true;
  first.difference = Difference{1, 2, 3, 1, 0.5f, std::numeric_limits<float>::quiet_NaN(), "x"};
  std::ofstream(dir / "results.jsonl") << to_json(result("b@2", Verdict::Pass)).dump() << "\n"
                                       << to_json(first).dump() << "\n"
                                       << to_json(again).dump() << "\n{\"id\": \"c@3\", \"verd";
  std::vector<CaseResult> rs = read_results_jsonl((dir / "results.jsonl").string());
  ASSERT_EQ(rs.size(), 2u);
  EXPECT_EQ(rs[0].id, "a@1");
  EXPECT_TRUE(rs[0].flaky);
  EXPECT_EQ(rs[0].attempt, 2u);
  EXPECT_EQ(rs[1].id, "b@2");
  // NaN survives JSON as a string.
  std::optional<CaseResult> back = from_json(to_json(first));
  ASSERT_TRUE(back && back->difference);
  EXPECT_TRUE(std::isnan(back->difference->vulkan));
  EXPECT_EQ(back->difference->channel, 1);
}

TEST(CorpusResults, MergedShardsReportWhatOneRunReports) {
  fs::path base = fresh_dir("merge");
  std::vector<CaseResult> all = {result("a@1", Verdict::Pass), result("b@2", Verdict::Fail),
                                 result("c@3", Verdict::Unsupported)};
  Expectations e;
  fs::create_directories(base / "one");
  std::ofstream(base / "one" / "results.jsonl") << to_json(all[2]).dump() << "\n"
                                                << to_json(all[0]).dump() << "\n"
                                                << to_json(all[1]).dump() << "\n";
  ASSERT_TRUE(write_reports((base / "one").string(), all, e));
  fs::create_directories(base / "s0");
  fs::create_directories(base / "s1");
  std::ofstream(base / "s0" / "results.jsonl") << to_json(all[1]).dump() << "\n";
  std::ofstream(base / "s1" / "results.jsonl") << to_json(all[2]).dump() << "\n"
                                               << to_json(all[0]).dump() << "\n";
  auto merged = merge_folders({(base / "s0").string(), (base / "s1").string()},
                              (base / "merged").string(), e);
  ASSERT_TRUE(merged) << merged.message();
  for (const char* f : {"results.csv", "failures.csv", "summary.md"})
    EXPECT_EQ(read(base / "merged" / f), read(base / "one" / f)) << f;
  EXPECT_NE(read(base / "merged" / "summary.md").find("| ps_2_0 | 3 | 1 | 1 | 0 | 0 | 1 | 0 |"),
            std::string::npos)
      << read(base / "merged" / "summary.md");
  // The same case in two shards is refused.
  EXPECT_FALSE(
      merge_folders({(base / "s1").string(), (base / "s1").string()}, (base / "m2").string(), e));
}
