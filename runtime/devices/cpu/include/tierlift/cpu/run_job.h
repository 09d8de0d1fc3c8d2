// `tierlift run` on the CPU device as a library: the request's pass (pass::prepare_pass,
// tierlift/pass/setup.h) drawn by cpu::draw, with the probes read back. Tests and benchmarks
// call run_job() directly; the CLI draws the prepared pass as a graph of one pass through the
// effect devices (effects/single_pass.h).
#pragma once

#include <string_view>
#include <vector>

#include "tierlift/cpu/draw.h"
#include "tierlift/pass/setup.h"

namespace tierlift::cpu {

using pass::ConstSetting;
using pass::ProbePoint;
using pass::ProbeValue;
using pass::RegisterSetting;
using pass::RunDiagnostics;
using pass::RunRequest;
using pass::StageMask;
using pass::TextureSetting;

// What a run drew.
struct RunResult {
  img::Image image;
  std::vector<ProbeValue> probes;
  DrawStats stats;
  double setup_ms = 0, draw_ms = 0;
};

// The rule of run_pass's and run_job's failures; their diagnostics are in `diags`.
inline constexpr std::string_view kRunRule = "run";

// Draws `pass` into a new `width`×`height` target of `format` and reads `probes`. On any
// error (reported in diags.other) a failure (rule kRunRule) with that error's message;
// warnings never stop the run.
ir::Result<RunResult> run_pass(const Pass& pass, uint32_t width, uint32_t height,
                               img::Format format, const std::vector<ProbePoint>& probes,
                               unsigned threads, RunDiagnostics& diags);

// prepare_pass, then run_pass. On any error (reported in `diags`) a failure (rule kRunRule)
// with the first error's message.
ir::Result<RunResult> run_job(const RunRequest& request, RunDiagnostics& diags);

} // namespace tierlift::cpu
