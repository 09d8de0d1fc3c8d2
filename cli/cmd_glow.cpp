// tierlift glow: the Real-Time Glow (GPU Gems ch. 21) over a scene — the built-in one, a
// JSON scene file or a PNG with alpha — on the interpreter, on Vulkan and as analytic math,
// with the agreement table of every pair of ways. Only flags, the order of the steps and
// printing live here; the work is tierlift::effects.
#include <algorithm>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "commands.h"
#include "front_end.h"
#include "glow_report.h"
#include "report.h"
#include "tierlift/effects/analytic_device.h"
#include "tierlift/effects/scene.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::cli {
namespace {

struct GlowFlags {
  std::string scene, image, tier, format, backend = "all", output, gpu;
  unsigned downsample = 0; // 0: the scene's
  bool no_half_texel = false, json = false, quiet = false;
  FrontEndOptions listing; // -D, -I, --profile, --skip-validation (its json is unused)
  bool both_devices() const { return backend == "both"; } // cpu and vulkan, no analytic
  unsigned threads = 0;
};

// The scene the flags name (default: the built-in one), with flag overrides applied.
// nullopt after printing the error.
std::optional<effects::Scene> scene_from_flags(const GlowFlags& f, Report& report, int* exit_code) {
  effects::SceneLoad load;
  if (!f.scene.empty())
    load = effects::load_scene_file(f.scene);
  else if (!f.image.empty())
    load = effects::scene_from_png(f.image);
  else
    load.scene = effects::default_scene();
  if (!load.scene) {
    // The loaders' messages are rendered diagnostics ("FILE:LINE:COL: error: ..." and a
    // caret line) already.
    if (report.json())
      report.error(load.io_error ? "io" : "scene", load.error, f.scene.empty() ? f.image : f.scene);
    else
      fmt::print(stderr, "{}{}", load.error, load.error.ends_with('\n') ? "" : "\n");
    *exit_code = load.io_error ? kExitUsage : kExitInvalid;
    return std::nullopt;
  }
  effects::GlowParams& p = load.scene->params;
  if (!f.tier.empty()) p.tier = *effects::parse_tier(f.tier); // CLI11 checked the name
  if (f.downsample != 0) p.downsample = f.downsample;
  if (!f.format.empty()) p.format = *img::parse_format(f.format);
  if (f.no_half_texel) p.half_texel = false;
  p.listing_options.defines = split_defines(f.listing.defines);
  p.listing_options.include_dirs = f.listing.include_dirs;
  p.listing_options.skip_validation = f.listing.skip_validation;
  if (!f.listing.profile.empty()) p.listing_options.profile = ir::parse_profile(f.listing.profile);
  return load.scene;
}

// Prints which pass runs on which device: one line updated in place on a terminal, a line
// per pass otherwise.
effects::PassProgress progress_printer(const std::string& way, bool quiet) {
  if (quiet) return {};
  const bool tty = isatty(STDERR_FILENO) != 0;
  return [way, tty](size_t i, size_t n, const effects::PassDesc& pass) {
    const std::string line =
        fmt::format("[{}] pass {}/{}: {} → {}", way, i + 1, n, pass.name, pass.target);
    if (tty)
      fmt::print(stderr, "\r\033[K{}{}", line, i + 1 == n ? "\n" : "");
    else
      fmt::print(stderr, "{}\n", line);
  };
}

nlohmann::json summary_json(const effects::Scene& scene, const effects::GlowPlan& plan,
                            const std::vector<GlowWay>& ways) {
  const effects::GlowParams& p = scene.params;
  nlohmann::json j = {
      {"scene",
       {{"file", scene.file}, {"image", scene.image}, {"width", p.width}, {"height", p.height}}},
      {"tier", effects::tier_name(p.tier)},
      {"format", img::format_name(p.format)},
      {"downsample", p.downsample},
      {"half_texel", p.half_texel},
      {"intensity", p.intensity},
      {"glow", {{"width", plan.glow_width}, {"height", plan.glow_height}}},
      {"taps", plan.taps.size()},
      {"blur_passes_per_axis", plan.blur_passes_per_axis},
      {"passes", plan.graph.passes.size()},
      {"warnings", scene.warnings}};
  for (const GlowWay& w : ways) {
    nlohmann::json passes = nlohmann::json::array();
    for (const effects::PassRecord& r : w.glow.run.passes)
      passes.push_back({{"pass", r.pass}, {"ms", r.ms}});
    j["timing_ms"][w.name] = {{"total", w.glow.run.total_ms}, {"passes", passes}};
  }
  return j;
}

int run(const GlowFlags& f) {
  Report report("glow", f.json);
  int exit_code = kExitOk;
  if (f.output == "-") {
    report.error("usage", "-o names a folder for glow (several images); '-' is not one");
    return report.finish(kExitUsage);
  }
  if (!f.listing.profile.empty() && !ir::parse_profile(f.listing.profile)) {
    report.error("usage", fmt::format("--profile '{}': expected one of vs_1_1 vs_2_0 ps_1_1 "
                                      "ps_1_2 ps_1_3 ps_1_4 ps_2_0",
                                      f.listing.profile));
    return report.finish(kExitUsage);
  }
  std::optional<effects::Scene> scene = scene_from_flags(f, report, &exit_code);
  if (!scene) return report.finish(exit_code);
  const effects::GlowParams& params = scene->params;
  const std::string where = scene->file.empty() ? "tierlift glow" : scene->file;

  effects::GlowPlan plan = effects::build_glow(params);
  if (!plan) {
    report.error("scene", fmt::format("{}: {}", where, plan.error), scene->file);
    return report.finish(kExitInvalid);
  }
  img::LoadResult image = effects::load_scene_image(*scene);
  if (!image) {
    report.error(image.io_error ? "io" : "scene", image.error, scene->image);
    return report.finish(image.io_error ? kExitUsage : kExitInvalid);
  }
  // The parameters' warnings after the flags' overrides, then the scene's own (the image's).
  std::vector<std::string> warnings = effects::glow_warnings(params);
  for (const std::string& w : scene->warnings)
    if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  for (const std::string& w : warnings) report.warning("scene", fmt::format("{}: {}", where, w));
  scene->warnings = warnings;

  const bool all = f.backend == "all", both = f.both_devices();
  // The device lives until the process ends (never destroyed): lavapipe then stays loaded,
  // so LeakSanitizer can attribute the driver's process-lifetime allocations to its module
  // (tests/lsan.supp), as `tierlift run` does.
  static vulkan::Device* vk = nullptr; // a global root: reachable, so not a leak either
  if ((all || both || f.backend == "vulkan") && !vk) {
    vulkan::DeviceOptions o;
    o.gpu_filter = f.gpu;
    std::string err;
    vk = vulkan::Device::create(o, &err).release();
    if (!vk) {
      report.error("device", err);
      return report.finish(kExitUsage);
    }
  }
  std::vector<std::pair<std::string, std::unique_ptr<effects::PassDevice>>> devices;
  if (all || both || f.backend == "cpu")
    devices.emplace_back("cpu", std::make_unique<effects::CpuPassDevice>(f.threads));
  if (vk && (all || both || f.backend == "vulkan"))
    devices.emplace_back("vulkan", effects::make_vulkan_pass_device(*vk));
  if (all || f.backend == "analytic")
    devices.emplace_back("analytic", effects::make_analytic_pass_device());

  const bool keep = devices.size() > 1;
  std::vector<GlowWay> ways;
  for (auto& [name, device] : devices) {
    ways.push_back({name, effects::run_glow(plan, *image.image, *device, keep,
                                            progress_printer(name, f.quiet || f.json))});
    if (!ways.back().glow.run.ok) {
      report.error("run", ways.back().glow.run.error);
      return report.finish(kExitInvalid);
    }
  }
  std::string err;
  const std::vector<PairAgreement> pairs = compare_ways(ways, &err);
  if (!err.empty()) {
    report.error("agreement", err);
    return report.finish(kExitInvalid);
  }
  std::vector<std::string> written;
  if (!f.output.empty())
    if (err = write_glow_images(f.output, ways, params.format != img::Format::RGBA8,
                                {f.scene, f.image, scene->image}, &written);
        !err.empty()) {
      report.error("io", err, f.output);
      return report.finish(kExitUsage);
    }

  bool all_within = true;
  for (const PairAgreement& p : pairs) all_within = all_within && p.agreement.all_pass;
  if (report.json()) {
    nlohmann::json& j = report.result();
    j = summary_json(*scene, plan, ways);
    if (vk && (all || both || f.backend == "vulkan")) j["vulkan_device"] = vk->name();
    j["agreement"] = agreement_json(pairs);
    j["all_within_targets"] = all_within;
    j["written"] = written;
  } else {
    fmt::print("glow {}: {}x{} {}, downsample {} ({}x{}), {} taps, {} blur passes per axis, "
               "half texel {}\n",
               effects::tier_name(params.tier), params.width, params.height,
               img::format_name(params.format), params.downsample, plan.glow_width,
               plan.glow_height, plan.taps.size(), plan.blur_passes_per_axis,
               params.half_texel ? "on" : "off");
    for (const GlowWay& w : ways)
      fmt::print("{}: {} passes in {:.1f} ms{}\n", w.name, w.glow.run.passes.size(),
                 w.glow.run.total_ms, w.name == "vulkan" ? fmt::format(" ({})", vk->name()) : "");
    print_agreement_table(pairs);
    if (!pairs.empty())
      fmt::print("{}\n", all_within ? "every pair within design.md's targets"
                                    : "BEYOND TARGETS where marked '!'");
    for (const std::string& file : written) fmt::print("wrote {}\n", file);
  }
  if (!all_within) {
    for (const PairAgreement& p : pairs)
      for (const effects::PassAgreement& row : p.agreement.passes)
        if (!row.verdict.pass)
          report.error("agreement",
                       fmt::format("{} vs {}, {}: {}", p.a, p.b, row.pass, row.verdict.summary));
    report.error("agreement", "the ways differ beyond the targets");
    return report.finish(kExitInvalid);
  }
  return report.finish(kExitOk);
}

} // namespace

void register_glow_command(CLI::App& app) {
  auto f = std::make_shared<GlowFlags>();
  CLI::App* sub = app.add_subcommand(
      "glow", "Run the Real-Time Glow (GPU Gems ch. 21) on the interpreter, on Vulkan and as "
              "analytic math, and print how they agree");
  auto* scene = sub->add_option("--scene", f->scene, "Scene file (JSON, listings/scenes/)");
  sub->add_option("--image", f->image, "PNG with alpha as the scene (default glow parameters)")
      ->excludes(scene);
  sub->add_option("--tier", f->tier, "dx9 (Listings 1 + 2) | dx8 (Listings 3 + 4)")
      ->check(CLI::IsMember({"dx9", "dx8"}));
  sub->add_option("--downsample", f->downsample, "Glow resolution 1/N, N = 1..4")
      ->check(CLI::Range(1u, 4u));
  sub->add_option("--format", f->format,
                  "rgba8 | rgba16f | rgba32f (every texture; default: the scene's format, "
                  "rgba32f when it names none)")
      ->check(CLI::IsMember({"rgba8", "rgba16f", "rgba32f"}));
  sub->add_option("--backend", f->backend,
                  "cpu | vulkan | analytic | both | all (both: cpu and vulkan; all: the three "
                  "ways; their agreement is printed)")
      ->check(CLI::IsMember({"cpu", "vulkan", "analytic", "both", "all"}))
      ->capture_default_str();
  sub->add_flag("--no-half-texel", f->no_half_texel,
                "Leave the half texel out of the blur offsets (taps land on texel corners)");
  sub->add_option("-o,--output", f->output,
                  "Folder for {scene,glow,final}-{cpu,vulkan,analytic}.png (opaque; .pfm too "
                  "for float formats)");
  // The listing flags of run, for every listing (built-in or a scene's); --profile applies
  // to the listings of its stage.
  add_front_end_options(sub, f->listing, /*skip_validation_flag=*/true, /*json_flag=*/false);
  sub->add_flag("--json", f->json,
                "Print one JSON document on standard output (docs/command-line.md; no "
                "progress lines)");
  sub->add_flag("-q,--quiet", f->quiet, "No progress lines");
  sub->add_option("--threads", f->threads, "CPU worker threads (0 = every core)")
      ->capture_default_str();
  sub->add_option("--gpu", f->gpu, "Vulkan device name filter (default: lavapipe)");
  set_action(sub, [f] { return run(*f); });
}

} // namespace tierlift::cli
