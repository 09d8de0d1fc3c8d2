// The files of `tierlift report`: report.json (one object per configuration and the sweep's
// settings), report.csv, report.md (the Pareto front, the scene's own configuration and
// where it stands, the cheapest configuration within 1/255 of the ideal) and the plot
// error-vs-time.png / .svg, drawn by gnuplot from a data file and a script tierlift writes.
// Everything is made in the temporary folder of an io::OutputFolder and moved into DIR at
// the end, so an error or an interrupt leaves DIR as it was (absent when it was absent).
#pragma once

#include "tierlift/ir/result.h"

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tierlift/effects/report/report_sweep.h"
#include "tierlift/io/output_folder.h"

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

// The names of the report's files, in the order write_report writes them. A command names
// them to its OutputFolder before the sweep, so a clash with an input is refused at once.
const std::vector<std::string>& report_file_names();

// Writes every file into `out` and commits it; the files' paths. On failure (rule "io",
// subject DIR) nothing changed in DIR. gnuplot missing is an error that says which package
// brings it.
ir::Result<std::vector<std::string>> write_report(io::OutputFolder& out, const SweepResult& r,
                                                  const SweepSettings& s, const ReportInfo& info);

} // namespace tierlift::effects
