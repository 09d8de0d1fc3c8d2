// The coordinator writes a worker its next case before the answer to the one it runs comes
// back (runner.cpp, kCasesInFlight), and a worker that dies with a case written ahead of it
// costs only the case it was running. The workers here are small bash scripts that speak the
// protocol of runner.h.
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "tierlift/corpus/report.h"
#include "tierlift/corpus/runner.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

// Answers each case after a short time of "work"; the verdict says whether the next case was
// already waiting on its input when it answered (pass) or not (fail).
constexpr const char* kLookingAhead = R"(
while IFS= read -r line; do
  sleep 0.2
  if read -t 0; then verdict=pass; else verdict=fail; fi
  id=${line#\{\"id\":\"}; id=${id%%\"*}
  printf '{"id":"%s","verdict":"%s","stages":{}}\n' "$id" "$verdict"
done
)";

// Dies (SIGKILL) on case "b" the first time, in the folder given as $1 (a marker file says
// it happened); answers pass otherwise.
constexpr const char* kDiesOnB = R"(
while IFS= read -r line; do
  id=${line#\{\"id\":\"}; id=${id%%\"*}
  if [ "$id" = b ] && [ ! -e "$1/died" ]; then : >"$1/died"; kill -9 $$; fi
  printf '{"id":"%s","verdict":"pass","stages":{}}\n' "$id"
done
)";

std::vector<corpus::Case> cases(std::initializer_list<const char*> ids) {
  std::vector<corpus::Case> out;
  for (const char* id : ids) {
    corpus::Case c;
    c.id = id;
    out.push_back(c);
  }
  return out;
}

std::map<std::string, corpus::Verdict> run(const std::vector<corpus::Case>& cs, const char* script,
                                           const std::string& name) {
  const fs::path out =
      fs::temp_directory_path() / ("tierlift_in_flight_" + name + std::to_string(::getpid()));
  fs::remove_all(out);
  fs::create_directories(out);
  corpus::RunOptions o;
  o.worker_argv = {"/bin/bash", "-c", script, "worker", out.string()};
  o.jobs = 1;
  o.timeout_s = 20;
  o.rerun = false;
  o.out_dir = (out / "run").string();
  std::map<std::string, corpus::Verdict> verdicts;
  auto results = corpus::run_corpus(cs, o);
  EXPECT_TRUE(results) << results.message();
  if (results)
    for (const corpus::CaseResult& r : *results) verdicts[r.id] = r.verdict;
  fs::remove_all(out);
  return verdicts;
}

} // namespace

TEST(CorpusRunner, TheNextCaseIsWrittenBeforeTheAnswer) {
  auto v = run(cases({"a", "b", "c"}), kLookingAhead, "ahead");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v["a"], corpus::Verdict::Pass); // b was written while a ran
  EXPECT_EQ(v["b"], corpus::Verdict::Pass); // c while b ran
  EXPECT_EQ(v["c"], corpus::Verdict::Fail); // nothing is left to write after c
}

TEST(CorpusRunner, ACaseWrittenAheadOfADeathRunsInTheNextWorker) {
  // One worker: a, b written; a answered, c written; the worker dies on b with c waiting.
  auto v = run(cases({"a", "b", "c", "d"}), kDiesOnB, "death");
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v["a"], corpus::Verdict::Pass);
  EXPECT_EQ(v["b"], corpus::Verdict::Crash);
  EXPECT_EQ(v["c"], corpus::Verdict::Pass);
  EXPECT_EQ(v["d"], corpus::Verdict::Pass);
}

// run_corpus returns the results as it recorded them, not read back from results.jsonl: they
// must be what the file holds, the last line of each id (a rerun's, a resumed run's cases).
TEST(CorpusRunner, TheResultsReturnedAreWhatResultsJsonlHolds) {
  const fs::path out =
      fs::temp_directory_path() / ("tierlift_returned_" + std::to_string(::getpid()));
  fs::remove_all(out);
  fs::create_directories(out);
  corpus::RunOptions o;
  o.worker_argv = {"/bin/bash", "-c", kDiesOnB, "worker", out.string()};
  o.jobs = 1;
  o.timeout_s = 20;
  o.out_dir = (out / "run").string();
  o.repro = [](const corpus::Case& c) { return "again " + c.id; };
  auto first = corpus::run_corpus(cases({"a", "b", "c"}), o); // b dies, then passes its rerun
  ASSERT_TRUE(first) << first.message();
  o.resume = true;
  auto second = corpus::run_corpus(cases({"a", "b", "c", "d"}), o); // d alone runs
  ASSERT_TRUE(second) << second.message();
  const auto file = corpus::read_results_jsonl((out / "run" / "results.jsonl").string());
  ASSERT_EQ(second->size(), 4u);
  ASSERT_EQ(file.size(), 4u);
  for (size_t i = 0; i < file.size(); ++i)
    EXPECT_EQ(corpus::to_json((*second)[i]).dump(), corpus::to_json(file[i]).dump());
  EXPECT_EQ((*second)[1].id, "b");
  EXPECT_EQ((*second)[1].attempt, 2u); // the rerun's line, the last of b's two
  EXPECT_TRUE((*second)[1].flaky);
  EXPECT_EQ((*second)[3].repro, "again d");
  fs::remove_all(out);
}
