// tierlift report: the glow swept over tier, downsample, taps, format and half texel; error
// against the ideal glow, agreement of the three ways and run time per configuration, written
// as report.json, report.csv, report.md and the error-vs-time plot. Only flags and printing
// live here; the work is tierlift::effects (report_sweep.h, report_files.h).
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <unistd.h>

#include "cmd_stress.h"
#include "commands.h"
#include "report.h"
#include "tierlift/effects/graph/vulkan_device.h"
#include "tierlift/effects/report/report_files.h"
#include "tierlift/effects/report/report_sweep.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/io/output_folder.h"

namespace tierlift::cli {
namespace {

struct ReportFlags {
  std::string scene, image, output, gpu;
  std::optional<std::string> tiers, downsamples, taps, formats, half_texel;
  unsigned frames = 0; // 0: the sweep's default
  bool json = false, quick = false, quiet = false, no_vulkan = false;
};

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// One list flag into the sweep; a word that is not one of the choices is a usage error.
template <typename T, typename Parse>
ir::Status parse_list(const std::optional<std::string>& flag, const char* name, Parse parse,
                      std::vector<T>& out) {
  if (!flag) return ir::ok_status();
  out.clear();
  for (const std::string& word : split(*flag)) {
    std::optional<T> v = parse(word);
    if (!v)
      return ir::fail(name, "usage",
                      fmt::format("{} '{}': not one of the choices (see --help)", name, word));
    out.push_back(*v);
  }
  return ir::ok_status();
}

ir::Status apply_lists(const ReportFlags& f, effects::SweepSettings& s) {
  if (ir::Status st = parse_list<effects::Tier>(f.tiers, "--tiers", effects::parse_tier, s.tiers);
      !st)
    return st;
  if (ir::Status st = parse_list<unsigned>(
          f.downsamples, "--downsamples",
          [](const std::string& w) -> std::optional<unsigned> {
            if (w.size() == 1 && w[0] >= '1' && w[0] <= '4') return unsigned(w[0] - '0');
            return std::nullopt;
          },
          s.downsamples);
      !st)
    return st;
  if (ir::Status st = parse_list<double>(
          f.taps, "--taps",
          [](const std::string& w) -> std::optional<double> {
            char* end = nullptr;
            const double v = std::strtod(w.c_str(), &end);
            if (end == w.c_str() || *end != '\0' || !(v > 0 && v <= 1)) return std::nullopt;
            return v;
          },
          s.taps);
      !st)
    return st;
  if (ir::Status st = parse_list<img::Format>(f.formats, "--formats", img::parse_format, s.formats);
      !st)
    return st;
  return parse_list<bool>(
      f.half_texel, "--half-texel",
      [](const std::string& w) -> std::optional<bool> {
        if (w == "on") return true;
        if (w == "off") return false;
        return std::nullopt;
      },
      s.half_texels);
}

void print_summary(const effects::SweepResult& r) {
  fmt::print("{:<40} {:>10} {:>11} {:>11} {:>10} {:>6} {}\n", "configuration", "frame ms",
             "final rmse", "final max", "glow rmse", "agree", "");
  for (size_t i = 0; i < r.configs.size(); ++i) {
    const effects::ConfigResult& c = r.configs[i];
    std::string mark;
    if (c.scene_choice) mark += " scene";
    if (std::find(r.pareto.begin(), r.pareto.end(), i) != r.pareto.end()) mark += " pareto";
    if (r.cheapest_within == i) mark += " cheapest-within-1/255";
    if (!c.skipped.empty()) {
      fmt::print("{:<40} skipped: {}\n", effects::config_label(c.config), c.skipped);
      continue;
    }
    fmt::print("{:<40} {:>10.2f} {:>11.3g} {:>11.3g} {:>10.3g} {:>6}{}\n",
               effects::config_label(c.config), c.frame_ms(), c.final.rmse, c.final.max_abs,
               c.glow.rmse, c.all_agree ? "yes" : "NO", mark);
  }
}

int run(const ReportFlags& f) {
  Report report("report", f.json);
  const ir::Result<effects::Scene> load = effects::load_scene(f.scene, f.image);
  if (!load) {
    const bool io = ir::failed_with(load, effects::kSceneIoRule);
    report.rendered_error(io ? "io" : "scene", load.message(), f.scene.empty() ? f.image : f.scene);
    return report.finish(io ? kExitUsage : kExitInvalid);
  }
  const effects::Scene& scene = *load;
  // -o DIR: made whole at the end or left as it was (io/output_folder.h); a report file
  // that would replace one of the scene's inputs is refused before the sweep.
  std::optional<io::OutputFolder> out_dir;
  if (!f.output.empty()) {
    std::vector<std::string> inputs = effects::scene_input_files(scene);
    inputs.insert(inputs.end(), {f.scene, f.image});
    out_dir.emplace(f.output, std::move(inputs), "report");
    for (const std::string& name : effects::report_file_names())
      if (ir::Result<std::string> path = out_dir->path(name); !path) break;
    if (ir::Status st = out_dir->status(); !st) {
      report.error("io", st.message(), f.output);
      return report.finish(kExitUsage);
    }
  }
  effects::SweepSettings s = f.quick ? effects::quick_sweep() : effects::full_sweep();
  if (f.frames != 0) s.frames = f.frames;
  if (ir::Status lists = apply_lists(f, s); !lists) {
    report.error("usage", lists.message());
    return report.finish(kExitUsage);
  }
  if (effects::sweep_configs(s, scene.params).empty()) {
    report.error("usage", "the sweep is empty: --tiers, --downsamples, --taps, --formats and "
                          "--half-texel each need at least one value");
    return report.finish(kExitUsage);
  }
  // The plot needs gnuplot: asked before the sweep, not found missing after it.
  if (!f.output.empty())
    if (ir::Status plot = effects::check_gnuplot(); !plot) {
      report.error("io", plot.message(), f.output);
      return report.finish(kExitUsage);
    }
  img::ImageResult image = effects::load_scene_image(scene);
  if (!image) {
    const bool io = img::is_io_error(image);
    report.error(io ? "io" : "scene", image.message(), scene.image);
    return report.finish(io ? kExitUsage : kExitInvalid);
  }
  // The process's device, kept until exit as in `tierlift glow` and `tierlift run`.
  vulkan::Device* vk = nullptr;
  if (!f.no_vulkan) {
    const ir::Result<vulkan::Device*> device = effects::vulkan_device(f.gpu);
    if (!device) {
      report.error("device", device.message());
      return report.finish(kExitUsage);
    }
    vk = *device;
  }
  if (f.no_vulkan) std::erase(s.timed, std::string("vulkan"));
  const bool tty = isatty(STDERR_FILENO) != 0;
  effects::SweepProgress progress;
  if (!f.quiet && !f.json)
    progress = [tty](size_t i, size_t n, const effects::SweepConfig& c) {
      fmt::print(stderr, "{}[report] {}/{}: {}{}", tty ? "\r\033[K" : "", i + 1, n,
                 effects::config_label(c), tty ? "" : "\n");
    };
  const ir::Result<effects::SweepResult> swept = effects::run_sweep(scene, *image, s, vk, progress);
  if (tty && progress) fmt::print(stderr, "\n");
  if (!swept) {
    report.error("run", swept.message());
    return report.finish(kExitInvalid);
  }
  const effects::SweepResult& r = *swept;
  effects::ReportInfo info;
  info.scene_file = scene.file;
  info.scene_image = scene.image;
  info.width = scene.params.width;
  info.height = scene.params.height;
  info.intensity = scene.params.intensity;
  if (vk) info.vulkan_device = effects::vulkan_device_name(*vk);
  std::vector<std::string> written;
  if (out_dir) {
    ir::Result<std::vector<std::string>> files = effects::write_report(*out_dir, r, s, info);
    if (!files) {
      report.error("io", files.message(), f.output);
      return report.finish(kExitUsage);
    }
    written = std::move(*files);
  }
  if (report.json()) {
    report.result() = effects::report_json(r, s, info);
    report.result()["written"] = written;
  } else {
    print_summary(r);
    for (const std::string& file : written) fmt::print("wrote {}\n", file);
  }
  return report.finish(kExitOk);
}

} // namespace

void register_report_command(CLI::App& app) {
  auto f = std::make_shared<ReportFlags>();
  CLI::App* sub = app.add_subcommand(
      "report", "Sweep the glow over tier, downsample, taps, format and half texel: error "
                "against the ideal glow, agreement and run time, with a Pareto plot");
  auto* scene = sub->add_option("--scene", f->scene, "Scene file (JSON, listings/scenes/)");
  sub->add_option("--image", f->image,
                  "PNG with alpha, or PFM (HDR, alpha 1), as the scene (default glow parameters)")
      ->excludes(scene);
  sub->add_option("-o,--output", f->output,
                  "Folder for report.json, report.csv, report.md, error-vs-time.png/.svg");
  sub->add_flag("--quick", f->quick,
                "A small sweep (downsample 2 and 4, full and half radius, rgba8 and rgba32f, "
                "half texel on; cpu and vulkan timed over 2 frames)");
  sub->add_option("--frames", f->frames, "Steady-state frames timed per device and configuration")
      ->check(CLI::Range(1u, 1000u));
  sub->add_option("--tiers", f->tiers, "Comma-separated tiers to sweep (default: every tier)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  sub->add_option("--downsamples", f->downsamples, "Comma-separated factors 1..4")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  sub->add_option("--taps", f->taps,
                  "Comma-separated fractions in (0, 1] of the whole kernel's radius")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  sub->add_option("--formats", f->formats, "Comma-separated rgba8, rgba16f, rgba32f")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  sub->add_option("--half-texel", f->half_texel, "Comma-separated on, off")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  sub->add_flag("--no-vulkan", f->no_vulkan, "Run without a Vulkan device (cpu and analytic)");
  sub->add_option("--gpu", f->gpu, "Vulkan device name filter (default: lavapipe)");
  sub->add_flag("--json", f->json, "Print one JSON document on standard output (no progress)");
  sub->add_flag("-q,--quiet", f->quiet, "No progress lines");
  auto stress = std::make_shared<StressFlags>();
  add_stress_flags(sub, *stress);
  set_action(sub, [f, stress] {
    if (!stress->stress && !stress->only.empty()) {
      // Without --stress the sweep would run in full and --case be ignored: refused.
      Report refusal("report", f->json);
      refusal.error("usage", fmt::format("--case {}: needs --stress (tierlift report --stress "
                                         "--case ID runs one case of the stress catalogue)",
                                         stress->only));
      return refusal.finish(kExitUsage);
    }
    if (!stress->stress) return run(*f);
    if (!f->scene.empty() || !f->image.empty() || f->quick) {
      fmt::print(stderr, "tierlift report: error: --stress runs its own catalogue of scenes; "
                         "drop --scene, --image and --quick\n");
      return kExitUsage;
    }
    stress->output = f->output;
    stress->json = f->json;
    stress->quiet = f->quiet;
    stress->gpu = f->gpu;
    return run_stress(*stress);
  });
}

} // namespace tierlift::cli
