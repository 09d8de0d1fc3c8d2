// `tierlift run`'s draw as the tests call it: a request's pass (pass::prepare_pass) drawn by
// cpu::draw into a new target, the probes read back. The CLI runs the same pass as a
// one-pass effect graph (effects/single_pass.h); these tests pin down what prepare_pass and
// cpu::draw do for it without the graph around them.
#pragma once

#include <new>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "tierlift/cpu/draw.h"
#include "tierlift/pass/setup.h"

namespace tierlift::test {

using pass::Pass;
using pass::ProbePoint;
using pass::ProbeValue;
using pass::RunDiagnostics;
using pass::RunRequest;

// What a run drew.
struct RunResult {
  img::Image image;
  std::vector<ProbeValue> probes;
};

// The rule of run_pass's and run_job's failures; their diagnostics are in `diags`.
inline constexpr std::string_view kRunRule = "run";

// Reports the error to `diags.other` (where the CLI renders it) and returns it as the run's
// failure.
inline ir::Failure run_error(RunDiagnostics& diags, std::string rule, std::string message) {
  diags.other.error({}, std::move(rule), message);
  return ir::fail("", std::string(kRunRule), std::move(message));
}

// Draws `pass` into a new `width`×`height` target of `format` and reads `probes`. On any
// error (reported in diags.other) a failure (rule kRunRule) with that error's message.
inline ir::Result<RunResult> run_pass(const Pass& pass, uint32_t width, uint32_t height,
                                      img::Format format, const std::vector<ProbePoint>& probes,
                                      unsigned threads, RunDiagnostics& diags) {
  RunResult result;
  try { // a 16384² float target is 4 GiB: running out of memory is an error, not a crash
    result.image = img::Image(width, height, format);
  } catch (const std::bad_alloc&) {
    return run_error(
        diags, "memory",
        fmt::format("not enough memory for a {}x{} target and its textures", width, height));
  }
  ir::Result<cpu::DrawStats> stats = cpu::draw(pass, result.image, threads);
  if (!stats) return run_error(diags, std::string(cpu::kDrawRule), stats.message());
  for (const ProbePoint& p : probes)
    if (p.x >= width || p.y >= height)
      return run_error(
          diags, "probe",
          fmt::format("--probe {},{} lies outside the {}x{} image", p.x, p.y, width, height));
  result.probes = pass::read_probes(result.image, probes);
  return result;
}

// prepare_pass, then run_pass. On any error (reported in `diags`) a failure (rule kRunRule)
// with the first error's message.
inline ir::Result<RunResult> run_job(const RunRequest& req, RunDiagnostics& diags) {
  ir::Result<Pass> pass = pass::prepare_pass(req);
  pass::add_by_listing(diags, pass.diagnostics());
  if (!pass) return ir::fail("", std::string(kRunRule), pass.message());
  return run_pass(*pass, req.width, req.height, req.format, req.probes, req.threads, diags);
}

} // namespace tierlift::test
