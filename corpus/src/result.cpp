#include "tierlift/corpus/result.h"

#include <cmath>

namespace tierlift::corpus {

namespace {
constexpr std::string_view kVerdictNames[] = {"pass",        "fail",  "skip",
                                              "unsupported", "crash", "timeout"};

// JSON has no NaN or infinity: such values are written as strings ("nan", "inf", "-inf").
nlohmann::json number(float v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}
float number_back(const nlohmann::json& j) {
  if (j.is_number()) return j.get<float>();
  std::string s = j.is_string() ? j.get<std::string>() : "nan";
  if (s == "inf") return INFINITY;
  if (s == "-inf") return -INFINITY;
  return NAN;
}
} // namespace

std::string_view verdict_name(Verdict v) {
  return kVerdictNames[static_cast<int>(v)];
}

std::optional<Verdict> parse_verdict(std::string_view name) {
  for (int i = 0; i < 6; ++i)
    if (kVerdictNames[i] == name) return static_cast<Verdict>(i);
  return std::nullopt;
}

bool is_failure(Verdict v) {
  return v == Verdict::Fail || v == Verdict::Crash || v == Verdict::Timeout;
}

std::string CaseResult::failed_stage() const {
  for (const StageResult& s : stages)
    if (is_failure(s.verdict) || s.verdict == Verdict::Unsupported) return s.stage;
  return {};
}

nlohmann::json to_json(const CaseResult& r) {
  nlohmann::json stages = nlohmann::json::object(), ms = nlohmann::json::object(),
                 messages = nlohmann::json::object();
  for (const StageResult& s : r.stages) {
    stages[s.stage] = verdict_name(s.verdict);
    ms[s.stage] = s.ms;
    if (!s.message.empty()) messages[s.stage] = s.message;
  }
  nlohmann::json j = {{"id", r.id},           {"verdict", verdict_name(r.verdict)},
                      {"profile", r.profile}, {"form", r.form},
                      {"stages", stages},     {"messages", messages},
                      {"stage_ms", ms},       {"ms", r.ms},
                      {"attempt", r.attempt}};
  if (r.flaky) j["flaky"] = true;
  if (!r.reduced.empty()) j["reduced"] = r.reduced;
  if (!r.repro.empty()) j["repro"] = r.repro;
  if (!r.note.empty()) j["note"] = r.note;
  if (r.difference) {
    const Difference& d = *r.difference;
    j["difference"] = {{"input_set", d.input_set},
                       {"x", d.x},
                       {"y", d.y},
                       {"channel", std::string(1, "rgba"[d.channel])},
                       {"cpu", number(d.cpu)},
                       {"vulkan", number(d.vulkan)},
                       {"summary", d.summary}};
  }
  return j;
}

std::optional<CaseResult> from_json(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("id") || !j.contains("verdict")) return std::nullopt;
  try {
    CaseResult r;
    r.id = j.at("id").get<std::string>();
    std::optional<Verdict> v = parse_verdict(j.at("verdict").get<std::string>());
    if (!v) return std::nullopt;
    r.verdict = *v;
    r.profile = j.value("profile", "");
    r.form = j.value("form", "");
    r.ms = j.value("ms", 0.0);
    r.attempt = j.value("attempt", 1u);
    r.flaky = j.value("flaky", false);
    r.reduced = j.value("reduced", "");
    r.repro = j.value("repro", "");
    r.note = j.value("note", "");
    const nlohmann::json& messages = j.value("messages", nlohmann::json::object());
    const nlohmann::json& ms = j.value("stage_ms", nlohmann::json::object());
    for (std::string_view name : kStages) {
      std::string key(name);
      if (!j.at("stages").contains(key)) continue;
      StageResult s;
      s.stage = key;
      s.verdict = parse_verdict(j["stages"][key].get<std::string>()).value_or(Verdict::Fail);
      s.message = messages.value(key, "");
      s.ms = ms.value(key, 0.0);
      r.stages.push_back(std::move(s));
    }
    if (j.contains("difference")) {
      const nlohmann::json& d = j["difference"];
      Difference diff;
      diff.input_set = d.value("input_set", 0u);
      diff.x = d.value("x", 0u);
      diff.y = d.value("y", 0u);
      std::string ch = d.value("channel", "r");
      diff.channel = static_cast<int>(std::string_view("rgba").find(ch.empty() ? 'r' : ch[0]));
      diff.cpu = number_back(d.at("cpu"));
      diff.vulkan = number_back(d.at("vulkan"));
      diff.summary = d.value("summary", "");
      r.difference = diff;
    }
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

} // namespace tierlift::corpus
