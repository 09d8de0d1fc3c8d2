// The order a run hands its cases out in (costliest first: shard.h, costliest_first), and
// the refusal of a run whose output folder holds one of its own inputs (output_guard.h).
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tierlift/corpus/output_guard.h"
#include "tierlift/corpus/report.h"
#include "tierlift/corpus/runner.h"
#include "tierlift/corpus/shard.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("tierlift_order_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

corpus::Case named(const std::string& id, const std::string& path = "") {
  corpus::Case c;
  c.id = id;
  c.path = path;
  return c;
}

std::vector<std::string> ids_in(const std::vector<corpus::Case>& cases,
                                const std::vector<size_t>& order) {
  std::vector<std::string> out;
  for (size_t i : order) out.push_back(cases[i].id);
  return out;
}

// Answers every case at once: pass, and "ms" the length of its id.
constexpr const char* kIdLengthMs = R"(
while IFS= read -r line; do
  id=${line#\{\"id\":\"}; id=${id%%\"*}
  printf '{"id":"%s","verdict":"pass","stages":{},"ms":%s}\n' "$id" "${#id}"
done
)";

// The ids of results.jsonl in the order of its lines: with one worker, the order the cases
// were handed out.
std::vector<std::string> jsonl_order(const fs::path& dir) {
  std::vector<std::string> out;
  std::ifstream in(dir / "results.jsonl");
  for (std::string line; std::getline(in, line);)
    out.push_back(nlohmann::json::parse(line)["id"].get<std::string>());
  return out;
}

} // namespace

TEST(CostliestFirst, ByTheCostsGivenAnUnnamedCaseAtTheirMedian) {
  const std::vector<corpus::Case> cases = {named("a"), named("b"), named("c"), named("d"),
                                           named("new")};
  // Known: 10, 300, 20, 40 µs; their median (the upper of the middle two) is 40, so "new"
  // ranks with d and after it (equal costs keep the input order).
  const std::map<std::string, uint64_t> costs = {{"a", 10}, {"b", 300}, {"c", 20}, {"d", 40}};
  EXPECT_EQ(ids_in(cases, corpus::costliest_first(cases, {0, 1, 2, 3, 4}, costs)),
            (std::vector<std::string>{"b", "d", "new", "c", "a"}));
  // Only the positions given are ordered.
  EXPECT_EQ(ids_in(cases, corpus::costliest_first(cases, {0, 2}, costs)),
            (std::vector<std::string>{"c", "a"}));
}

TEST(CostliestFirst, BySizeWithoutCostsOrWithAnotherCorpusCosts) {
  const fs::path dir = fresh_dir("size");
  std::ofstream(dir / "small.psh") << std::string(10, 'x');
  std::ofstream(dir / "large.psh") << std::string(3000, 'x');
  std::vector<corpus::Case> cases = {named("small", (dir / "small.psh").string()),
                                     named("large", (dir / "large.psh").string()), named("gen")};
  cases[2].generated = true;
  cases[2].text = std::string(200, 'y');
  const std::vector<std::string> by_size = {"large", "gen", "small"};
  EXPECT_EQ(ids_in(cases, corpus::costliest_first(cases, {0, 1, 2}, {})), by_size);
  // Costs that name none of these cases say nothing about them.
  EXPECT_EQ(ids_in(cases, corpus::costliest_first(cases, {0, 1, 2}, {{"other", 5}})), by_size);
  fs::remove_all(dir);
}

// One worker answers in the order it is given: results.jsonl's lines are the hand-out order.
// The first run goes by the costs given; a second run in the same folder, given none, by the
// times the first one recorded (the id's length, kIdLengthMs).
TEST(CorpusRunner, HandsOutTheCostliestCaseFirst) {
  const fs::path dir = fresh_dir("runner");
  corpus::RunOptions o;
  o.worker_argv = {"/bin/bash", "-c", kIdLengthMs, "worker"};
  o.jobs = 1;
  o.rerun = false;
  o.out_dir = (dir / "run").string();
  o.costs = {{"a", 1}, {"bbb", 30}, {"cc", 20}};
  const std::vector<corpus::Case> cases = {named("a"), named("bbb"), named("cc"), named("dddd")};
  ASSERT_TRUE(corpus::run_corpus(cases, o));
  // dddd is not named: it costs the median of 1, 20, 30.
  EXPECT_EQ(jsonl_order(dir / "run"), (std::vector<std::string>{"bbb", "cc", "dddd", "a"}));
  o.costs.clear();
  ASSERT_TRUE(corpus::run_corpus(cases, o));
  EXPECT_EQ(jsonl_order(dir / "run"), (std::vector<std::string>{"dddd", "bbb", "cc", "a"}));
  fs::remove_all(dir);
}

TEST(OutputGuard, AnInputThatIsAnOutputOfTheFolderIsRefused) {
  const fs::path dir = fresh_dir("guard");
  const fs::path out = dir / "out";
  const std::vector<std::string> inputs = {(out / "failures.csv").string(),
                                           (dir / "flakes.txt").string()};
  // A folder that does not exist yet, or holds no report, overwrites nothing.
  EXPECT_TRUE(corpus::refuse_outputs_among_inputs(out.string(), inputs));
  fs::create_directories(out);
  std::ofstream(out / "failures.csv") << "id,verdict,stage\nx,fail,parse\n";
  std::ofstream(dir / "flakes.txt") << "x\n";
  ir::Status s = corpus::refuse_outputs_among_inputs(out.string(), inputs);
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("failures.csv: refusing to run"), std::string::npos) << s.message();
  // The same file under another name (a hard link) is the same file.
  fs::create_hard_link(out / "failures.csv", dir / "baseline.csv");
  const std::vector<std::string> linked = {(dir / "baseline.csv").string()};
  s = corpus::refuse_outputs_among_inputs(out.string(), linked);
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("as " + (out / "failures.csv").string()), std::string::npos)
      << s.message();
  // run_corpus refuses a listing that is one of its reports, before writing anything.
  std::ofstream(out / "results.csv") << "ps_2_0\nmov oC0, c0\n";
  corpus::RunOptions o;
  o.worker_argv = {"/bin/bash", "-c", kIdLengthMs, "worker"};
  o.out_dir = out.string();
  auto r = corpus::run_corpus({named("listing", (out / "results.csv").string())}, o);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.diagnostics().front().rule, "write");
  EXPECT_FALSE(fs::exists(out / "results.jsonl"));
  std::ifstream in(out / "failures.csv");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}),
            "id,verdict,stage\nx,fail,parse\n");
  fs::remove_all(dir);
}

// A folder of the user's files (`-o .` in a project) is not written into: its summary.md or
// results.csv could be theirs. A new folder, an empty one, and one that holds a run's
// results.jsonl are.
TEST(OutputGuard, AFolderOfOtherFilesIsNotWrittenInto) {
  const fs::path dir = fresh_dir("foreign");
  EXPECT_TRUE(corpus::refuse_foreign_folder((dir / "new").string()));
  EXPECT_TRUE(corpus::refuse_foreign_folder(dir.string())); // empty
  std::ofstream(dir / "summary.md") << "my notes\n";
  ir::Status s = corpus::refuse_foreign_folder(dir.string());
  ASSERT_FALSE(s);
  EXPECT_NE(s.message().find("no results.jsonl"), std::string::npos) << s.message();
  corpus::RunOptions o;
  o.worker_argv = {"/bin/bash", "-c", kIdLengthMs, "worker"};
  o.out_dir = dir.string();
  auto run = corpus::run_corpus({named("a")}, o);
  ASSERT_FALSE(run);
  EXPECT_EQ(run.diagnostics().front().rule, "write");
  auto merged = corpus::merge_folders({(dir / "new").string()}, dir.string(), {});
  ASSERT_FALSE(merged);
  EXPECT_EQ(merged.diagnostics().front().rule, "write");
  std::ifstream in(dir / "summary.md");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "my notes\n");
  EXPECT_FALSE(fs::exists(dir / "results.jsonl"));
  // An earlier run's folder is run into again.
  std::ofstream(dir / "results.jsonl") << "";
  EXPECT_TRUE(corpus::refuse_foreign_folder(dir.string()));
  fs::remove_all(dir);
}
