// tierlift glow: the Real-Time Glow (tier dx9) over the built-in scene, on the CPU device,
// on Vulkan, or both with a per-pass agreement table. Only flags and printing live here;
// the work is tierlift::effects.
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "tierlift/cpu/run_job.h"
#include "tierlift/effects/agreement.h"
#include "tierlift/effects/default_scene.h"
#include "tierlift/effects/glow_run.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::cli {
namespace {

struct GlowFlags {
  std::string backend = "all", format = "rgba32f", output, gpu;
  unsigned downsample = 2;
  bool no_half_texel = false, json = false;
  unsigned threads = 0;
};

struct DeviceRun {
  std::string name;
  effects::GlowRun glow;
};

// Writes DIR/{scene,glow,final}-<device>.png; empty on success.
std::string write_outputs(const std::string& dir, const DeviceRun& r) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return fmt::format("cannot create '{}': {}", dir, ec.message());
  for (std::string_view tex :
       {effects::kSceneTexture, effects::kGlowTexture, effects::kFinalTexture}) {
    const auto it = r.glow.images.find(tex);
    if (it == r.glow.images.end()) continue;
    const std::string path =
        (std::filesystem::path(dir) / fmt::format("{}-{}.png", tex, r.name)).string();
    // Opaque copies: the scene's alpha is the glow mask, and a PNG viewer would show the
    // dark ground (alpha 0) as transparent.
    img::Image opaque = it->second;
    for (size_t i = 3; i < opaque.rgba.size(); i += 4) opaque.rgba[i] = 1.0f;
    std::string warning;
    if (std::string err = cpu::write_run_output(path, opaque, &warning); !err.empty()) return err;
  }
  return {};
}

nlohmann::json agreement_json(const effects::RunAgreement& a) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& p : a.passes)
    rows.push_back({{"pass", p.pass},
                    {"target", p.target},
                    {"max_abs", p.comparison.max_abs_all},
                    {"rmse", p.comparison.rmse_all},
                    {"identical_share", p.comparison.identical_share},
                    {"within_targets", p.verdict.pass},
                    {"summary", p.verdict.summary}});
  return {{"rows", rows}, {"all_within_targets", a.all_pass}};
}

void print_table(const effects::RunAgreement& a) {
  fmt::print("{:<12} {:<13} {:>10} {:>10} {:>10}  {}\n", "pass", "target", "max abs", "rmse",
             "identical", "verdict");
  for (const auto& p : a.passes)
    fmt::print("{:<12} {:<13} {:>10.3g} {:>10.3g} {:>9.3f}%  {}\n", p.pass, p.target,
               p.comparison.max_abs_all, p.comparison.rmse_all,
               100.0 * p.comparison.identical_share, p.verdict.pass ? "ok" : "BEYOND TARGETS");
}

int run(const GlowFlags& f) {
  effects::GlowParams params;
  auto format = img::parse_format(f.format);
  if (!format || *format == img::Format::RGBA16F) {
    fmt::print(stderr, "tierlift glow: error: --format '{}': expected rgba8 or rgba32f\n",
               f.format);
    return kExitUsage;
  }
  params.format = *format;
  params.downsample = f.downsample;
  params.half_texel = !f.no_half_texel;
  const bool want_cpu = f.backend != "vulkan", want_vulkan = f.backend != "cpu";

  std::unique_ptr<vulkan::Device> vk;
  if (want_vulkan) {
    vulkan::DeviceOptions o;
    o.gpu_filter = f.gpu;
    std::string err;
    vk = vulkan::Device::create(o, &err);
    if (!vk) {
      fmt::print(stderr, "tierlift glow: error: {}\n", err);
      return kExitUsage;
    }
    // Exact bilinear weights on both devices: the Vulkan device samples float textures
    // (R32G32B32A32_SFLOAT) and lavapipe weights those in float, not with the 8 sub-texel
    // bits it reports (measured: a read 0.3/256 texel off a centre returns the exact blend).
  }
  effects::GlowPlan plan = effects::build_glow_dx9(params);
  if (!plan) {
    fmt::print(stderr, "tierlift glow: error: {}\n", plan.error);
    return kExitUsage;
  }
  const img::Image scene = effects::make_default_scene(params.width, params.height);

  std::vector<DeviceRun> runs;
  const bool keep = want_cpu && want_vulkan;
  if (want_cpu) {
    effects::CpuPassDevice dev(f.threads);
    runs.push_back({"cpu", effects::run_glow(plan, scene, dev, keep)});
  }
  if (want_vulkan) {
    auto dev = effects::make_vulkan_pass_device(*vk);
    runs.push_back({"vulkan", effects::run_glow(plan, scene, *dev, keep)});
  }
  for (const DeviceRun& r : runs) {
    if (!r.glow.run.ok) {
      fmt::print(stderr, "tierlift glow: error: {}\n", r.glow.run.error);
      return kExitInvalid;
    }
    if (f.output.empty()) continue;
    if (std::string err = write_outputs(f.output, r); !err.empty()) {
      fmt::print(stderr, "tierlift glow: error: {}\n", err);
      return kExitUsage;
    }
  }

  std::optional<effects::RunAgreement> agreement;
  if (keep) {
    agreement = effects::compare_runs(runs[0].glow.run, runs[0].glow.images, runs[1].glow.run,
                                      runs[1].glow.images, std::string(effects::kFinalTexture));
    if (!agreement->error.empty()) {
      fmt::print(stderr, "tierlift glow: error: {}\n", agreement->error);
      return kExitInvalid;
    }
  }
  if (f.json) {
    nlohmann::json j = {{"scene", {{"width", params.width}, {"height", params.height}}},
                        {"format", img::format_name(params.format)},
                        {"downsample", params.downsample},
                        {"half_texel", params.half_texel},
                        {"glow", {{"width", plan.glow_width}, {"height", plan.glow_height}}},
                        {"taps", plan.taps.size()},
                        {"passes", plan.graph.passes.size()}};
    for (const DeviceRun& r : runs) j["timing_ms"][r.name] = r.glow.run.total_ms;
    if (vk) j["vulkan_device"] = vk->name();
    if (agreement) j["agreement"] = agreement_json(*agreement);
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("glow dx9: {}x{} {}, downsample {} ({}x{}), {} taps, {} blur passes per axis, "
               "half texel {}\n",
               params.width, params.height, img::format_name(params.format), params.downsample,
               plan.glow_width, plan.glow_height, plan.taps.size(), plan.blur_passes_per_axis,
               params.half_texel ? "on" : "off");
    for (const DeviceRun& r : runs)
      fmt::print("{}: {} passes in {:.1f} ms\n", r.name, r.glow.run.passes.size(),
                 r.glow.run.total_ms);
    if (agreement) {
      fmt::print("cpu vs vulkan ({}):\n", vk->name());
      print_table(*agreement);
    }
  }
  if (agreement && !agreement->all_pass) {
    for (const auto& p : agreement->passes)
      if (!p.verdict.pass) fmt::print(stderr, "tierlift glow: {}: {}\n", p.pass, p.verdict.summary);
    fmt::print(stderr, "tierlift glow: error: cpu and vulkan differ beyond the targets\n");
    return kExitInvalid;
  }
  return kExitOk;
}

} // namespace

void register_glow_command(CLI::App& app) {
  auto f = std::make_shared<GlowFlags>();
  CLI::App* sub = app.add_subcommand(
      "glow", "Run the Real-Time Glow (tier dx9: Listings 1 + 2) over the built-in scene");
  sub->add_option("--backend", f->backend, "cpu | vulkan | all (all: compare the devices)")
      ->check(CLI::IsMember({"cpu", "vulkan", "all"}))
      ->capture_default_str();
  sub->add_option("--downsample", f->downsample, "Glow resolution 1/N, N = 1..4")
      ->check(CLI::Range(1u, 4u))
      ->capture_default_str();
  sub->add_option("--format", f->format, "rgba8 | rgba32f (every texture)")->capture_default_str();
  sub->add_flag("--no-half-texel", f->no_half_texel,
                "Leave the half texel out of the blur offsets (taps land on texel corners)");
  sub->add_option("-o,--output", f->output,
                  "Folder for {scene,glow,final}-{cpu,vulkan}.png (written opaque)");
  sub->add_flag("--json", f->json, "Print a JSON summary");
  sub->add_option("--threads", f->threads, "CPU worker threads (0 = every core)")
      ->capture_default_str();
  sub->add_option("--gpu", f->gpu, "Vulkan device name filter (default: lavapipe)");
  set_action(sub, [f] { return run(*f); });
}

} // namespace tierlift::cli
