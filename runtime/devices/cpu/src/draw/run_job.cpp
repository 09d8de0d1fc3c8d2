// `tierlift run` on the CPU device: prepared pass → draw → probes.
#include "tierlift/cpu/run_job.h"

#include <chrono>
#include <fmt/format.h>
#include <new>

namespace tierlift::cpu {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Reports the error to `diags.other` (where the CLI renders it) and returns it as the run's
// failure.
ir::Failure run_error(RunDiagnostics& diags, std::string rule, std::string message) {
  diags.other.error({}, std::move(rule), message);
  return ir::fail("", std::string(kRunRule), std::move(message));
}

} // namespace

ir::Result<RunResult> run_pass(const Pass& pass, uint32_t width, uint32_t height,
                               img::Format format, const std::vector<ProbePoint>& probes,
                               unsigned threads, RunDiagnostics& diags) {
  RunResult result;
  auto t0 = Clock::now();
  try { // a 16384² float target is 4 GiB: running out of memory is an error, not a crash
    result.image = img::Image(width, height, format);
  } catch (const std::bad_alloc&) {
    return run_error(
        diags, "memory",
        fmt::format("not enough memory for a {}x{} target and its textures", width, height));
  }
  result.setup_ms = ms_since(t0);

  auto t1 = Clock::now();
  ir::Result<DrawStats> stats = draw(pass, result.image, threads);
  result.draw_ms = ms_since(t1);
  if (!stats) return run_error(diags, std::string(kDrawRule), stats.message());
  result.stats = *stats;
  if (result.stats.triangles == 0)
    diags.other.warning({}, "nothing-drawn",
                        "no triangle reached the screen (the vertex listing's oPos is "
                        "degenerate, behind the eye or clipped away): the image is empty");
  for (const ProbePoint& p : probes)
    if (p.x >= width || p.y >= height)
      return run_error(
          diags, "probe",
          fmt::format("--probe {},{} lies outside the {}x{} image", p.x, p.y, width, height));
  result.probes = pass::read_probes(result.image, probes);
  return result;
}

ir::Result<RunResult> run_job(const RunRequest& req, RunDiagnostics& diags) {
  auto t0 = Clock::now();
  ir::Result<Pass> pass = pass::prepare_pass(req);
  pass::add_by_listing(diags, pass.diagnostics());
  if (!pass) return ir::fail("", std::string(kRunRule), pass.message());
  const double prepare_ms = ms_since(t0);
  ir::Result<RunResult> result =
      run_pass(*pass, req.width, req.height, req.format, req.probes, req.threads, diags);
  if (result) result->setup_ms += prepare_ms;
  return result;
}

} // namespace tierlift::cpu
