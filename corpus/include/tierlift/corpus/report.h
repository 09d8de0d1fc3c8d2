// The files a corpus run leaves in its output folder, read by CI: results.jsonl (written by
// the runner as cases finish), and from it results.csv, failures.csv, junit.xml and
// summary.md. Each case is held against the expectations: a baseline of known failures,
// flake patterns and skip patterns (regular expressions on the id).
#pragma once

#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tierlift/corpus/result.h"
#include "tierlift/ir/result.h"

namespace tierlift::corpus {

struct Expectations {
  std::set<std::string> baseline; // ids expected to fail (failures.csv of an earlier run)
  std::vector<std::regex> flakes, skips;
  // Whether the id matches a pattern of the list.
  static bool matches(const std::vector<std::regex>& patterns, const std::string& id);
};

// failures.csv as a baseline: the first column of every line but a header ("id,…").
ir::Result<std::set<std::string>> read_baseline(const std::string& path);
// One ECMAScript regular expression per line; blank lines and lines starting with '#' are
// left out. A bad pattern is an error naming its line.
ir::Result<std::vector<std::regex>> read_patterns(const std::string& path);

// A case against the expectations.
enum class Outcome {
  Pass,
  Skipped,
  Unsupported,
  ExpectedFailure, // fails, and the baseline says so
  NewFailure,      // fails, and the baseline does not say so
  Fixed,           // in the baseline, and passes now
  Flake,           // failed, then passed on the rerun, or matches --flakes
};
std::string_view outcome_name(Outcome o);
Outcome classify(const CaseResult& r, const Expectations& e);

struct Tally {
  std::map<Outcome, size_t> outcomes;
  size_t cases = 0;
  // 0: every case as expected; 1: a new failure or a fixed baseline failure.
  int exit_code() const;
};
Tally tally(const std::vector<CaseResult>& results, const Expectations& e);

// results.jsonl: the last line of each id (a rerun's line follows the first), sorted by id.
// Lines that are not results (a line cut short by a kill) are left out.
std::vector<CaseResult> read_results_jsonl(const std::string& path);

// results.csv, failures.csv, junit.xml and summary.md in `dir` (each written whole, then
// renamed into place). `results` sorted by id. Nothing in them depends on which machine or
// how many shards ran the cases, except junit.xml's times.
ir::Status write_reports(const std::string& dir, const std::vector<CaseResult>& results,
                         const Expectations& e);

// failures.csv's content: the failing cases (flakes left out), one "id,verdict,stage" line
// each after the header — the baseline of the next run.
std::string failures_csv(const std::vector<CaseResult>& results, const Expectations& e);

// `tierlift test merge`: the results.jsonl of every folder, as one run, reported in `out`
// (results.jsonl too). An id in more than one folder is an error (shards overlap); so is an
// `out` that holds other files and no results.jsonl (output_guard.h).
ir::Result<std::vector<CaseResult>> merge_folders(const std::vector<std::string>& dirs,
                                                  const std::string& out, const Expectations& e);

} // namespace tierlift::corpus
