// The worker side of the protocol (runner.h): one case per input line, one result per
// output line.
#include <csignal>
#include <cstdlib>
#include <string>
#include <unistd.h>

#include "tierlift/corpus/runner.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::corpus {
namespace {

// The test hooks: a worker that dies or hangs on a named case, as a driver might.
bool hook_matches(const char* variable, const std::string& id) {
  const char* v = std::getenv(variable);
  return v && *v && id.find(v) != std::string::npos;
}

std::string read_line(std::FILE* in, bool& eof) {
  std::string line;
  int ch;
  while ((ch = std::fgetc(in)) != EOF && ch != '\n') line += static_cast<char>(ch);
  eof = ch == EOF && line.empty();
  return line;
}

} // namespace

nlohmann::json case_json(const Case& c) {
  nlohmann::json j = {{"id", c.id}};
  if (!c.path.empty()) j["path"] = c.path;
  if (c.generated)
    j["generated"] = {
        {"text", c.text}, {"profile", c.gen_profile}, {"seed", c.gen_seed}, {"index", c.gen_index}};
  return j;
}

std::optional<Case> case_from_json(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("id")) return std::nullopt;
  try {
    Case c;
    c.id = j.at("id").get<std::string>();
    c.path = j.value("path", "");
    if (j.contains("generated")) {
      const nlohmann::json& g = j.at("generated");
      c.generated = true;
      c.text = g.value("text", "");
      c.gen_profile = g.value("profile", "");
      c.gen_seed = g.value("seed", uint64_t{0});
      c.gen_index = g.value("index", size_t{0});
    }
    return c;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

int worker_loop(std::FILE* in, std::FILE* out, StageOptions options,
                const std::function<vulkan::Device*()>& make_device, const Reducer& reducer) {
  bool asked_for_device = false;
  for (;;) {
    bool eof = false;
    const std::string line = read_line(in, eof);
    if (eof) {
      // The pipelines this worker made, for the next worker and the next run (the device's
      // cache file in the user's cache folder, shared by every worker on the machine).
      if (options.device) options.device->save_pipeline_cache();
      return 0;
    }
    std::optional<Case> c = case_from_json(nlohmann::json::parse(line, nullptr, false));
    if (!c) {
      std::fprintf(stderr, "tierlift test --worker: not a case: %s\n", line.c_str());
      return 2;
    }
    if (hook_matches("TIERLIFT_TEST_CRASH_ON", c->id)) std::raise(SIGKILL);
    if (hook_matches("TIERLIFT_TEST_HANG_ON", c->id))
      for (;;) ::pause();
    if (!options.check_only && !asked_for_device) {
      asked_for_device = true;
      options.device = make_device ? make_device() : nullptr;
    }
    CaseResult r = run_case(*c, options);
    if (c->generated && is_failure(r.verdict) && reducer) {
      // Smaller programs that still fail the same stage: the reducer keeps them valid by
      // asking this predicate, which reruns every stage on the candidate.
      const std::string stage = r.failed_stage();
      r.reduced = reducer(c->text, [&](const std::string& text) {
        CaseResult again = run_listing(c->id, c->id, text, options);
        return is_failure(again.verdict) && again.failed_stage() == stage;
      });
    }
    std::fputs((to_json(r).dump() + "\n").c_str(), out);
    std::fflush(out);
  }
}

} // namespace tierlift::corpus
