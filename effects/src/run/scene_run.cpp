// run_scene: a scene from its effect's graph to the agreement of every pair of ways (see
// scene_run.h). Each step is a function of its own; run_scene only orders them.
#include "tierlift/effects/scenes/scene_run.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "scene_animation.h"
#include "tierlift/effects/graph/analytic_device.h"
#include "tierlift/effects/graph/memory_plan.h"

namespace tierlift::effects {
namespace {

// One diagnostic as it is given: no word shortened (the messages quote no input), so the
// front end shows exactly the words built here.
ir::Diagnostic diagnostic(ir::Severity severity, std::string rule, std::string message,
                          std::string subject = "") {
  return {severity, {}, std::move(message), std::move(rule), std::move(subject)};
}

// The failure: the warnings so far, then the error.
ir::Failure failure(std::vector<ir::Diagnostic> warnings, std::string rule, std::string message,
                    std::string subject = "") {
  warnings.push_back(
      diagnostic(ir::Severity::Error, std::move(rule), std::move(message), std::move(subject)));
  return ir::Failure{std::move(warnings)};
}

// The run's peak (plan_memory) against what the machine has: empty when it fits, else why
// not and what would fit.
std::string memory_refusal(const EffectPlan& plan, const std::vector<std::string>& names,
                           unsigned frames, const std::string& where, uint64_t* planned) {
  const uint64_t available = available_memory();
  // The scene as loaded stays beside the run, and the program (kProgramBytes); frames run
  // each device once more, alone.
  const TextureDesc& in = *plan.graph.find_texture(kSceneTexture);
  const uint64_t scene = uint64_t{in.width} * in.height * 16 + kProgramBytes;
  auto peak = [&](const std::vector<std::string>& devices) {
    MemoryPlan m = plan_memory(plan.graph, devices, devices.size() > 1, scene);
    uint64_t again = 0;
    if (frames > 0)
      for (const DeviceMemory& d : m.devices) again = std::max(again, d.kept);
    return m.peak + again;
  };
  const uint64_t need = peak(names);
  *planned = need;
  if (available == 0 || need <= available) return {}; // 0: unknown, nothing to hold against
  std::string alone;
  for (const std::string& d : names)
    if (names.size() > 1 && peak({d}) <= available)
      alone += fmt::format("{}--backend {} alone needs {}", alone.empty() ? "; " : ", ", d,
                           format_bytes(peak({d})));
  return fmt::format("{}: the glow at {}x{} ({}, {}) needs {} of memory at its peak and {} is "
                     "available; a smaller --format, a larger --downsample or fewer devices "
                     "(--backend) need less{}",
                     where, in.width, in.height, img::format_name(in.format),
                     fmt::join(names, " + "), format_bytes(need), format_bytes(available), alone);
}

// The effect's warnings after the caller's overrides, then the scene's own (the image's),
// each once.
std::vector<std::string> scene_warnings(const Scene& scene, const EffectPlan& plan, bool moves,
                                        unsigned frames) {
  std::vector<std::string> warnings = effect_warnings(scene);
  for (const std::string& w : afterimage_warnings(scene.params, plan.taps)) warnings.push_back(w);
  if (moves && frames == 0)
    warnings.push_back(scene.effect == EffectKind::RadialBeams
                           ? "the star moves from frame to frame (radial amplitude > 0); this "
                             "run shows its first frame only: --frames N runs N frames"
                           : "the scene changes from frame to frame (after-image or "
                             "keyframes); this run shows frame 1 only: --frames N runs N "
                             "frames");
  for (const std::string& w : scene.warnings)
    if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(w);
  return warnings;
}

// Frames on a still scene: each device again, fresh, setup apart from N steady-state frames;
// the last frame must be the image the compared run made (every texture of a still scene is
// first written by a replacing pass, so each frame repeats the first).
std::string run_still_frames(const EffectPlan& plan, const img::Image& image,
                             const std::vector<WayRun>& ways, const DeviceMaker& make,
                             const SceneRunOptions& o, double vk_create_ms,
                             std::vector<FrameReport>& out) {
  const std::string final_name(kFinalTexture);
  for (const WayRun& way : ways) {
    std::unique_ptr<PassDevice> device = make(way.name);
    if (!device) return fmt::format("{}: no device", way.name);
    EffectFrames run = run_effect_frames(plan, image, *device, o.frames, {}, {}, {},
                                         o.frame_progress ? o.frame_progress(way.name) : nullptr);
    if (!run.run.ok()) return run.run.message();
    if (way.name == "vulkan") run.run->setup_ms += vk_create_ms; // the device is setup too
    auto a = run.images.find(final_name);
    auto b = way.glow.images.find(final_name);
    if (a == run.images.end() || b == way.glow.images.end() || a->second.rgba != b->second.rgba)
      return fmt::format("{}: frame {} differs from the compared run", way.name, o.frames);
    out.push_back({way.name, run.run.value()});
  }
  return {};
}

// The compared run: every way once, pass images kept when there is a pair to compare.
std::string run_ways(const EffectPlan& plan, const img::Image& image, const DeviceMaker& make,
                     const SceneRunOptions& o, SceneRun& out) {
  const bool keep = out.selected.ways.size() > 1;
  for (const std::string& name : out.selected.ways) {
    std::unique_ptr<PassDevice> device = make(name);
    out.ways.push_back({name, run_effect(plan, image, *device, keep,
                                         o.pass_progress ? o.pass_progress(name) : nullptr)});
    if (!out.ways.back().glow.run.ok()) return out.ways.back().glow.run.message();
  }
  return {};
}

// With frames: the steady state of a still scene, or every frame of a moving one.
std::string run_more_frames(const Scene& scene, const img::Image& image, const DeviceMaker& make,
                            const SceneRunOptions& o, double vk_create_ms, SceneRun& out) {
  if (!out.animated)
    return o.frames > 0
               ? run_still_frames(out.plan, image, out.ways, make, o, vk_create_ms, out.frames)
               : std::string();
  std::vector<std::string> names;
  for (const WayRun& w : out.ways) names.push_back(w.name);
  SceneAt scene_at;
  if (scene.params.motion.on())
    scene_at = [&scene](unsigned frame) { return load_scene_image(scene, frame + 1); };
  if (std::string e = run_animation(out.plan, image, names, make, o.frames, o.frames_folder,
                                    scene_at, o.frame_progress, out.animation);
      !e.empty())
    return e;
  for (FrameReport& r : out.animation.times)
    if (r.device == "vulkan") r.times.setup_ms += vk_create_ms;
  return {};
}

} // namespace

ir::Result<std::vector<PairAgreement>> compare_ways(const std::vector<WayRun>& ways) {
  std::vector<PairAgreement> pairs;
  for (size_t i = 0; i < ways.size(); ++i)
    for (size_t j = i + 1; j < ways.size(); ++j) {
      ir::Result<RunAgreement> compared =
          compare_runs(*ways[i].glow.run, ways[i].glow.images, *ways[j].glow.run,
                       ways[j].glow.images, std::string(kFinalTexture));
      if (!compared)
        return ir::fail(
            ways[i].name + " vs " + ways[j].name, "agreement",
            fmt::format("{} vs {}: {}", ways[i].name, ways[j].name, compared.message()));
      pairs.push_back({ways[i].name, ways[j].name, std::move(*compared)});
    }
  return pairs;
}

bool SceneRun::all_within() const {
  bool within = !animated || animation.all_within();
  for (const PairAgreement& p : pairs) within = within && p.agreement.all_pass;
  return within;
}

ir::Result<SceneRun> run_scene(const Scene& scene_in, const SceneRunOptions& o) {
  SceneRun out;
  out.scene = scene_in;
  Scene& scene = out.scene;
  const std::string where = scene.file.empty() ? "tierlift glow" : scene.file;
  // The radial star moves through the frames (per-frame vertex constants).
  if (scene.effect == EffectKind::RadialBeams && o.frames > 0) scene.radial.frames = o.frames;
  out.moves = scene_animated(scene);
  out.animated = o.frames > 0 && out.moves;
  PlanResult built = build_scene_effect(scene);
  if (!built)
    return failure({}, "scene", fmt::format("{}: {}", where, built.message()), scene.file);
  out.plan = std::move(built).value();
  if (std::string e =
          memory_refusal(out.plan, o.backends.ways, o.frames, where, &out.planned_bytes);
      !e.empty())
    return failure({}, "memory", std::move(e));
  img::ImageResult image = load_scene_image(scene);
  if (!image)
    return failure({}, img::is_io_error(image) ? "io" : "scene", image.message(), scene.image);
  std::vector<ir::Diagnostic> told;
  scene.warnings = scene_warnings(scene, out.plan, out.moves, o.frames);
  for (const std::string& w : scene.warnings)
    told.push_back(diagnostic(ir::Severity::Warning, "scene", fmt::format("{}: {}", where, w)));
  out.pruned = prune_glow(out.plan, *image);
  // A moving scene changes the image every frame: the bounds pruning takes from frame 1's
  // image would not hold for the others.
  if (o.prune && !scene.params.motion.on()) out.plan.graph = out.pruned.graph;

  // The process's device (vulkan::process_device, through select_ways): never destroyed, so
  // lavapipe stays loaded for LeakSanitizer (tests/lsan.supp). "all" leaves Vulkan out, with
  // a note, where the machine has none.
  const auto t0 = std::chrono::steady_clock::now();
  ir::Result<SelectedWays> selected = select_ways(o.backends, o.vulkan);
  if (!selected) return failure(std::move(told), "device", selected.message());
  out.selected = std::move(selected).value();
  vulkan::Device* vk = out.selected.vulkan;
  const double vk_create_ms =
      vk ? std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()
         : 0;
  if (vk) out.vulkan_device = vk->name();
  if (!out.selected.note.empty())
    told.push_back(diagnostic(ir::Severity::Warning, "backend", out.selected.note));
  const unsigned threads = o.threads;
  const DeviceMaker make = [vk, threads](const std::string& name) -> std::unique_ptr<PassDevice> {
    if (name == "cpu") return std::make_unique<CpuPassDevice>(threads);
    if (name == "vulkan") return vk ? make_vulkan_pass_device(*vk) : nullptr;
    return make_analytic_pass_device();
  };

  if (std::string e = run_ways(out.plan, *image, make, o, out); !e.empty())
    return failure(std::move(told), "run", std::move(e));
  ir::Result<std::vector<PairAgreement>> compared = compare_ways(out.ways);
  if (!compared) return failure(std::move(told), "agreement", compared.message());
  out.pairs = std::move(compared).value();
  if (std::string e = run_more_frames(scene, *image, make, o, vk_create_ms, out); !e.empty())
    return failure(std::move(told), "frames", std::move(e));
  ir::Result<SceneRun> result(std::move(out));
  for (ir::Diagnostic& d : told) result.add(std::move(d));
  return result;
}

} // namespace tierlift::effects
