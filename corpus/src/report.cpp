// results.csv, failures.csv, junit.xml, summary.md from the results of a run (or of the
// shards of one: merge_folders). Sorted by id and free of times (junit.xml aside), so that
// a merged run reports byte for byte what the single-machine run reports.
#include "tierlift/corpus/report.h"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "tierlift/corpus/output_guard.h"
#include "tierlift/io/bounded_read.h"
#include "tierlift/io/output_file.h"

namespace tierlift::corpus {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    std::string line = text.substr(pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out.push_back(std::move(line));
    pos = nl + 1;
  }
  return out;
}

std::string csv_cell(std::string s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
}

std::string xml(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '&': out += "&amp;"; break;
    case '"': out += "&quot;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string stage_or_worker(const CaseResult& r) {
  std::string s = r.failed_stage();
  return s.empty() ? std::string(is_failure(r.verdict) ? "worker" : "") : s;
}

std::string why(const CaseResult& r) {
  for (const StageResult& s : r.stages)
    if (is_failure(s.verdict) || s.verdict == Verdict::Unsupported) return s.message;
  return r.note;
}

std::string results_csv(const std::vector<CaseResult>& results, const Expectations& e) {
  std::string out = "id,profile,verdict,outcome";
  for (std::string_view s : kStages) out += fmt::format(",{}", s);
  out += "\n";
  for (const CaseResult& r : results) {
    out += fmt::format("{},{},{},{}", csv_cell(r.id), r.profile, verdict_name(r.verdict),
                       outcome_name(classify(r, e)));
    for (std::string_view name : kStages) {
      std::string_view v = "";
      for (const StageResult& s : r.stages)
        if (s.stage == name) v = verdict_name(s.verdict);
      out += fmt::format(",{}", v);
    }
    out += "\n";
  }
  return out;
}

std::string junit_xml(const std::vector<CaseResult>& results, const Expectations& e) {
  const Tally t = tally(results, e);
  auto count = [&](Outcome o) { return t.outcomes.count(o) ? t.outcomes.at(o) : 0; };
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
  out += fmt::format("  <testsuite name=\"tierlift test\" tests=\"{}\" failures=\"{}\" "
                     "skipped=\"{}\">\n",
                     t.cases, count(Outcome::NewFailure) + count(Outcome::Fixed),
                     count(Outcome::Skipped) + count(Outcome::Unsupported) +
                         count(Outcome::ExpectedFailure));
  for (const CaseResult& r : results) {
    out += fmt::format("    <testcase classname=\"{}\" name=\"{}\" time=\"{:.3f}\"",
                       r.profile.empty() ? "unknown" : r.profile, xml(r.id), r.ms / 1000.0);
    const Outcome o = classify(r, e);
    std::string body;
    if (o == Outcome::NewFailure)
      body = fmt::format("<failure type=\"{}\" message=\"{}: {}\">{}</failure>",
                         verdict_name(r.verdict), stage_or_worker(r), xml(why(r)), xml(r.repro));
    else if (o == Outcome::Fixed)
      body = "<failure type=\"fixed\" message=\"in the baseline of expected failures, passes "
             "now: update the baseline\"/>";
    else if (o == Outcome::Skipped || o == Outcome::Unsupported || o == Outcome::ExpectedFailure)
      body = fmt::format("<skipped message=\"{}: {}\"/>", outcome_name(o), xml(why(r)));
    out += body.empty() ? "/>\n" : ">" + body + "</testcase>\n";
  }
  return out + "  </testsuite>\n</testsuites>\n";
}

std::string summary_md(const std::vector<CaseResult>& results, const Expectations& e) {
  const Tally t = tally(results, e);
  std::string out = "# tierlift test\n\n";
  out += fmt::format("{} cases:", t.cases);
  for (const auto& [o, n] : t.outcomes) out += fmt::format(" {} {},", n, outcome_name(o));
  if (out.back() == ',') out.pop_back();
  out += fmt::format(".\n\nVerdict: **{}**\n\n",
                     t.exit_code() == 0 ? "as expected" : "NOT as expected");
  out += "## Per stage\n\n| stage | pass | fail | unsupported | skip |\n|---|---|---|---|---|\n";
  for (std::string_view name : kStages) {
    std::map<Verdict, size_t> n;
    for (const CaseResult& r : results)
      for (const StageResult& s : r.stages)
        if (s.stage == name) ++n[s.verdict];
    out += fmt::format("| {} | {} | {} | {} | {} |\n", name, n[Verdict::Pass], n[Verdict::Fail],
                       n[Verdict::Unsupported], n[Verdict::Skip]);
  }
  out += "\n## Per profile\n\n| profile | cases | pass | fail | crash | timeout | unsupported "
         "| skip |\n|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, std::map<Verdict, size_t>> per;
  for (const CaseResult& r : results) ++per[r.profile.empty() ? "(unknown)" : r.profile][r.verdict];
  for (auto& [profile, n] : per) {
    size_t cases = 0;
    for (const auto& [v, k] : n) cases += k;
    out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", profile, cases,
                       n[Verdict::Pass], n[Verdict::Fail], n[Verdict::Crash], n[Verdict::Timeout],
                       n[Verdict::Unsupported], n[Verdict::Skip]);
  }
  auto list = [&](Outcome which, std::string_view title) {
    std::string part;
    for (const CaseResult& r : results) {
      if (classify(r, e) != which) continue;
      part += fmt::format("- `{}` ({} {}): {}\n", r.id, stage_or_worker(r), verdict_name(r.verdict),
                          why(r));
      if (!r.repro.empty()) part += fmt::format("  reproduce: `{}`\n", r.repro);
    }
    if (!part.empty()) out += fmt::format("\n## {}\n\n{}", title, part);
  };
  list(Outcome::NewFailure, "New failures");
  list(Outcome::Fixed, "Baseline failures that pass now (update the baseline)");
  list(Outcome::Flake, "Flakes");
  list(Outcome::ExpectedFailure, "Expected failures (baseline)");
  list(Outcome::Unsupported, "Unsupported");
  return out;
}

ir::Status write(const std::string& dir, const char* name, const std::string& text) {
  return io::write_output((std::filesystem::path(dir) / name).string(), text);
}

} // namespace

bool Expectations::matches(const std::vector<std::regex>& patterns, const std::string& id) {
  for (const std::regex& p : patterns)
    if (std::regex_search(id, p)) return true;
  return false;
}

ir::Result<std::set<std::string>> read_baseline(const std::string& path) {
  ir::Result<std::string> text = io::read_bounded(path, {uint64_t{64} << 20, "baseline"});
  if (!text) return text.failure();
  std::set<std::string> ids;
  for (const std::string& line : lines_of(*text)) {
    if (line.empty() || line.starts_with("id,") || line.starts_with("#")) continue;
    std::string id = line.substr(0, line.find(','));
    if (id.size() >= 2 && id.front() == '"') id = id.substr(1, id.size() - 2);
    ids.insert(id);
  }
  return ids;
}

ir::Result<std::vector<std::regex>> read_patterns(const std::string& path) {
  ir::Result<std::string> text = io::read_bounded(path, {uint64_t{16} << 20, "pattern list"});
  if (!text) return text.failure();
  std::vector<std::regex> out;
  size_t number = 0;
  for (const std::string& line : lines_of(*text)) {
    ++number;
    if (line.empty() || line.starts_with("#")) continue;
    try {
      out.emplace_back(line);
    } catch (const std::regex_error& err) {
      return ir::fail(
          path, "usage",
          fmt::format("{}:{}: bad regular expression '{}': {}", path, number, line, err.what()));
    }
  }
  return out;
}

std::string_view outcome_name(Outcome o) {
  static constexpr std::string_view names[] = {
      "pass", "skipped", "unsupported", "expected-failure", "new-failure", "fixed", "flake"};
  return names[static_cast<int>(o)];
}

Outcome classify(const CaseResult& r, const Expectations& e) {
  const bool expected = e.baseline.contains(r.id);
  if (r.verdict == Verdict::Skip) return Outcome::Skipped;
  if (r.verdict == Verdict::Unsupported) return Outcome::Unsupported;
  if (r.flaky) return Outcome::Flake;
  if (is_failure(r.verdict)) {
    if (expected) return Outcome::ExpectedFailure;
    return Expectations::matches(e.flakes, r.id) ? Outcome::Flake : Outcome::NewFailure;
  }
  return expected ? Outcome::Fixed : Outcome::Pass;
}

int Tally::exit_code() const {
  return outcomes.count(Outcome::NewFailure) || outcomes.count(Outcome::Fixed) ? 1 : 0;
}

Tally tally(const std::vector<CaseResult>& results, const Expectations& e) {
  Tally t;
  t.cases = results.size();
  for (const CaseResult& r : results) ++t.outcomes[classify(r, e)];
  return t;
}

std::vector<CaseResult> read_results_jsonl(const std::string& path) {
  std::map<std::string, CaseResult> last;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) continue;
    if (std::optional<CaseResult> r = from_json(j)) last[r->id] = std::move(*r);
  }
  std::vector<CaseResult> out;
  for (auto& [id, r] : last) out.push_back(std::move(r));
  return out;
}

std::string failures_csv(const std::vector<CaseResult>& results, const Expectations& e) {
  std::string out = "id,verdict,stage\n";
  for (const CaseResult& r : results) {
    const Outcome o = classify(r, e);
    if (o == Outcome::NewFailure || o == Outcome::ExpectedFailure)
      out += fmt::format("{},{},{}\n", csv_cell(r.id), verdict_name(r.verdict), stage_or_worker(r));
  }
  return out;
}

ir::Status write_reports(const std::string& dir, const std::vector<CaseResult>& results,
                         const Expectations& e) {
  for (auto [name, text] : {std::pair{"results.csv", results_csv(results, e)},
                            std::pair{"failures.csv", failures_csv(results, e)},
                            std::pair{"junit.xml", junit_xml(results, e)},
                            std::pair{"summary.md", summary_md(results, e)}})
    if (ir::Status s = write(dir, name, text); !s) return s;
  return ir::ok_status();
}

ir::Result<std::vector<CaseResult>> merge_folders(const std::vector<std::string>& dirs,
                                                  const std::string& out, const Expectations& e) {
  if (ir::Status s = refuse_foreign_folder(out); !s) return s.failure();
  std::map<std::string, CaseResult> all;
  for (const std::string& dir : dirs) {
    const std::string path = (std::filesystem::path(dir) / "results.jsonl").string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      return ir::fail(path, "io", fmt::format("{}: no results.jsonl (not a test folder)", dir));
    for (CaseResult& r : read_results_jsonl(path)) {
      if (all.contains(r.id))
        return ir::fail(dir, "usage",
                        fmt::format("case {} is in two folders (do the shards overlap?)", r.id));
      all[r.id] = std::move(r);
    }
  }
  std::vector<CaseResult> results;
  std::string jsonl;
  for (auto& [id, r] : all) {
    jsonl += to_json(r).dump() + "\n";
    results.push_back(std::move(r));
  }
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ir::Status s = write(out, "results.jsonl", jsonl); !s) return s.failure();
  if (ir::Status s = write_reports(out, results, e); !s) return s.failure();
  return results;
}

} // namespace tierlift::corpus
