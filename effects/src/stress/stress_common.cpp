// The stress catalogue's shared parts (stress_common.h) and its entry points (stress.h).
#include "stress_common.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::effects {
namespace {

// NaN matches NaN, an infinity only itself, finite values within the tolerance.
bool within(double measured, double expected, double tolerance) {
  if (std::isnan(expected) || std::isnan(measured))
    return std::isnan(expected) && std::isnan(measured);
  if (std::isinf(expected) || std::isinf(measured)) return measured == expected;
  return std::fabs(measured - expected) <= tolerance;
}

} // namespace

void judge_stress_row(StressRow& row) {
  row.ways_agree = !row.measured.empty();
  row.pass = row.error.empty() && !row.measured.empty();
  for (const StressMeasure& m : row.measured) {
    bool ok = within(m.value, row.expected, row.tolerance);
    if (auto it = row.also_expected.find(m.way); it != row.also_expected.end())
      ok = ok || within(m.value, it->second, row.tolerance);
    row.pass = row.pass && ok;
    const StressMeasure& first = row.measured.front();
    const bool same = !m.mask.empty() || !first.mask.empty()
                          ? m.mask == first.mask
                          : within(m.value, first.value, row.tolerance) ||
                                row.also_expected.contains(m.way) ||
                                row.also_expected.contains(first.way);
    row.ways_agree = row.ways_agree && same;
  }
  row.pass = row.pass && row.ways_agree;
  row.verdict = !row.error.empty() ? "ERROR" : row.pass ? "PASS" : "FAIL";
}

namespace stress {

std::vector<WayImages> run_on_ways(const PlanResult& plan, const img::Image& scene,
                                   const StressOptions& options) {
  std::vector<WayImages> out;
  for (const std::string& way : options.ways) {
    std::unique_ptr<PassDevice> device = options.make_device ? options.make_device(way) : nullptr;
    if (!device) continue;
    if (!plan) {
      out.push_back({way, {}, plan.message()});
      continue;
    }
    EffectRun run = run_effect(*plan, scene, *device);
    out.push_back({way, std::move(run.images), run.run.ok() ? "" : run.run.message()});
  }
  return out;
}

double device_store(img::Format f, double v) {
  const float x = float(v);
  if (f == img::Format::RGBA16F) return rounding::half_toward_zero(double(x));
  return img::quantize(f, x);
}

img::Image uniform_scene(uint32_t w, uint32_t h, float v, float a) {
  img::Image s(w, h, img::Format::RGBA32F);
  for (size_t i = 0; i < s.rgba.size(); i += 4) {
    s.rgba[i] = s.rgba[i + 1] = s.rgba[i + 2] = v;
    s.rgba[i + 3] = a;
  }
  return s;
}

EffectParams small_params(uint32_t w, uint32_t h, unsigned downsample, img::Format format,
                          double sigma, unsigned max_taps) {
  EffectParams p;
  p.width = w;
  p.height = h;
  p.downsample = downsample;
  p.format = format;
  p.profile.terms = {{sigma, 1.0}};
  p.profile.max_taps = max_taps;
  return p;
}

StressRow stress_row(std::string id, std::string regime, std::string format, std::string quantity) {
  StressRow row;
  row.id = std::move(id);
  row.regime = std::move(regime);
  row.format = std::move(format);
  row.quantity = std::move(quantity);
  return row;
}

std::string first_error(const std::vector<WayImages>& ways) {
  if (ways.empty()) return "no way could run (no device)";
  for (const WayImages& w : ways)
    if (!w.error.empty()) return fmt::format("{}: {}", w.way, w.error);
  return {};
}

void measure_masks(StressRow& row, const std::vector<WayImages>& ways, std::string_view texture,
                   const std::function<bool(float)>& hit) {
  row.error = first_error(ways);
  for (const WayImages& wi : ways) {
    if (!wi.error.empty()) continue;
    const img::Image& im = wi.images.at(std::string(texture));
    StressMeasure m{wi.way, 0, {}};
    for (size_t i = 0; i < im.rgba.size(); i += 4) {
      const bool is_hit = hit(im.rgba[i]);
      m.mask.push_back(is_hit ? 1 : 0);
      m.value += is_hit;
    }
    row.measured.push_back(std::move(m));
  }
}

double texel_red(const WayImages& w, std::string_view texture, uint32_t x, uint32_t y) {
  auto it = w.images.find(texture);
  if (it == w.images.end() || x >= it->second.width || y >= it->second.height)
    return std::numeric_limits<double>::quiet_NaN();
  return it->second.at(x, y)[0];
}

const EffectPlan& shape(const PlanResult& plan) {
  static const EffectPlan kNone;
  return plan ? *plan : kNone;
}

void set_blur_weights(EffectPlan& plan, const std::vector<double>& weights) {
  for (PassDesc& d : plan.graph.passes) {
    if (!d.name.starts_with("blur_")) continue;
    const size_t index = std::stoul(d.name.substr(d.name.find('.') + 1));
    const size_t per = d.draw.ps_constants.f.size();
    for (size_t k = 0; k < per; ++k) {
      const size_t t = index * per + k;
      const float w = t < weights.size() && t < plan.taps.size() ? float(weights[t]) : 0.0f;
      d.draw.ps_constants.f[k] = {w, w, w, w};
    }
  }
}

std::vector<StressCase> all_cases() {
  std::vector<StressCase> all = glow_cases();
  for (auto* more : {&extreme_cases, &feedback_cases})
    for (StressCase& c : more()) all.push_back(std::move(c));
  return all;
}

} // namespace stress

std::vector<std::string> stress_case_ids() {
  std::vector<std::string> ids;
  for (const stress::StressCase& c : stress::all_cases()) ids.push_back(c.id);
  return ids;
}

ir::Result<std::vector<StressRow>> run_stress_case(const std::string& id,
                                                   const StressOptions& options) {
  for (const stress::StressCase& c : stress::all_cases())
    if (c.id == id) {
      std::vector<StressRow> rows = c.run(options);
      for (StressRow& r : rows) judge_stress_row(r);
      return rows;
    }
  return ir::fail(id, "usage", fmt::format("no stress case '{}'", id));
}

std::vector<StressRow> run_stress_catalogue(const StressOptions& options) {
  std::vector<StressRow> rows;
  const std::vector<stress::StressCase> cases = stress::all_cases();
  for (size_t i = 0; i < cases.size(); ++i) {
    if (options.progress) options.progress(cases[i].id, i, cases.size());
    for (StressRow& r : cases[i].run(options)) {
      judge_stress_row(r);
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

} // namespace tierlift::effects
