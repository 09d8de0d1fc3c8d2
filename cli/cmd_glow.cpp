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
#include "tierlift/effects/analytic_device.h"
#include "tierlift/effects/backends.h"
#include "tierlift/effects/memory_plan.h"
#include "tierlift/effects/prune.h"
#include "tierlift/effects/scene.h"
#include "tierlift/ir/ps1x_range.h"
#include "vulkan_device.h"

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
  effects::GlowParams& p = load->params;
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

// Memory known before running: the run's peak (effects::plan_memory) against what the
// machine has. False after printing why the scene does not fit, and what would.
bool memory_fits(const effects::GlowPlan& plan, const GlowFlags& f,
                 const std::vector<std::string>& names, const std::string& where, Report& report,
                 uint64_t* planned) {
  const uint64_t available = effects::available_memory();
  // The scene as loaded stays beside the run; --frames runs each device once more, alone.
  // Besides the images: the program, its listings and the Vulkan driver (lavapipe, LLVM),
  // measured at 92 MB resident for a 16×16 scene on all three devices.
  constexpr uint64_t kProgramBytes = 96ull << 20;
  const effects::TextureDesc& in = *plan.graph.find_texture(effects::kSceneTexture);
  const uint64_t scene = uint64_t{in.width} * in.height * 16 + kProgramBytes;
  auto peak = [&](const std::vector<std::string>& devices) {
    effects::MemoryPlan m = effects::plan_memory(plan.graph, devices, devices.size() > 1, scene);
    uint64_t again = 0;
    if (f.frames > 0)
      for (const effects::DeviceMemory& d : m.devices) again = std::max(again, d.kept);
    return m.peak + again;
  };
  const uint64_t need = peak(names);
  *planned = need;
  if (available == 0 || need <= available) return true; // 0: unknown, nothing to hold against
  std::string alone;
  for (const std::string& d : names)
    if (names.size() > 1 && peak({d}) <= available)
      alone += fmt::format("{}--backend {} alone needs {}", alone.empty() ? "; " : ", ", d,
                           effects::format_bytes(peak({d})));
  report.error("memory",
               fmt::format("{}: the glow at {}x{} ({}, {}) needs {} of memory at its peak and {} "
                           "is available; a smaller --format, a larger --downsample or fewer "
                           "devices (--backend) need less{}",
                           where, in.width, in.height, img::format_name(in.format),
                           fmt::join(names, " + "), effects::format_bytes(need),
                           effects::format_bytes(available), alone));
  return false;
}

// A fresh device of the kind `name` names (the Vulkan one over the process's device).
std::unique_ptr<effects::PassDevice> make_device(const std::string& name, const GlowFlags& f,
                                                 vulkan::Device* vk) {
  if (name == "cpu") return std::make_unique<effects::CpuPassDevice>(f.threads);
  if (name == "vulkan") return vk ? effects::make_vulkan_pass_device(*vk) : nullptr;
  return effects::make_analytic_pass_device();
}

// --frames N: each device again, fresh, setup apart from N steady-state frames; the last
// frame must be the image the compared run made (every texture of the glow is first written
// by a replacing pass, so each frame repeats the first). Empty string on success.
std::string run_frames(const effects::GlowPlan& plan, const img::Image& scene,
                       const std::vector<GlowWay>& ways, const GlowFlags& f, vulkan::Device* vk,
                       double vk_create_ms, std::vector<FrameReport>& out) {
  const std::string final_name(effects::kFinalTexture);
  for (const GlowWay& way : ways) {
    std::unique_ptr<effects::PassDevice> device = make_device(way.name, f, vk);
    if (!device) return fmt::format("{}: no device", way.name);
    effects::GlowFrames run = effects::run_glow_frames(plan, scene, *device, f.frames, {}, {}, {},
                                                       frame_progress_line(way.name));
    if (!run.run.ok()) return run.run.message();
    if (way.name == "vulkan") run.run->setup_ms += vk_create_ms; // the device is setup too
    auto a = run.images.find(final_name);
    auto b = way.glow.images.find(final_name);
    if (a == run.images.end() || b == way.glow.images.end() || a->second.rgba != b->second.rgba)
      return fmt::format("{}: frame {} differs from the compared run", way.name, f.frames);
    out.push_back({way.name, run.run.value()});
  }
  return {};
}

nlohmann::json summary_json(const effects::Scene& scene, const effects::GlowPlan& plan,
                            const std::vector<GlowWay>& ways) {
  const effects::GlowParams& p = scene.params;
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
  for (const GlowWay& w : ways) {
    nlohmann::json passes = nlohmann::json::array();
    for (const effects::PassRecord& r : w.glow.run->passes)
      passes.push_back({{"pass", r.pass}, {"ms", r.ms}});
    j["timing_ms"][w.name] = {{"total", w.glow.run->total_ms}, {"passes", passes}};
  }
  return j;
}

int run(const GlowFlags& f) {
  Report report("glow", f.json);
  set_frame_progress(!f.quiet && !f.json);
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
  const ir::Result<effects::BackendChoice> backends =
      effects::parse_backends(f.backend, {"cpu", "vulkan", "analytic"});
  if (!backends) {
    report.error("usage", backends.message());
    return report.finish(kExitUsage);
  }
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
  const effects::GlowParams& params = scene->params;
  const std::string where = scene->file.empty() ? "tierlift glow" : scene->file;

  const bool radial = scene->effect == effects::EffectKind::RadialBeams;
  // The radial star moves through the frames --frames runs (per-frame vertex constants).
  if (radial && f.frames > 0) scene->radial.frames = f.frames;
  const bool scene_moves = effects::scene_animated(*scene);
  effects::PlanResult built = effects::build_scene_effect(*scene);
  if (!built) {
    report.error("scene", fmt::format("{}: {}", where, built.message()), scene->file);
    return report.finish(kExitInvalid);
  }
  effects::GlowPlan& plan = *built;
  uint64_t planned_bytes = 0;
  if (!memory_fits(plan, f, backends->ways, where, report, &planned_bytes))
    return report.finish(kExitInvalid);
  img::ImageResult image = effects::load_scene_image(*scene);
  if (!image) {
    const bool io = img::is_io_error(image);
    report.error(io ? "io" : "scene", image.message(), scene->image);
    return report.finish(io ? kExitUsage : kExitInvalid);
  }
  // The parameters' warnings after the flags' overrides, then the scene's own (the image's).
  std::vector<std::string> warnings = effects::effect_warnings(*scene);
  for (const std::string& w : effects::afterimage_warnings(params, plan.taps))
    warnings.push_back(w);
  if (scene_moves && f.frames == 0)
    warnings.push_back(radial ? "the star moves from frame to frame (radial amplitude > 0); this "
                                "run shows its first frame only: --frames N runs N frames"
                              : "the scene changes from frame to frame (after-image or "
                                "keyframes); this run shows frame 1 only: --frames N runs N "
                                "frames");
  for (const std::string& w : scene->warnings)
    if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  for (const std::string& w : warnings) report.warning("scene", fmt::format("{}: {}", where, w));
  scene->warnings = warnings;
  // Leave out what this scene does not need (prune.h), unless --no-prune.
  const effects::PrunedGraph pruned = effects::prune_glow(plan, *image);
  // A moving scene changes the image every frame: the bounds pruning takes from frame 1's
  // image would not hold for the others.
  if (!f.no_prune && !params.motion.on()) plan.graph = pruned.graph;

  // The process's device (vulkan::process_device): never destroyed, so lavapipe stays loaded
  // and LeakSanitizer can attribute the driver's process-lifetime allocations to its module
  // (tests/lsan.supp), as in `tierlift run`. "all" leaves Vulkan out, with a note, where the
  // machine has none (effects::select_ways).
  const auto t0 = std::chrono::steady_clock::now();
  vulkan::DeviceOptions vk_options;
  vk_options.gpu_filter = f.gpu;
  const ir::Result<effects::SelectedWays> selected = effects::select_ways(*backends, vk_options);
  if (!selected) {
    report.error("device", selected.message());
    return report.finish(kExitUsage);
  }
  vulkan::Device* vk = selected->vulkan;
  const double vk_create_ms =
      vk ? std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()
         : 0;
  if (!selected->note.empty()) report.warning("backend", selected->note);
  std::vector<std::pair<std::string, std::unique_ptr<effects::PassDevice>>> devices;
  for (const std::string& name : selected->ways)
    devices.emplace_back(name, make_device(name, f, vk));

  const bool keep = devices.size() > 1;
  std::vector<GlowWay> ways;
  for (auto& [name, device] : devices) {
    ways.push_back({name, effects::run_glow(plan, *image, *device, keep,
                                            progress_printer(name, f.quiet || f.json))});
    if (!ways.back().glow.run.ok()) {
      report.error("run", ways.back().glow.run.message());
      return report.finish(kExitInvalid);
    }
  }
  ir::Result<std::vector<PairAgreement>> compared = compare_ways(ways);
  if (!compared) {
    report.error("agreement", compared.message());
    return report.finish(kExitInvalid);
  }
  const std::vector<PairAgreement> pairs = std::move(compared).value();
  std::string err;
  std::vector<FrameReport> frames;
  Animation animation;
  const bool animated = f.frames > 0 && scene_moves;
  if (animated) {
    std::vector<std::string> names;
    for (const GlowWay& w : ways) names.push_back(w.name);
    auto make = [&](const std::string& name) { return make_device(name, f, vk); };
    effects::SceneAt scene_at;
    if (params.motion.on())
      scene_at = [&](unsigned frame) { return effects::load_scene_image(*scene, frame + 1); };
    if (err = run_animation(plan, *image, names, make, f.frames, out_dir ? &*out_dir : nullptr,
                            scene_at, animation);
        !err.empty()) {
      report.error("frames", err);
      return report.finish(kExitInvalid);
    }
    for (FrameReport& r : animation.times)
      if (r.device == "vulkan") r.times.setup_ms += vk_create_ms;
  } else if (f.frames > 0)
    if (err = run_frames(plan, *image, ways, f, vk, vk_create_ms, frames); !err.empty()) {
      report.error("frames", err);
      return report.finish(kExitInvalid);
    }
  std::vector<std::string> written;
  if (out_dir) {
    err = write_glow_images(*out_dir, ways, params.format != img::Format::RGBA8);
    if (err.empty()) {
      ir::Result<std::vector<std::string>> done = out_dir->commit();
      if (done)
        written = std::move(done).value();
      else
        err = done.message();
    }
    if (!err.empty()) {
      report.error("io", err, f.output);
      return report.finish(kExitUsage);
    }
  }

  bool all_within = !animated || animation.all_within();
  for (const PairAgreement& p : pairs) all_within = all_within && p.agreement.all_pass;
  if (report.json()) {
    nlohmann::json& j = report.result();
    j = summary_json(*scene, plan, ways);
    if (vk) j["vulkan_device"] = vk->name();
    j["backends"] = {{"ran", selected->ways}, {"note", selected->note}};
    if (!selected->left_out_why.empty())
      j["backends"]["left_out"] = {{{"way", "vulkan"}, {"why", selected->left_out_why}}};
    j["agreement"] = agreement_json(pairs);
    if (!frames.empty()) j["frames"] = frames_json(frames);
    if (animated) {
      j["frames"] = frames_json(animation.times);
      j["animation"] = animation_json(animation);
    }
    j["memory"] = {{"planned_peak_bytes", planned_bytes},
                   {"available_bytes", effects::available_memory()}};
    j["all_within_targets"] = all_within;
    j["pruning"] = pruning_json(pruned, !f.no_prune);
    j["written"] = written;
  } else {
    if (radial)
      fmt::print("radial-beams {}: {}x{} {}, {} copies toward ({}, {}), {} zoom passes, strength "
                 "{}, {}\n",
                 effects::tier_name(params.tier), params.width, params.height,
                 img::format_name(params.format), scene->radial.steps, scene->radial.centre[0],
                 scene->radial.centre[1], plan.blur_passes_per_axis, scene->radial.strength,
                 animated ? fmt::format("frames {}..{}", scene->radial.frame,
                                        scene->radial.frame + f.frames - 1)
                          : fmt::format("frame {}", scene->radial.frame));
    else if (scene->effect == effects::EffectKind::GlslBlur)
      fmt::print("glsl-blur: {}x{} {}, {} taps per axis, {} GLSL passes (glslang → SPIR-V on "
                 "vulkan; their ps_2_0 twins on cpu)\n",
                 params.width, params.height, img::format_name(params.format), plan.taps.size(),
                 plan.graph.passes.size());
    else
      fmt::print("glow {}: {}x{} {}, downsample {} ({}x{}), {} taps, {} blur passes per axis, "
                 "half texel {}, ps1x-max {}\n",
                 effects::tier_name(params.tier), params.width, params.height,
                 img::format_name(params.format), params.downsample, plan.glow_width,
                 plan.glow_height, plan.taps.size(), plan.blur_passes_per_axis,
                 params.half_texel ? "on" : "off",
                 ir::ps1x_max_label(plan.graph.conventions.ps1x_max_value));
    if (!plan.quantization.empty()) fmt::print("{}\n", plan.quantization);
    if (auto c = effects::context_summary(params.context); !c.empty()) fmt::print("{}\n", c);
    for (const GlowWay& w : ways)
      fmt::print("{}: {} passes in {:.1f} ms{}\n", w.name, w.glow.run->passes.size(),
                 w.glow.run->total_ms, w.name == "vulkan" ? fmt::format(" ({})", vk->name()) : "");
    if (f.explain) print_pruning(pruned, f.no_prune, scene_moves);
    print_frames_table(frames);
    if (animated) print_animation(animation);
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
    for (const FramePairAgreement& p : animation.pairs)
      if (!p.first_failure.empty())
        report.error("agreement", fmt::format("{} vs {}, {}", p.a, p.b, p.first_failure));
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
  sub->add_option("--image", f->image,
                  "PNG with alpha, or PFM (HDR, alpha 1), as the scene (default glow parameters)")
      ->excludes(scene);
  sub->add_option("--tier", f->tier,
                  "dx9 (Listings 1 + 2) | dx8 (Listings 3 + 4) | dx7 (two fixed-function "
                  "texture stages, 8-bit weights)")
      ->check(CLI::IsMember({"dx9", "dx8", "dx7"}));
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
                  "ps_1_x register range of tier dx8: geforce3 (1), radeon8500 (8), d3d9 "
                  "(default), max, or a number >= 1");
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
