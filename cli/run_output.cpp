// `tierlift run -o`: PNG or PFM, with a warning when PNG clamps.
#include "run_output.h"

#include <fmt/format.h>

#include "tierlift/image/io.h"
#include "tierlift/pass/input_sources.h"

namespace tierlift::cli {

std::string write_run_output(const std::string& path, const img::Image& stored,
                             std::string* warning, bool keep_alpha) {
  const bool pfm = path.size() >= 4 && (path.ends_with(".pfm") || path.ends_with(".PFM"));
  img::Image opaque;
  if (!pfm && !keep_alpha) {
    opaque = stored;
    for (size_t i = 3; i < opaque.rgba.size(); i += 4) opaque.rgba[i] = 1.0f;
  }
  const img::Image& image = !pfm && !keep_alpha ? opaque : stored;
  if (!pfm && warning) {
    size_t clamped = 0;
    for (float v : image.rgba) clamped += !(v >= 0.0f && v <= 1.0f);
    if (clamped)
      *warning = fmt::format("{}: {} channel values outside [0, 1] are clamped in PNG; write "
                             ".pfm to keep them",
                             path, clamped);
  }
  ir::Status s = pfm ? img::write_pfm(path, image)
                     : img::write_png(path, image,
                                      image.format == img::Format::RGBA8 ? img::PngDepth::Bits8
                                                                         : img::PngDepth::Bits16);
  return s.message();
}

} // namespace tierlift::cli

namespace tierlift::cli {

void report_input_sources(const pass::RunRequest& request, const Report& report) {
  if (report.json()) return;
  for (const pass::InputSource& s : pass::describe_inputs(request))
    fmt::print(stderr, "tierlift run: note: {}: {}\n", s.reg, s.source);
}

nlohmann::json input_sources_json(const pass::RunRequest& request) {
  nlohmann::json out = nlohmann::json::object();
  for (const pass::InputSource& s : pass::describe_inputs(request)) out[s.reg] = s.source;
  return out;
}

// The run's text output: each probe's value, and with two devices the agreement line.
void print_text_result(const DeviceRun& shown, const DeviceRun& vk, const std::string& vk_name,
                       const std::optional<img::Comparison>& agreement,
                       const std::optional<img::Verdict>& verdict) {
  for (const auto& p : shown.probes)
    fmt::print("{},{}: {} {} {} {}\n", p.x, p.y, p.value[0], p.value[1], p.value[2], p.value[3]);
  if (!agreement) return;
  for (const auto& p : vk.probes)
    fmt::print("{},{} (vulkan): {} {} {} {}\n", p.x, p.y, p.value[0], p.value[1], p.value[2],
               p.value[3]);
  fmt::print("cpu vs vulkan ({}): max abs per channel {:.3g} {:.3g} {:.3g} {:.3g}, rmse "
             "{:.3g}, identical pixels {:.2f} %: {}\n",
             vk_name, agreement->max_abs[0], agreement->max_abs[1], agreement->max_abs[2],
             agreement->max_abs[3], agreement->rmse_all, agreement->identical_share * 100.0,
             verdict->pass ? "within targets" : "BEYOND TARGETS");
}

} // namespace tierlift::cli
