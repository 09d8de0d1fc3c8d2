// The report's sweep (report_sweep.h): configurations, their runs, the Pareto front.
#include "tierlift/effects/report/report_sweep.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/glow/prune.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"

namespace tierlift::effects {
namespace {

// Taps per axis of the whole kernel at this downsample factor (0 when it cannot be sampled).
unsigned whole_taps(const BlurProfile& profile, unsigned downsample) {
  BlurProfile p = profile;
  p.max_taps = 0;
  ir::Result<std::vector<BlurTap>> taps = sample_blur_profile(p, downsample);
  return taps ? unsigned(taps->size()) : 0;
}

// Taps per axis of radius × fraction (odd, at least 1).
unsigned taps_for(unsigned whole, double fraction) {
  if (whole == 0) return 0;
  const double radius = (whole - 1) / 2.0;
  const auto r = static_cast<unsigned>(std::lround(std::clamp(fraction, 0.0, 1.0) * radius));
  return 2 * r + 1;
}

std::unique_ptr<PassDevice> make_device(const std::string& name, vulkan::Device* vk) {
  if (name == "cpu") return std::make_unique<CpuPassDevice>();
  if (name == "vulkan") return vk ? make_vulkan_pass_device(*vk) : nullptr;
  if (name == "analytic") return make_analytic_pass_device();
  return nullptr;
}

EffectParams params_for(const EffectParams& scene, const SweepConfig& c) {
  EffectParams p = scene;
  p.tier = c.tier;
  p.downsample = c.downsample;
  p.format = c.format;
  p.half_texel = c.half_texel;
  p.profile.max_taps = c.taps;
  return p;
}

struct Way {
  std::string name;
  EffectRun glow;
};

// Runs one configuration; a device failure returns its message (the sweep stops).
std::string run_config(ConfigResult& out, const Scene& scene, const img::Image& image,
                       const SweepSettings& s, vulkan::Device* vk, const RgbImage& ideal_glow_img,
                       const RgbImage& ideal_final_img) {
  const EffectParams params = params_for(scene.params, out.config);
  const PlanResult built = build_glow(params);
  if (!built) {
    out.skipped = built.message();
    return {};
  }
  const EffectPlan& plan = *built;
  out.taps = unsigned(plan.taps.size());
  out.passes = unsigned(plan.graph.passes.size());
  out.glow_width = plan.glow_width;
  out.glow_height = plan.glow_height;

  std::vector<Way> ways;
  for (const char* name : {"cpu", "vulkan", "analytic"}) {
    std::unique_ptr<PassDevice> device = make_device(name, vk);
    if (!device) continue;
    ways.push_back({name, run_effect(plan, image, *device, /*keep_pass_images=*/true)});
    if (!ways.back().glow.run.ok())
      return fmt::format("{}, {}: {}", config_label(out.config), name,
                         ways.back().glow.run.message());
  }
  out.all_agree = true;
  for (size_t i = 0; i < ways.size(); ++i)
    for (size_t j = i + 1; j < ways.size(); ++j) {
      const ir::Result<RunAgreement> compared =
          compare_runs(*ways[i].glow.run, ways[i].glow.images, *ways[j].glow.run,
                       ways[j].glow.images, std::string(kFinalTexture));
      if (!compared)
        return fmt::format("{}, {} vs {}: {}", config_label(out.config), ways[i].name, ways[j].name,
                           compared.message());
      const RunAgreement& a = *compared;
      PairResult p{ways[i].name, ways[j].name, a.all_pass, 0};
      if (!a.passes.empty()) p.frame_max_abs = a.passes.back().comparison.max_abs_all;
      out.all_agree = out.all_agree && a.all_pass;
      out.agreement.push_back(p);
    }
  // The error against the ideal, on the Vulkan run when there is one (what a user ships).
  const Way* measured = &ways.front();
  for (const Way& w : ways)
    if (w.name == "vulkan") measured = &w;
  const img::Image& glow = measured->glow.images.at(std::string(kGlowTexture));
  const img::Image& final = measured->glow.images.at(std::string(kFinalTexture));
  out.glow = error_against(ideal_glow_img,
                           upsample_glow(glow, params.width, params.height, params.downsample));
  out.final = error_against(ideal_final_img, displayed(rgb_of(final)));
  ways.clear(); // the pass images are large; the timing runs need the memory

  // The device whose frame time the plot uses: Vulkan when timed, else the first timed.
  std::string clock;
  for (const std::string& name : s.timed)
    if (clock.empty() || name == "vulkan") clock = make_device(name, vk) ? name : clock;
  ImageMap clock_images;
  for (const std::string& name : s.timed) {
    std::unique_ptr<PassDevice> device = make_device(name, vk);
    if (!device) continue;
    EffectFrames f = run_effect_frames(plan, image, *device, std::max(1u, s.frames));
    if (!f.run.ok())
      return fmt::format("{}, {} (frames): {}", config_label(out.config), name, f.run.message());
    out.times.push_back({name, f.run->setup_ms, f.run->median_ms(), f.run->min_ms(),
                         f.run->max_ms(), unsigned(f.run->frame_ms.size())});
    if (name == clock) clock_images = std::move(f.images);
  }
  // The same frames with the plan pruned for this scene (prune.h), on the clock device; the
  // pruned frame must equal the whole plan's (RGBA32F within 1e-6, else bit for bit).
  const PrunedGraph pruned = prune_glow(plan, image);
  out.pruned_left_out = pruned.left_out.size();
  out.pruned_limited = pruned.limited.size();
  out.pruned_frame_ms = out.frame_ms();
  if (pruned.changed() && !clock.empty()) {
    EffectPlan lean = plan;
    lean.graph = pruned.graph;
    std::unique_ptr<PassDevice> device = make_device(clock, vk);
    EffectFrames f = run_effect_frames(lean, image, *device, std::max(1u, s.frames));
    if (!f.run.ok())
      return fmt::format("{}, {} (pruned): {}", config_label(out.config), clock, f.run.message());
    out.pruned_frame_ms = f.run->median_ms();
    for (std::string_view tex : {kGlowTexture, kFinalTexture}) {
      const std::vector<float>& a = f.images.at(std::string(tex)).rgba;
      const std::vector<float>& b = clock_images.at(std::string(tex)).rgba;
      const bool f32 = params.format == img::Format::RGBA32F;
      for (size_t i = 0; i < a.size() && i < b.size(); ++i)
        if (f32 ? !(std::abs(a[i] - b[i]) <= 1e-6f)
                : a[i] != b[i] && !(std::isnan(a[i]) && std::isnan(b[i])))
          return fmt::format("{}: pruning changed {} (value {}: {} instead of {})",
                             config_label(out.config), tex, i, a[i], b[i]);
    }
  }
  return {};
}

} // namespace

std::string config_label(const SweepConfig& c) {
  return fmt::format("{} ds{} taps{} {} half-texel {}", tier_name(c.tier), c.downsample, c.taps,
                     img::format_name(c.format), c.half_texel ? "on" : "off");
}

SweepSettings full_sweep() {
  SweepSettings s;
  s.tiers = all_tiers();
  s.downsamples = {1, 2, 3, 4};
  s.taps = {1.0, 0.5, 0.25};
  s.formats = {img::Format::RGBA8, img::Format::RGBA16F, img::Format::RGBA32F};
  s.half_texels = {true, false};
  return s;
}

SweepSettings quick_sweep() {
  SweepSettings s;
  s.tiers = all_tiers();
  s.downsamples = {2, 4};
  s.taps = {1.0, 0.5};
  s.formats = {img::Format::RGBA8, img::Format::RGBA32F};
  s.half_texels = {true};
  s.frames = 2;
  s.timed = {"cpu", "vulkan"};
  s.quick = true;
  return s;
}

std::vector<SweepConfig> sweep_configs(const SweepSettings& s, const EffectParams& scene) {
  std::vector<SweepConfig> out;
  if (s.tiers.empty() || s.downsamples.empty() || s.taps.empty() || s.formats.empty() ||
      s.half_texels.empty())
    return out;
  auto add = [&out](const SweepConfig& c) {
    if (c.taps != 0 && std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
  };
  // The scene's own choice: its taps limit applied to the whole kernel.
  const unsigned own_whole = whole_taps(scene.profile, scene.downsample);
  const unsigned own_taps =
      scene.profile.max_taps == 0 ? own_whole : std::min(scene.profile.max_taps, own_whole);
  add({scene.tier, scene.downsample, own_taps, scene.format, scene.half_texel});
  for (Tier t : s.tiers)
    for (unsigned d : s.downsamples)
      for (double f : s.taps)
        for (img::Format fmt : s.formats)
          for (bool h : s.half_texels)
            add({t, d, taps_for(whole_taps(scene.profile, d), f), fmt, h});
  return out;
}

double ConfigResult::frame_ms() const {
  for (const char* want : {"vulkan", "cpu", "analytic"})
    for (const DeviceTime& t : times)
      if (t.device == want) return t.median_ms;
  return 0;
}

bool same_error(double a, double b) {
  const double tolerance = std::max(kParetoRelativeTolerance * std::max(std::fabs(a), std::fabs(b)),
                                    kParetoAbsoluteTolerance);
  return a == b || std::fabs(a - b) <= tolerance;
}

std::vector<size_t> pareto_front(const std::vector<ConfigResult>& configs) {
  std::vector<size_t> front;
  for (size_t i = 0; i < configs.size(); ++i) {
    const ConfigResult& a = configs[i];
    if (!a.skipped.empty() || a.times.empty()) continue;
    bool dominated = false;
    for (size_t j = 0; j < configs.size() && !dominated; ++j) {
      const ConfigResult& b = configs[j];
      if (j == i || !b.skipped.empty() || b.times.empty()) continue;
      const bool same = same_error(b.final.rmse, a.final.rmse);
      const bool no_worse = same || b.final.rmse < a.final.rmse;
      dominated = b.frame_ms() <= a.frame_ms() && no_worse &&
                  (b.frame_ms() < a.frame_ms() || (!same && b.final.rmse < a.final.rmse));
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(),
            [&](size_t x, size_t y) { return configs[x].frame_ms() < configs[y].frame_ms(); });
  return front;
}

ir::Result<SweepResult> run_sweep(const Scene& scene, const img::Image& image,
                                  const SweepSettings& s, vulkan::Device* vk,
                                  const SweepProgress& progress) {
  auto fail = [](std::string why) { return ir::fail("report", "run", std::move(why)); };
  SweepResult r;
  const std::vector<SweepConfig> configs = sweep_configs(s, scene.params);
  if (configs.empty())
    return fail("the sweep is empty: every list (tiers, downsample, taps, formats, half texel) "
                "needs at least one value");
  if (image.width != scene.params.width || image.height != scene.params.height)
    return fail(fmt::format("the scene image is {}x{}, the scene says {}x{}", image.width,
                            image.height, scene.params.width, scene.params.height));
  // The ideal depends on the scene and its profile only: computed once.
  const RgbImage ideal = ideal_glow(glow_sources(image), scene.params.profile);
  // The final frame as displayed (clamped to [0, 1]) on both sides: ideal_glow.h, displayed().
  const RgbImage ideal_fin = displayed(ideal_final(image, ideal, scene.params.intensity));
  for (size_t i = 0; i < configs.size(); ++i) {
    if (progress) progress(i, configs.size(), configs[i]);
    ConfigResult c;
    c.config = configs[i];
    c.scene_choice = i == 0;
    if (std::string err = run_config(c, scene, image, s, vk, ideal, ideal_fin); !err.empty())
      return fail(err);
    r.configs.push_back(std::move(c));
  }
  r.pareto = pareto_front(r.configs);
  for (size_t i = 0; i < r.configs.size(); ++i) {
    const ConfigResult& c = r.configs[i];
    if (!c.skipped.empty() || c.times.empty() || !(c.final.rmse <= 1.0 / 255)) continue;
    if (!r.cheapest_within || c.frame_ms() < r.configs[*r.cheapest_within].frame_ms())
      r.cheapest_within = i;
  }
  return r;
}

} // namespace tierlift::effects
