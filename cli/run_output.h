// Where `tierlift run` writes its image.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report.h"
#include "tierlift/image/compare.h"
#include "tierlift/image/image.h"
#include "tierlift/pass/pass.h"
#include "tierlift/pass/setup.h"

namespace tierlift::cli {

// One device's run of the one-pass graph: its target, the probes, what the draw took.
// Diagnostics go to `report`; ok is false after an error.
struct DeviceRun {
  bool ok = false;
  img::Image image;
  std::vector<pass::ProbeValue> probes;
  pass::DrawReport report;
  std::vector<img::Image> more_images; // oC1..oC3 of a run with --output1..3
};

// The run's text output: each probe's value, and with two devices the agreement line.
void print_text_result(const DeviceRun& shown, const DeviceRun& vk, const std::string& vk_name,
                       const std::optional<img::Comparison>& agreement,
                       const std::optional<img::Verdict>& verdict);

// Writes the image atomically: ".pfm" → PFM (float RGB), otherwise PNG, 8-bit for RGBA8
// targets and 16-bit for float targets. Empty string on success, else the reason. When a
// PNG must clamp values outside [0, 1] (or NaN), `warning` says so (use .pfm for HDR).
// A PNG is opaque (alpha 1) unless `keep_alpha`: shaders often leave alpha 0, which viewers
// show as nothing at all. PFM has no alpha either way.
std::string write_run_output(const std::string& path, const img::Image& image,
                             std::string* warning = nullptr, bool keep_alpha = false);

} // namespace tierlift::cli

namespace tierlift::cli {

// What drives each input of the run's listings (pass::describe_inputs): one note line per
// input on standard error ("tierlift run: note: t0: quad uv (no --vs)"); nothing under --json,
// where input_sources_json carries them as result.inputs {"t0": "quad uv (no --vs)", ...}.
void report_input_sources(const pass::RunRequest& request, const Report& report);
nlohmann::json input_sources_json(const pass::RunRequest& request);

} // namespace tierlift::cli
