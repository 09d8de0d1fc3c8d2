// `tierlift run` on the CPU device as a library: the request's pass (pass::prepare_pass,
// tierlift/pass/setup.h) drawn by cpu::draw, with the probes read back. Tests and benchmarks
// call run_job() directly; the CLI draws the prepared pass as a graph of one pass through the
// effect devices (effects/single_pass.h).
#pragma once

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

struct RunResult {
  bool ok = false;
  img::Image image;
  std::vector<ProbeValue> probes;
  DrawStats stats;
  double setup_ms = 0, draw_ms = 0;
};

// Draws `pass` into a new `width`×`height` target of `format` and reads `probes`. ok is
// false on any error (reported in diags.other); warnings never stop the run.
RunResult run_pass(const Pass& pass, uint32_t width, uint32_t height, img::Format format,
                   const std::vector<ProbePoint>& probes, unsigned threads, RunDiagnostics& diags);

// prepare_pass, then run_pass. ok is false on any error (reported in `diags`).
RunResult run_job(const RunRequest& request, RunDiagnostics& diags);

} // namespace tierlift::cpu
