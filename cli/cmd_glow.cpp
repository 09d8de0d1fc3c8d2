// tierlift glow: the Real-Time Glow (GPU Gems ch. 21) over a scene — the built-in one, a
// JSON scene file or a PNG with alpha — on the interpreter, on Vulkan and as analytic math,
// with the agreement table of every pair of ways. Only flags, the order of the steps and
// printing live here; the work is tierlift::effects.
#include <algorithm>
#include <chrono>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "commands.h"
#include "front_end.h"
#include "glow_frames.h"
#include "glow_report.h"
#include "progress_line.h"
#include "report.h"
#include "tierlift/effects/glow/prune.h"
#include "tierlift/effects/graph/backends.h"
#include "tierlift/effects/graph/memory_plan.h"
#include "tierlift/effects/scenes/scene.h"
#include "tierlift/effects/scenes/scene_run.h"
#include "tierlift/ir/ps1x_range.h"

namespace tierlift::cli {
namespace {

struct GlowFlags {
  std::string scene, image, tier, format, backend = "all", output, gpu, ps1x_max;
  std::string weight_rounding; // dx7: "plain" | "error-carry"; empty: the scene's
  unsigned downsample = 0;     // 0: the scene's
  bool no_half_texel = false, json = false, quiet = false;
  bool explain = false, no_prune = false; // --explain: what pruning left out; --no-prune
  FrontEndOptions listing; // -D, -I, --profile, --skip-validation (its json is unused)
  unsigned threads = 0;
  unsigned frames = 0; // --frames N: setup and N steady-state frames per device (0: off)
};

// The scene the flags name (default: the built-in one), with flag overrides applied.
// nullopt after printing the error.
std::optional<effects::Scene> scene_from_flags(const GlowFlags& f, Report& report, int* exit_code) {
  ir::Result<effects::Scene> load = effects::load_scene(f.scene, f.image);
  if (!load) {
    const bool io = ir::failed_with(load, effects::kSceneIoRule);
    report.rendered_error(io ? "io" : "scene", load.message(), f.scene.empty() ? f.image : f.scene);
    *exit_code = io ? kExitUsage : kExitInvalid;
    return std::nullopt;
  }
  effects::EffectParams& p = load->params;
  if (!f.tier.empty()) p.tier = *effects::parse_tier(f.tier); // CLI11 checked the name
  if (!f.weight_rounding.empty())
    p.weight_rounding = *effects::parse_weight_rounding(f.weight_rounding); // checked too
  if (f.downsample != 0) p.downsample = f.downsample;
  if (!f.format.empty()) p.format = *img::parse_format(f.format);
  if (f.no_half_texel) p.half_texel = false;
  if (!f.ps1x_max.empty()) {
    const ir::Result<float> m = ir::parse_ps1x_max(f.ps1x_max);
    if (!m) {
      report.error("usage", "--ps1x-max " + m.message());
      *exit_code = kExitUsage;
      return std::nullopt;
    }
    p.ps1x_max = *m;
  }
  p.listing_options.defines = split_defines(f.listing.defines);
  p.listing_options.include_dirs = f.listing.include_dirs;
  p.listing_options.skip_validation = f.listing.skip_validation;
  p.listing_options.strict = f.listing.strict;
  if (!f.listing.profile.empty()) p.listing_options.profile = ir::parse_profile(f.listing.profile);
  return std::move(load).value();
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

nlohmann::json summary_json(const effects::Scene& scene, const effects::EffectPlan& plan,
                            const std::vector<effects::WayRun>& ways) {
  const effects::EffectParams& p = scene.params;
  nlohmann::json j = {
      {"scene",
       {{"file", scene.file}, {"image", scene.image}, {"width", p.width}, {"height", p.height}}},
      {"effect", effects::effect_name(scene.effect)},
      {"tier", effects::tier_name(p.tier)},
      {"format", img::format_name(p.format)},
      {"downsample", p.downsample},
      {"half_texel", p.half_texel},
      {"intensity", p.intensity},
      {"ps1x_max", {{"preset", ir::ps1x_max_label(p.ps1x_max)}, {"value", p.ps1x_max}}},
      {"glow", {{"width", plan.glow_width}, {"height", plan.glow_height}}},
      {"taps", plan.taps.size()},
      {"weight_rounding", p.tier == effects::Tier::Dx7
                              ? nlohmann::json(effects::weight_rounding_name(p.weight_rounding))
                              : nlohmann::json(nullptr)},
      {"weight_bytes", plan.weight_bytes},
      {"quantization", plan.quantization},
      {"blur_passes_per_axis", plan.blur_passes_per_axis},
      {"passes", plan.graph.passes.size()},
      {"warnings", scene.warnings},
      {"effect", effects::effect_name(scene.effect)}};
  if (scene.effect == effects::EffectKind::RadialBeams)
    j["radial"] = {{"centre", scene.radial.centre},       {"steps", scene.radial.steps},
                   {"step", scene.radial.step},           {"strength", scene.radial.strength},
                   {"amplitude", scene.radial.amplitude}, {"rate", scene.radial.rate},
                   {"frame", scene.radial.frame}};
  for (const effects::WayRun& w : ways) {
    nlohmann::json passes = nlohmann::json::array();
    for (const effects::PassRecord& r : w.glow.run->passes)
      passes.push_back({{"pass", r.pass}, {"ms", r.ms}});
    j["timing_ms"][w.name] = {{"total", w.glow.run->total_ms}, {"passes", passes}};
  }
  return j;
}

// The flags' usage errors that need no scene: false after reporting the first.
bool usage_ok(const GlowFlags& f, Report& report) {
  if (f.output == "-") {
    report.error("usage", "-o names a folder for glow (several images); '-' is not one");
    return false;
  }
  if (!f.listing.profile.empty() && !ir::parse_profile(f.listing.profile)) {
    report.error("usage", fmt::format("--profile '{}': expected one of vs_1_1 vs_2_0 ps_1_1 "
                                      "ps_1_2 ps_1_3 ps_1_4 ps_2_0",
                                      f.listing.profile));
    return false;
  }
  return true;
}

// run_scene's warnings and error, in the order they arose; the exit code of the error (a
// file that cannot be read or a device that cannot be had: usage), kExitOk without one.
int report_run(const std::vector<ir::Diagnostic>& diagnostics, Report& report) {
  int exit_code = kExitOk;
  for (const ir::Diagnostic& d : diagnostics) {
    if (d.severity != ir::Severity::Error) {
      report.warning(d.rule, d.message, d.subject);
      continue;
    }
    report.error(d.rule, d.message, d.subject);
    exit_code = d.rule == "io" || d.rule == "device" ? kExitUsage : kExitInvalid;
  }
  return exit_code;
}

// The glow's images and the run's frames into -o DIR, all at once. False after reporting.
bool commit_images(io::OutputFolder& out_dir, const effects::SceneRun& r, const GlowFlags& f,
                   Report& report, std::vector<std::string>& written) {
  std::string err = write_glow_images(out_dir, r.ways, r.scene.params.format != img::Format::RGBA8);
  if (err.empty()) {
    ir::Result<std::vector<std::string>> done = out_dir.commit();
    if (done)
      written = std::move(done).value();
    else
      err = done.message();
  }
  if (err.empty()) return true;
  report.error("io", err, f.output);
  return false;
}

nlohmann::json result_json(const effects::SceneRun& r, const GlowFlags& f,
                           const std::vector<std::string>& written) {
  nlohmann::json j = summary_json(r.scene, r.plan, r.ways);
  if (!r.vulkan_device.empty()) j["vulkan_device"] = r.vulkan_device;
  j["backends"] = {{"ran", r.selected.ways}, {"note", r.selected.note}};
  if (!r.selected.left_out_why.empty())
    j["backends"]["left_out"] = {{{"way", "vulkan"}, {"why", r.selected.left_out_why}}};
  j["agreement"] = agreement_json(r.pairs);
  if (!r.frames.empty()) j["frames"] = frames_json(r.frames);
  if (r.animated) {
    j["frames"] = frames_json(r.animation.times);
    j["animation"] = animation_json(r.animation);
  }
  j["memory"] = {{"planned_peak_bytes", r.planned_bytes},
                 {"available_bytes", effects::available_memory()}};
  j["all_within_targets"] = r.all_within();
  j["pruning"] = pruning_json(r.pruned, !f.no_prune);
  j["written"] = written;
  return j;
}

// The first line of the text output: which effect, at which size and settings.
void print_heading(const effects::SceneRun& r, const GlowFlags& f) {
  const effects::EffectParams& params = r.scene.params;
  const effects::EffectPlan& plan = r.plan;
  const effects::RadialParams& radial = r.scene.radial;
  switch (r.scene.effect) {
  case effects::EffectKind::RadialBeams:
    fmt::print("radial-beams {}: {}x{} {}, {} copies toward ({}, {}), {} zoom passes, strength "
               "{}, {}\n",
               effects::tier_name(params.tier), params.width, params.height,
               img::format_name(params.format), radial.steps, radial.centre[0], radial.centre[1],
               plan.blur_passes_per_axis, radial.strength,
               r.animated ? fmt::format("frames {}..{}", radial.frame, radial.frame + f.frames - 1)
                          : fmt::format("frame {}", radial.frame));
    return;
  case effects::EffectKind::GlslBlur:
    fmt::print("glsl-blur: {}x{} {}, {} taps per axis, {} GLSL passes (glslang → SPIR-V on "
               "vulkan; their ps_2_0 twins on cpu)\n",
               params.width, params.height, img::format_name(params.format), plan.taps.size(),
               plan.graph.passes.size());
    return;
  case effects::EffectKind::Glow:
  case effects::EffectKind::StencilOutline: break;
  }
  fmt::print("glow {}: {}x{} {}, downsample {} ({}x{}), {} taps, {} blur passes per axis, "
             "half texel {}, ps1x-max {}\n",
             effects::tier_name(params.tier), params.width, params.height,
             img::format_name(params.format), params.downsample, plan.glow_width, plan.glow_height,
             plan.taps.size(), plan.blur_passes_per_axis, params.half_texel ? "on" : "off",
             ir::ps1x_max_label(plan.graph.conventions.ps1x_max_value));
}

void print_text(const effects::SceneRun& r, const GlowFlags& f,
                const std::vector<std::string>& written) {
  print_heading(r, f);
  if (!r.plan.quantization.empty()) fmt::print("{}\n", r.plan.quantization);
  if (auto c = effects::context_summary(r.scene.params.context); !c.empty()) fmt::print("{}\n", c);
  for (const effects::WayRun& w : r.ways)
    fmt::print("{}: {} passes in {:.1f} ms{}\n", w.name, w.glow.run->passes.size(),
               w.glow.run->total_ms,
               w.name == "vulkan" ? fmt::format(" ({})", r.vulkan_device) : "");
  if (f.explain) print_pruning(r.pruned, f.no_prune, r.moves);
  print_frames_table(r.frames);
  if (r.animated) print_animation(r.animation);
  print_agreement_table(r.pairs);
  if (!r.pairs.empty())
    fmt::print("{}\n", r.all_within() ? "every pair within design.md's targets"
                                      : "BEYOND TARGETS where marked '!'");
  for (const std::string& file : written) fmt::print("wrote {}\n", file);
}

// Each pair, pass and frame beyond the targets, as errors.
void report_beyond_targets(const effects::SceneRun& r, Report& report) {
  for (const effects::PairAgreement& p : r.pairs)
    for (const effects::PassAgreement& row : p.agreement.passes)
      if (!row.verdict.pass)
        report.error("agreement",
                     fmt::format("{} vs {}, {}: {}", p.a, p.b, row.pass, row.verdict.summary));
  for (const effects::FramePairAgreement& p : r.animation.pairs)
    if (!p.first_failure.empty())
      report.error("agreement", fmt::format("{} vs {}, {}", p.a, p.b, p.first_failure));
  report.error("agreement", "the ways differ beyond the targets");
}

int run(const GlowFlags& f) {
  Report report("glow", f.json);
  set_frame_progress(!f.quiet && !f.json);
  if (!usage_ok(f, report)) return report.finish(kExitUsage);
  const ir::Result<effects::BackendChoice> backends =
      effects::parse_backends(f.backend, {"cpu", "vulkan", "analytic"});
  if (!backends) {
    report.error("usage", backends.message());
    return report.finish(kExitUsage);
  }
  int exit_code = kExitOk;
  std::optional<effects::Scene> scene = scene_from_flags(f, report, &exit_code);
  if (!scene) return report.finish(exit_code);
  // -o DIR is written as one (io/output_folder.h): complete at the end, or untouched.
  std::optional<io::OutputFolder> out_dir;
  if (!f.output.empty()) {
    std::vector<std::string> inputs = effects::scene_input_files(*scene);
    inputs.insert(inputs.end(), {f.scene, f.image});
    out_dir.emplace(f.output, std::move(inputs), "glow");
    if (ir::Status s = out_dir->status(); !s) {
      report.error("io", s.message(), f.output);
      return report.finish(kExitUsage);
    }
  }
  effects::SceneRunOptions options;
  options.backends = *backends;
  options.vulkan.gpu_filter = f.gpu;
  options.threads = f.threads;
  options.frames = f.frames;
  options.prune = !f.no_prune;
  options.frames_folder = out_dir ? &*out_dir : nullptr;
  const bool quiet = f.quiet || f.json;
  options.pass_progress = [quiet](const std::string& way) { return progress_printer(way, quiet); };
  options.frame_progress = frame_progress_line;
  ir::Result<effects::SceneRun> ran = effects::run_scene(*scene, options);
  if (int failed = report_run(ran.diagnostics(), report); failed != kExitOk)
    return report.finish(failed);
  const effects::SceneRun& r = *ran;
  std::vector<std::string> written;
  if (out_dir && !commit_images(*out_dir, r, f, report, written)) return report.finish(kExitUsage);
  if (report.json())
    report.result() = result_json(r, f, written);
  else
    print_text(r, f, written);
  if (r.all_within()) return report.finish(kExitOk);
  report_beyond_targets(r, report);
  return report.finish(kExitInvalid);
}

} // namespace

void register_glow_command(CLI::App& app) {
  auto f = std::make_shared<GlowFlags>();
  CLI::App* sub = app.add_subcommand(
      "glow", "Run the Real-Time Glow (GPU Gems ch. 21) on the interpreter, on Vulkan and as "
              "analytic math, and print how they agree");
  auto* scene = sub->add_option("--scene", f->scene, "Scene file (JSON, listings/scenes/)");
  sub->add_option("--image", f->image,
                  "PNG with alpha, or PFM (HDR, alpha 1), as the scene (default glow parameters)")
      ->excludes(scene);
  sub->add_option("--tier", f->tier,
                  "dx9 (Listings 1 + 2) | dx8 (Listings 3 + 4) | dx7 (two fixed-function "
                  "texture stages, 8-bit weights) | dx9c (ps_3_0 blur: one loop of texldl)")
      ->check(CLI::IsMember({"dx9", "dx8", "dx7", "dx9c"}));
  sub->add_option("--weight-rounding", f->weight_rounding,
                  "Tier dx7: how blur weights become 8-bit vertex colours: plain | error-carry "
                  "(default: the scene's, error-carry when it names none)")
      ->check(CLI::IsMember({"plain", "error-carry"}));
  sub->add_option("--downsample", f->downsample, "Glow resolution 1/N, N = 1..4")
      ->check(CLI::Range(1u, 4u));
  sub->add_option("--format", f->format,
                  "rgba8 | rgba16f | rgba32f (every texture; default: the scene's format, "
                  "rgba32f when it names none)")
      ->check(CLI::IsMember({"rgba8", "rgba16f", "rgba32f"}));
  sub->add_option("--backend", f->backend,
                  "cpu | vulkan | analytic | both | all, or a comma list such as cpu,analytic "
                  "(both: cpu and vulkan; all: every way the machine has, saying what it left "
                  "out; the agreement of every pair that ran is printed)")
      ->capture_default_str();
  sub->add_option("--ps1x-max", f->ps1x_max,
                  "ps_1_x register range of tier dx8: " + ir::ps1x_choices());
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
  sub->add_flag("--explain", f->explain, "List what pruning leaves out for this scene, and why");
  sub->add_flag("--no-prune", f->no_prune, "Run the whole plan (nothing left out)");
  sub->add_option("--threads", f->threads, "CPU worker threads (0 = every core)")
      ->capture_default_str();
  sub->add_option("--frames", f->frames,
                  "Run each device again N times: setup apart from steady-state frames "
                  "(median, min, max); a scene that changes per frame (after-image, "
                  "keyframes) is compared frame by frame, and -o writes frame-0001.png …")
      ->check(CLI::Range(1u, 100000u));
  sub->add_option("--gpu", f->gpu, "Vulkan device name filter (default: lavapipe)");
  set_action(sub, [f] { return run(*f); });
}

} // namespace tierlift::cli
