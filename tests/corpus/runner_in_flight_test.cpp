// The coordinator writes a worker its next cases before the answer to the one it runs comes
// back (runner.cpp, kCasesAhead: more of them when cases are fast), and a worker that dies with a
// case written ahead of it costs only the case it was running. The workers here are small bash
// scripts that speak the protocol of runner.h.
#include <filesystem>
#include <fstream>
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

// Answers every case at once, each saying it took $2 ms, except case "e": before answering
// it, the worker waits 0.5 s and counts the cases already waiting on its input, then answers
// "e" with the count in its note ("waiting N") and the waiting ones after it.
constexpr const char* kCountsWaiting = R"(
answer() { printf '{"id":"%s","verdict":"pass","stages":{},"ms":%s,"note":"%s"}\n' "$1" "$2" "$3"; }
while IFS= read -r line; do
  id=${line#\{\"id\":\"}; id=${id%%\"*}
  if [ "$id" != e ]; then answer "$id" "$2" ""; continue; fi
  sleep 0.5
  waiting=()
  while read -t 0; do
    IFS= read -r next
    next=${next#\{\"id\":\"}; waiting+=("${next%%\"*}")
  done
  answer e "$2" "waiting ${#waiting[@]}"
  for w in "${waiting[@]}"; do answer "$w" "$2" ""; done
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

std::vector<corpus::CaseResult> run_results(const std::vector<corpus::Case>& cs, const char* script,
                                            const std::string& name,
                                            const std::string& argument = "") {
  const fs::path out =
      fs::temp_directory_path() / ("tierlift_in_flight_" + name + std::to_string(::getpid()));
  fs::remove_all(out);
  fs::create_directories(out);
  corpus::RunOptions o;
  o.worker_argv = {"/bin/bash", "-c", script, "worker", out.string()};
  if (!argument.empty()) o.worker_argv.push_back(argument);
  o.jobs = 1;
  o.timeout_s = 20;
  o.rerun = false;
  o.out_dir = (out / "run").string();
  auto results = corpus::run_corpus(cs, o);
  EXPECT_TRUE(results) << results.message();
  fs::remove_all(out);
  return results ? *results : std::vector<corpus::CaseResult>{};
}

std::map<std::string, corpus::Verdict> run(const std::vector<corpus::Case>& cs, const char* script,
                                           const std::string& name) {
  std::map<std::string, corpus::Verdict> verdicts;
  for (const corpus::CaseResult& r : run_results(cs, script, name)) verdicts[r.id] = r.verdict;
  return verdicts;
}

// The note of case "e" when every case takes `ms` (kCountsWaiting).
std::string waiting_at_e(const char* ms) {
  const auto results =
      run_results(cases({"a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m",
                         "n", "o", "p", "q", "r", "s", "t", "u", "v", "w", "x", "y", "z"}),
                  kCountsWaiting, std::string("waiting") + ms, ms);
  for (const corpus::CaseResult& r : results)
    if (r.id == "e") return r.note;
  return "no answer for e";
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

// Cases that take 0.01 ms are written 15 ahead (the most, kCasesAhead: 2 ms of work would be
// 200 of them); cases that take 50 ms one ahead. "e" is the fifth case: when it runs, a..d have
// been answered, so the coordinator knows how long a case takes.
TEST(CorpusRunner, FastCasesAreWrittenManyAheadSlowOnesOne) {
  EXPECT_EQ(waiting_at_e("0.01"), "waiting 15");
  EXPECT_EQ(waiting_at_e("50"), "waiting 1");
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

// A worker's answer goes to results.jsonl as it came, with the repro command added; an answer
// that already names "repro" (here empty) is written again from its parse instead, so that
// the line never holds the key twice.
TEST(CorpusRunner, AnAnswerIsWrittenAsItCameWithTheReproAdded) {
  constexpr const char* kAnswers = R"(
while IFS= read -r line; do
  id=${line#\{\"id\":\"}; id=${id%%\"*}
  if [ "$id" = a ]; then
    printf '{"id":"a","verdict":"pass","stages":{},"extra":1}\n'
  else
    printf '{"id":"b","verdict":"pass","stages":{},"repro":""}\n'
  fi
done
)";
  const fs::path out =
      fs::temp_directory_path() / ("tierlift_as_came_" + std::to_string(::getpid()));
  fs::remove_all(out);
  corpus::RunOptions o;
  o.worker_argv = {"/bin/bash", "-c", kAnswers, "worker"};
  o.out_dir = out.string();
  o.repro = [](const corpus::Case& c) { return "again " + c.id; };
  ASSERT_TRUE(corpus::run_corpus(cases({"a", "b"}), o));
  std::ifstream in(out / "results.jsonl");
  std::string a, b;
  std::getline(in, a);
  std::getline(in, b);
  EXPECT_EQ(a, R"({"id":"a","verdict":"pass","stages":{},"extra":1,"repro":"again a"})");
  EXPECT_EQ(b.find("\"repro\""), b.rfind("\"repro\"")) << b; // once
  EXPECT_NE(b.find(R"("repro":"again b")"), std::string::npos) << b;
  fs::remove_all(out);
}
