// The coordinator of a corpus run and its workers. Each case runs in a worker process (the
// `tierlift test --worker` command, or any command that speaks the protocol below), so a
// shader that crashes, aborts or hangs the lift costs its own case — reported `crash` with
// the signal or exit status, or `timeout` with the limit — and the worker is started again.
//
// Protocol, one JSON object per line: the coordinator writes a case to the worker's standard
// input ({"id", "path"} or {"id", "text", "generated": {...}}); the worker answers with the
// case's results.jsonl line on its standard output, the cases in the order written. The
// coordinator writes the next cases (about 2 ms of work by the times answered so far, 1 to
// 15 cases, together at most PIPE_BUF bytes) before the answer to the running one arrives,
// so a worker never waits for it between cases; a worker that dies or hangs costs the case
// it was running, and those written ahead of it go to the worker started next. End of input:
// the worker exits.
//
// Every result is appended to DIR/results.jsonl as it arrives (the answers one wake of the
// coordinator brings, in one write), so a run killed whole keeps what it finished, and
// `resume` continues from there. A worker's line is written as it came, the command that
// reproduces the case added.
#pragma once

#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tierlift/corpus/cases.h"
#include "tierlift/corpus/report.h"
#include "tierlift/corpus/result.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/ir/result.h"

namespace tierlift::corpus {

nlohmann::json case_json(const Case& c);
std::optional<Case> case_from_json(const nlohmann::json& j);

struct RunOptions {
  std::vector<std::string> worker_argv; // argv[0] a path: the worker command
  unsigned jobs = 1;                    // worker processes
  double timeout_s = 60;                // per case, wall clock
  std::string out_dir;
  bool resume = false;   // keep DIR/results.jsonl and run only the cases it lacks
  bool rerun = true;     // run each unexpected failure once more (flake or failure?)
  bool progress = false; // a progress line on standard error (a terminal)
  Expectations expectations;
  // The command that reproduces a case alone (stored with its result).
  std::function<std::string(const Case&)> repro;
  // What each case took before (microseconds by id: an earlier run's results.jsonl,
  // read_costs): the cases are handed out costliest first (shard.h, costliest_first). Empty:
  // the times of the run last written in out_dir (its results.jsonl, read before it is
  // replaced), else the cases' sizes in bytes.
  std::map<std::string, uint64_t> costs;
};

// Runs `cases` (their --skips already applied by the caller or not: a case whose id matches
// a skip pattern is recorded `skip` without running) and writes the reports. An output folder
// of other files, or a case whose file is one of those the run writes there (output_guard.h),
// is refused (rule "write") before anything is written. The results
// are every case of DIR/results.jsonl afterwards (resumed ones included), sorted by id.
ir::Result<std::vector<CaseResult>> run_corpus(const std::vector<Case>& cases,
                                               const RunOptions& options);

// A failing generated case made smaller: the listing text, and the predicate "still fails the
// same stage" that the reducer keeps true (gen::reduce_listing has this shape).
using Reducer =
    std::function<std::string(const std::string&, const std::function<bool(const std::string&)>&)>;

// The environment a worker starts with: `parent` (a null-terminated list of NAME=VALUE), with
// lavapipe's rasteriser threads off (LP_NUM_THREADS=0: a draw is rasterised on the thread
// that submits it) unless `parent` sets LP_NUM_THREADS. The workers are the parallelism, one
// per core; a case's target is one small tile, so rasteriser threads would only add a
// hand-over and a wake-up per draw, and where there is one core per worker they take time
// from the other worker.
std::vector<std::string> worker_environment(char* const* parent);

// The worker's loop: cases from `in`, results to `out`, until end of input. The device is
// made by `make_device` on the first case that reaches the draw (null: the draw is skipped).
// Test hooks (environment): TIERLIFT_TEST_CRASH_ON / TIERLIFT_TEST_HANG_ON, a substring of an
// id: the worker kills itself with SIGKILL / sleeps forever on that case.
int worker_loop(std::FILE* in, std::FILE* out, StageOptions options,
                const std::function<vulkan::Device*()>& make_device, const Reducer& reducer);

} // namespace tierlift::corpus
