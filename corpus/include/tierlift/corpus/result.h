// What one case of a corpus run gave: a verdict per stage, the first difference the
// differential run found, and the times. One CaseResult is one line of results.jsonl; the
// worker sends it to the coordinator as that same line.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace tierlift::corpus {

// Pass/Fail: the stage ran. Skip: not run (an earlier stage failed, --skips, or the stage
// does not apply). Unsupported: the front end refuses the profile (shader model 3): known,
// not a failure. Crash/Timeout: the worker died or hung on the case (the coordinator's
// verdict, never a stage's).
enum class Verdict { Pass, Fail, Skip, Unsupported, Crash, Timeout };
std::string_view verdict_name(Verdict v);
std::optional<Verdict> parse_verdict(std::string_view name);
// Fail, Crash and Timeout.
bool is_failure(Verdict v);

// The stages in the order they run.
inline constexpr std::string_view kStageParse = "parse";
inline constexpr std::string_view kStageValidate = "validate";
inline constexpr std::string_view kStageRoundTrip = "roundtrip";
inline constexpr std::string_view kStageSpirv = "spirv";
inline constexpr std::string_view kStageDiff = "diff";
inline constexpr std::string_view kStages[] = {kStageParse, kStageValidate, kStageRoundTrip,
                                               kStageSpirv, kStageDiff};

struct StageResult {
  std::string stage;
  Verdict verdict = Verdict::Skip;
  std::string message; // why it failed / was skipped (first lines of the diagnostics)
  double ms = 0;
};

// The first place the interpreter and Vulkan disagree on.
struct Difference {
  unsigned input_set = 0; // which of the K generated input sets
  unsigned x = 0, y = 0;
  int channel = 0; // 0..3 = R, G, B, A of the target (oC0 / oD0 as stored)
  float cpu = 0, vulkan = 0;
  std::string summary; // img::judge's line
};

struct CaseResult {
  std::string id;
  std::string profile;             // "ps_2_0"; "" when it did not parse
  std::string form;                // "text", "token stream", ...
  Verdict verdict = Verdict::Pass; // the worst of the stages (Fail > Unsupported > Pass)
  std::vector<StageResult> stages;
  std::optional<Difference> difference;
  double ms = 0;
  unsigned attempt = 1; // 2: the automatic rerun of an unexpected failure
  bool flaky = false;   // failed, then passed on the rerun
  std::string reduced;  // a generated failing case, delta-reduced (listing text)
  std::string repro;    // the command that reproduces the case alone (coordinator's)
  std::string note;     // a crash's signal or exit status, a timeout's limit

  // The first stage that failed (or was unsupported), "" when none.
  std::string failed_stage() const;
};

nlohmann::json to_json(const CaseResult& r);
// A results.jsonl line back (a line that is not one: nullopt).
std::optional<CaseResult> from_json(const nlohmann::json& j);

} // namespace tierlift::corpus
