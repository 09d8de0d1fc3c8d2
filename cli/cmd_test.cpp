// tierlift test PATH...: a corpus of listings as one regression run (the corpus library:
// tierlift/corpus/runner.h); `tierlift test merge DIR...` joins the folders of shards.
// Flags, the worker's entry and printing live here; the run itself in tierlift_corpus.
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <thread>
#include <unistd.h>

#include <fmt/format.h>

#include "commands.h"
#include "report.h"
#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/output_guard.h"
#include "tierlift/corpus/report.h"
#include "tierlift/corpus/runner.h"
#include "tierlift/corpus/shard.h"
#include "tierlift/effects/graph/vulkan_device.h"
#include "tierlift/generate/generate.h"
#include "tierlift/io/output_file.h"

namespace tierlift::cli {
namespace {

struct TestFlags {
  std::vector<std::string> paths, only, profiles, merge_dirs;
  std::string output = "test-results", baseline, flakes, skips, shard, shard_costs, gpu,
              merge_output;
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  double timeout = 60;
  unsigned inputs = 3, size = 8;
  uint64_t seed = 1;
  size_t generate = 0;
  bool check_only = false, resume = false, update_baseline = false, no_rerun = false;
  bool worker = false, list = false, quiet = false;
};

std::string quoted(const std::string& s) {
  if (s.find_first_of(" '\"$`\\!*?[]{}()<>|&;#~") == std::string::npos && !s.empty()) return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The flags that change what a case's stages do: the same in a worker and in a repro.
std::vector<std::string> stage_flags(const TestFlags& f) {
  std::vector<std::string> out{"--inputs", std::to_string(f.inputs),
                               "--seed",   std::to_string(f.seed),
                               "--size",   std::to_string(f.size)};
  if (f.check_only) out.push_back("--check-only");
  if (!f.gpu.empty()) out.insert(out.end(), {"--gpu", f.gpu});
  return out;
}

std::string repro(const TestFlags& f, const corpus::Case& c) {
  std::string cmd = "tierlift test";
  for (const std::string& a : stage_flags(f)) cmd += " " + quoted(a);
  if (c.generated)
    cmd += fmt::format(" --generate {} --profile {}", c.gen_index + 1, c.gen_profile);
  cmd += " --only " + quoted(c.id);
  if (!c.generated)
    for (const std::string& p : f.paths) cmd += " " + quoted(p);
  return cmd;
}

corpus::StageOptions stage_options(const TestFlags& f) {
  corpus::StageOptions o;
  o.input_sets = f.inputs;
  o.seed = f.seed;
  o.size = f.size;
  o.check_only = f.check_only;
  return o;
}

int run_worker(const TestFlags& f) {
  // The protocol owns standard output; anything else printed there (a driver's chatter)
  // goes to standard error instead.
  const int protocol = ::dup(1);
  ::dup2(2, 1);
  std::FILE* out = ::fdopen(protocol, "w");
  if (!out) return kExitUsage;
  auto make_device = [gpu = f.gpu]() -> vulkan::Device* {
    ir::Result<vulkan::Device*> d = effects::vulkan_device(gpu);
    if (!d) std::fprintf(stderr, "tierlift test --worker: %s\n", d.message().c_str());
    return d ? *d : nullptr;
  };
  corpus::Reducer reducer;
  reducer = [](const std::string& text, const std::function<bool(const std::string&)>& fails) {
    return gen::reduce_listing(text, fails);
  };
  return corpus::worker_loop(stdin, out, stage_options(f), make_device, reducer);
}

// Reads --baseline, --flakes, --skips.
ir::Result<corpus::Expectations> expectations(const TestFlags& f) {
  corpus::Expectations e;
  if (!f.baseline.empty()) {
    auto b = corpus::read_baseline(f.baseline);
    if (!b) return b.failure();
    e.baseline = std::move(*b);
  }
  for (auto [path, into] : {std::pair{&f.flakes, &e.flakes}, std::pair{&f.skips, &e.skips}}) {
    if (path->empty()) continue;
    auto p = corpus::read_patterns(*path);
    if (!p) return p.failure();
    *into = std::move(*p);
  }
  return e;
}

// The cases of the run; `costs`: those of --shard-costs, read once (they shard the run and
// order its cases).
ir::Result<std::vector<corpus::Case>> gather(const TestFlags& f,
                                             std::map<std::string, uint64_t>& costs) {
  std::vector<corpus::Case> cases;
  if (!f.paths.empty()) {
    auto found = corpus::discover(f.paths);
    if (!found) return found.failure();
    cases = std::move(*found);
  }
  if (f.generate > 0) {
    for (const std::string& profile : f.profiles) {
      ir::Result<std::vector<corpus::Case>> made =
          corpus::generated_cases(profile, f.seed, f.generate);
      if (!made) return std::move(made).failure();
      std::move(made->begin(), made->end(), std::back_inserter(cases));
    }
  }
  if (!f.only.empty())
    std::erase_if(cases, [&](const corpus::Case& c) {
      return std::find(f.only.begin(), f.only.end(), c.id) == f.only.end();
    });
  if (!f.shard.empty()) {
    size_t index = 0, count = 0;
    if (std::sscanf(f.shard.c_str(), "%zu/%zu", &index, &count) != 2 || count == 0 ||
        index >= count)
      return ir::fail("--shard", "usage",
                      fmt::format("--shard {}: expected I/N with 0 <= I < N", f.shard));
    if (!f.shard_costs.empty()) {
      auto read = corpus::read_costs(f.shard_costs);
      if (!read) return read.failure();
      costs = std::move(*read);
      cases = corpus::balanced_shard(cases, costs, index, count);
    } else {
      std::erase_if(cases,
                    [&](const corpus::Case& c) { return !corpus::in_shard(c, index, count); });
    }
  } else if (!f.shard_costs.empty()) {
    return ir::fail("--shard-costs", "usage", "--shard-costs needs --shard I/N");
  }
  return cases;
}

void print_outcome(const std::vector<corpus::CaseResult>& results, const corpus::Expectations& e,
                   const std::string& dir) {
  for (const corpus::CaseResult& r : results) {
    const corpus::Outcome o = corpus::classify(r, e);
    if (o == corpus::Outcome::NewFailure) {
      std::string stage = r.failed_stage(), why = r.note;
      for (const corpus::StageResult& s : r.stages)
        if (s.stage == stage) why = s.message;
      fmt::print("FAIL {} ({} {}): {}\n  reproduce: {}\n", r.id, stage.empty() ? "worker" : stage,
                 corpus::verdict_name(r.verdict), why, r.repro);
    } else if (o == corpus::Outcome::Fixed) {
      fmt::print("FIXED {}: in the baseline, passes now (update the baseline)\n", r.id);
    }
  }
  const corpus::Tally t = corpus::tally(results, e);
  std::string counts;
  for (const auto& [o, n] : t.outcomes)
    counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", n, corpus::outcome_name(o));
  fmt::print("{} cases: {}; reports in {}\n", t.cases, counts, dir);
}

int run_test(const TestFlags& f) {
  if (f.worker) return run_worker(f);
  Report report("test", false);
  if (f.paths.empty() && f.generate == 0) {
    report.error("usage", "nothing to test: give PATH... or --generate N (tierlift test --help)");
    return report.finish(kExitUsage);
  }
  if (f.generate > 0 && f.profiles.empty()) {
    report.error("usage", "--generate needs --profile (ps_2_0, vs_1_1, ...)");
    return report.finish(kExitUsage);
  }
  if (f.update_baseline && f.baseline.empty()) {
    report.error("usage", "--update-baseline rewrites the --baseline file: give --baseline");
    return report.finish(kExitUsage);
  }
  auto e = expectations(f);
  if (!e) {
    report.error(e.diagnostics().front().rule, e.message());
    return report.finish(kExitUsage);
  }
  std::map<std::string, uint64_t> costs;
  auto cases = gather(f, costs);
  if (!cases) {
    report.error(cases.diagnostics().front().rule, cases.message());
    return report.finish(kExitUsage);
  }
  if (f.list) {
    for (const corpus::Case& c : *cases) fmt::print("{}\n", c.id);
    return report.finish(kExitOk);
  }
  const std::vector<std::string> read = {f.baseline, f.flakes, f.skips, f.shard_costs};
  if (ir::Status s = corpus::refuse_outputs_among_inputs(f.output, read); !s) {
    report.error("write", s.message());
    return report.finish(kExitUsage);
  }
  corpus::RunOptions o;
  o.costs = std::move(costs);
  char self[4096];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  o.worker_argv = {n > 0 ? std::string(self, static_cast<size_t>(n)) : std::string("tierlift"),
                   "test", "--worker"};
  for (const std::string& a : stage_flags(f)) o.worker_argv.push_back(a);
  o.jobs = f.jobs;
  o.timeout_s = f.timeout;
  o.out_dir = f.output;
  o.resume = f.resume;
  o.rerun = !f.no_rerun;
  o.progress = !f.quiet && ::isatty(2);
  o.expectations = std::move(*e);
  o.repro = [&f](const corpus::Case& c) { return repro(f, c); };
  auto results = corpus::run_corpus(*cases, o);
  if (!results) {
    report.error("io", results.message());
    return report.finish(kExitUsage);
  }
  print_outcome(*results, o.expectations, f.output);
  if (f.update_baseline) {
    const std::string text = corpus::failures_csv(*results, o.expectations);
    if (ir::Status s = io::write_output(f.baseline, text); !s) {
      report.error("io", s.message(), f.baseline);
      return report.finish(kExitUsage);
    }
    fmt::print("baseline {} updated\n", f.baseline);
    return report.finish(kExitOk);
  }
  return report.finish(corpus::tally(*results, o.expectations).exit_code());
}

int run_merge(const TestFlags& f) {
  Report report("test merge", false);
  if (f.merge_output.empty()) {
    report.error("usage", "tierlift test merge DIR... -o OUT: give -o");
    return report.finish(kExitUsage);
  }
  std::error_code ec;
  for (const std::string& d : f.merge_dirs)
    if (std::filesystem::equivalent(d, f.merge_output, ec)) {
      report.error("usage", fmt::format("-o {} is one of the folders merged", f.merge_output));
      return report.finish(kExitUsage);
    }
  const std::vector<std::string> read = {f.baseline, f.flakes, f.skips};
  if (ir::Status s = corpus::refuse_outputs_among_inputs(f.merge_output, read); !s) {
    report.error("write", s.message());
    return report.finish(kExitUsage);
  }
  auto e = expectations(f);
  if (!e) {
    report.error(e.diagnostics().front().rule, e.message());
    return report.finish(kExitUsage);
  }
  auto results = corpus::merge_folders(f.merge_dirs, f.merge_output, *e);
  if (!results) {
    report.error(results.diagnostics().front().rule, results.message());
    return report.finish(kExitUsage);
  }
  print_outcome(*results, *e, f.merge_output);
  return report.finish(corpus::tally(*results, *e).exit_code());
}

void add_expectation_flags(CLI::App* sub, TestFlags& f) {
  sub->add_option("--baseline", f.baseline,
                  "Expected failures (a failures.csv): the run passes when exactly these fail");
  sub->add_option("--flakes", f.flakes, "Regular expressions (one a line) on ids known to flake");
  sub->add_option("--skips", f.skips, "Regular expressions (one a line) on ids not to run");
}

} // namespace

void register_test_command(CLI::App& app) {
  auto f = std::make_shared<TestFlags>();
  CLI::App* sub = app.add_subcommand(
      "test", "Run a corpus of listings through the whole lift (parse, validate, round trip, "
              "SPIR-V, interpreter against Vulkan) in worker processes");
  sub->add_option("paths", f->paths, "Listings, folders (recursively) and list files");
  sub->add_option("-o,--output", f->output, "Folder for results.jsonl and the reports")
      ->capture_default_str();
  sub->add_option("-j,--jobs", f->jobs, "Worker processes")->capture_default_str();
  sub->add_option("--timeout", f->timeout, "Seconds one case may take before its worker is killed")
      ->capture_default_str();
  sub->add_option("--inputs", f->inputs, "Generated input sets per differential run (K)")
      ->capture_default_str();
  sub->add_option("--seed", f->seed, "Seed of the generated inputs and programs")
      ->capture_default_str();
  sub->add_option("--size", f->size, "Target size (N x N pixels) of the differential run")
      ->capture_default_str();
  sub->add_flag("--check-only", f->check_only, "Parse and validate only");
  add_expectation_flags(sub, *f);
  sub->add_flag("--update-baseline", f->update_baseline,
                "Rewrite the --baseline file with this run's failures");
  sub->add_flag("--no-rerun", f->no_rerun, "Do not rerun unexpected failures");
  sub->add_flag("--resume", f->resume, "Continue the run whose results.jsonl is in -o");
  sub->add_option("--shard", f->shard,
                  "Run share I of N (0-based), by a hash of the id, or by cost with --shard-costs");
  sub->add_option("--shard-costs", f->shard_costs,
                  "An earlier run's results.jsonl: balance the --shard shares by its case times");
  sub->add_option("--only", f->only, "Run only the case with this id (repeatable)");
  sub->add_option("--generate", f->generate, "Add N generated programs per --profile");
  sub->add_option("--profile", f->profiles, "Profile of the generated programs (repeatable)");
  sub->add_option("--gpu", f->gpu, "Vulkan device name filter (default: lavapipe)");
  sub->add_flag("--list", f->list, "Print the ids of the cases and exit");
  sub->add_flag("-q,--quiet", f->quiet, "No progress line");
  sub->add_flag("--worker", f->worker, "Internal: serve cases over standard input/output")
      ->group("");
  CLI::App* merge =
      sub->add_subcommand("merge", "Join the result folders of shards into one result");
  merge->add_option("dirs", f->merge_dirs, "Result folders (-o of each shard)")->required();
  merge->add_option("-o,--output", f->merge_output, "Folder for the joined result")->required();
  add_expectation_flags(merge, *f);
  set_action(sub, [f, merge] { return merge->parsed() ? run_merge(*f) : run_test(*f); });
}

} // namespace tierlift::cli
