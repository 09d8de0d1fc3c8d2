// The files of `tierlift report`: report.json (one object per configuration and the sweep's
// settings), report.csv, report.md (the Pareto front, the scene's own configuration and
// where it stands, the cheapest configuration within 1/255 of the ideal) and the plot
// error-vs-time.png / .svg, drawn by gnuplot from a data file and a script tierlift writes.
// Everything is made in a temporary folder beside DIR and moved into DIR at the end, so an
// error leaves DIR as it was (absent when it was absent).
#pragma once

#include "tierlift/ir/result.h"

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tierlift/effects/report_sweep.h"

namespace tierlift::effects {

struct ReportInfo {
  std::string scene_file;  // "" for the built-in scene
  std::string scene_image; // builtin:neon or the PNG
  uint32_t width = 0, height = 0;
  double intensity = 1;
  std::string vulkan_device;                     // "" when none ran
  unsigned plot_width = 1000, plot_height = 700; // pixels of the PNG
};

nlohmann::json report_json(const SweepResult& r, const SweepSettings& s, const ReportInfo& info);
std::string report_csv(const SweepResult& r);
std::string report_markdown(const SweepResult& r, const SweepSettings& s, const ReportInfo& info);

// The gnuplot program: TIERLIFT_GNUPLOT when set, else "gnuplot" on PATH.
std::string gnuplot_program();
// Whether gnuplot_program() can be run (an executable file at that path, or on PATH): a
// failure (rule "io") that says which package brings it. Callers ask before a sweep, so a
// missing gnuplot is not found only after minutes of work.
ir::Status check_gnuplot();

// Writes every file into `dir` (created when missing) and returns their paths; on failure
// (rule "io", subject `dir`) nothing changed in `dir`. gnuplot missing is an error that says
// which package brings it.
ir::Result<std::vector<std::string>> write_report(const std::string& dir, const SweepResult& r,
                                                  const SweepSettings& s, const ReportInfo& info);

} // namespace tierlift::effects
