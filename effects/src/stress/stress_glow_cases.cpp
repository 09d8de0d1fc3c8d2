// Stress cases on the glow graph with finite inputs: HDR values, σ at both ends, odd
// downsample sizes, saturation, and profiles whose weights miss their total. Each row's
// expected value is a closed form written beside it (docs/stress.md has the table).
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stress_common.h"

namespace tierlift::effects::stress {
namespace {

using img::Format;

std::string fmt_name(Format f) {
  return std::string(img::format_name(f));
}

// A row with one measured value per way: `probe` reads it from a way's images.
template <typename Probe>
StressRow measured_row(StressRow row, const std::vector<WayImages>& ways, Probe probe) {
  row.error = first_error(ways);
  for (const WayImages& w : ways)
    if (w.error.empty()) row.measured.push_back({w.way, probe(w), {}});
  return row;
}

// The normalised Gaussian taps exp(−k²/2σ²)/Σ over −r..r (σ in texels).
std::vector<double> gauss_taps(double sigma, int r) {
  std::vector<double> w;
  double sum = 0;
  for (int k = -r; k <= r; ++k)
    sum += w.emplace_back(std::exp(-double(k) * k / (2 * sigma * sigma)));
  for (double& x : w) x /= sum;
  return w;
}

// HDR: one source texel of value v at the centre of a 9×9 scene, σ = 1 (7 taps), no
// downsample. The glow's centre is v·w0² (w0 = the centre tap): the blur_h store holds v·w0,
// the blur_v store w0 times that (every other tap reads 0 there).
std::vector<StressRow> hdr(Format f, double v) {
  const double w0 = gauss_taps(1.0, 3)[3];
  std::string id = v > 65504 ? fmt_name(f) == "rgba16f" ? std::string("hdr.overflow.rgba16f")
                                                        : fmt::format("hdr.{:g}.{}", v, fmt_name(f))
                             : fmt::format("hdr.6e4.{}", fmt_name(f));
  StressRow row = stress_row(std::move(id), "hdr", fmt_name(f),
                             fmt::format("glow at the source (source {:g})", v));
  row.has_ideal = true;
  row.ideal = v * w0 * w0;
  if (f == Format::RGBA16F && v > 65504) {
    row.quantity = fmt::format("stored scene texel (source {:g} > 65504)", v);
    row.expected = std::numeric_limits<double>::infinity();
    row.bound = "RGBA16F overflows to +inf at the store (round to nearest)";
    row.note = "see hdr.overflow.rgba16f.spread for how far it spreads";
    return {row};
  }
  row.expected = row.ideal;
  // Two stores round (blur_h, blur_v). A half store rounds toward zero (lavapipe, and the
  // other ways with it): within 2^-10 relative each, 2·2^-10 for both, plus a few 2^-24 from
  // the fp32 products: 2.2·2^-10 covers it. fp32 stores: within 2^-24 each, far below 1e-6.
  row.tolerance = row.expected * (f == Format::RGBA16F   ? 2.2 * std::ldexp(1.0, -10)
                                  : f == Format::RGBA32F ? 1e-6
                                                         : 1.0);
  row.bound = f == Format::RGBA16F ? "v·w0²; two half stores toward zero: ≤ 2.2·2^-10 relative"
                                   : "v·w0²; fp32 stores and products: ≤ 1e-6 relative";
  return {row};
}

std::vector<StressRow> run_hdr(const StressOptions& o, Format f, double v) {
  std::vector<StressRow> rows = hdr(f, v);
  EffectParams p = small_params(9, 9, 1, f, 1.0);
  const PlanResult plan = build_glow(p);
  img::Image scene = uniform_scene(9, 9, 0, 0);
  float* c = scene.at(4, 4);
  c[0] = c[1] = c[2] = float(v);
  c[3] = 1;
  const std::vector<WayImages> ways = run_on_ways(plan, scene, o);
  StressRow& main = rows.front();
  const bool overflow = f == Format::RGBA16F && v > 65504;
  main = measured_row(main, ways, [&](const WayImages& w) {
    return texel_red(w, overflow ? kSceneTexture : kGlowTexture, 4, 4);
  });
  if (overflow) {
    // +inf times every positive tap stays +inf (0 × inf is +0 in D3D9, so the zero padding
    // taps add nothing): the 7×7 footprint of the kernel, and nothing beyond it.
    StressRow spread;
    spread.id = "hdr.overflow.rgba16f.spread";
    spread.regime = "hdr";
    spread.format = fmt_name(f);
    spread.quantity = "glow texels that are +inf";
    spread.expected = 49;
    spread.bound = "(2R+1)² with R = 3 (σ 1): the kernel's footprint";
    spread = measured_row(spread, ways, [&](const WayImages& w) {
      const img::Image& g = w.images.at(std::string(kGlowTexture));
      double n = 0;
      for (size_t i = 0; i < g.rgba.size(); i += 4) n += std::isinf(g.rgba[i]) && g.rgba[i] > 0;
      return n;
    });
    for (StressMeasure& m : spread.measured) {
      const img::Image& g = std::find_if(ways.begin(), ways.end(), [&](const WayImages& w) {
                              return w.way == m.way;
                            })->images.at(std::string(kGlowTexture));
      for (size_t i = 0; i < g.rgba.size(); i += 4) m.mask.push_back(std::isinf(g.rgba[i]) ? 1 : 0);
    }
    rows.push_back(spread);
  }
  return rows;
}

// σ → 0: σ = 0.01 gives taps (0, 1, 0) (e^-5000 is 0 in double): the glow is its sources,
// bit for bit, on a scene with a different value in every texel.
std::vector<StressRow> sigma_tiny(const StressOptions& o) {
  EffectParams p = small_params(6, 5, 1, Format::RGBA32F, 0.01);
  const PlanResult plan = build_glow(p);
  img::Image scene(6, 5, Format::RGBA32F);
  for (uint32_t y = 0; y < 5; ++y)
    for (uint32_t x = 0; x < 6; ++x) {
      float* t = scene.at(x, y);
      t[0] = t[1] = t[2] = float(x * 5 + y + 1) / 37.0f;
      t[3] = (x + y) % 2 ? 1.0f : 0.5f;
    }
  StressRow row =
      stress_row("sigma.tiny", "sigma", "rgba32f", "max |glow − sources| (σ 0.01: taps 0, 1, 0)");
  row.expected = 0;
  row.bound = "one tap of weight 1: exact";
  return {measured_row(row, run_on_ways(plan, scene, o), [](const WayImages& w) {
    const img::Image& g = w.images.at(std::string(kGlowTexture));
    const img::Image& s = w.images.at(std::string(kSourcesTexture));
    double m = 0;
    for (size_t i = 0; i < g.rgba.size(); ++i)
      if (i % 4 != 3) m = std::max(m, std::fabs(double(g.rgba[i]) - s.rgba[i]));
    return m;
  })};
}

// σ at the schema's limit (4096) cut to 2049 taps, the most the blur takes (radius 1024):
// 257 passes per axis summed by ONE/ONE, each store rounding. On a uniform scene of value v
// (clamped reads: every tap reads v) the ideal glow is v; what the devices store follows the
// recurrence y_p = Q(y_{p−1} + v·W_p) per axis (W_p: pass p's weights, Q: the store rule).
// Drift bound: each store moves by at most half a step, so |glow − v| ≤ 2·P·step/2.
std::vector<StressRow> sigma_limit(const StressOptions& o, Format f) {
  constexpr double v = 0.25;
  EffectParams p = small_params(4, 4, 1, f, 4096, kMaxBlurTaps);
  const PlanResult plan = build_glow(p);
  StressRow row = stress_row(fmt::format("sigma.limit.{}", fmt_name(f)), "sigma", fmt_name(f),
                             "glow of a uniform 0.25 (σ 4096, 2049 taps, 257 passes an axis)");
  row.has_ideal = true;
  row.ideal = v;
  // The recurrence over the plan's own float weights, eight a pass.
  const size_t per = kTapsPerBlurPassDx9;
  auto axis = [&](double in) {
    double y = 0;
    for (size_t first = 0; first < shape(plan).taps.size(); first += per) {
      double wsum = 0;
      for (size_t t = first; t < std::min(shape(plan).taps.size(), first + per); ++t)
        wsum += double(float(shape(plan).taps[t].weight));
      y = device_store(f, y + in * wsum);
    }
    return y;
  };
  // The scene is stored in the format first (RGBA8: 64/255).
  row.expected = plan ? axis(axis(device_store(f, v))) : 0;
  const double step = f == Format::RGBA8 ? 1.0 / 255 : std::ldexp(1.0, -12); // at 0.125..0.25
  // The devices sum a pass's eight products in fp32 before the store: a store that lands
  // within ~1e-7 of a rounding boundary may go the other way; allow 4 such flips.
  row.tolerance = 4 * step;
  const double passes = double((shape(plan).taps.size() + per - 1) / per);
  row.bound = fmt::format("recurrence y = Q(y + v·W_p) per pass, ±4 steps; drift bound "
                          "2·{}·step = {:.4g} (a toward-zero store moves up to a step)",
                          passes, 2 * passes * step);
  row = measured_row(row, run_on_ways(plan, uniform_scene(4, 4, float(v), 1), o),
                     [](const WayImages& w) { return texel_red(w, kGlowTexture, 1, 1); });
  row.note = fmt::format("drift from the ideal {:.4g}", std::fabs(row.expected - v));
  if (!plan) row.error = plan.message();
  return {row};
}

// Downsample of 1×1, 1×N and odd sizes with one tap of weight 1 (max_taps 1), so the glow
// is the downsampled sources. A block that runs past the edge reads the edge texel again
// (clamp addressing), so a partial block weighs its edge texels more.
std::vector<StressRow> downsample_sizes(const StressOptions& o) {
  std::vector<StressRow> rows;
  auto one = [&](std::string id, uint32_t w, uint32_t h, unsigned n, const img::Image& scene,
                 uint32_t gx, uint32_t gy, double expected, std::string bound) {
    EffectParams p = small_params(w, h, n, Format::RGBA32F, 1.0, 1);
    const PlanResult plan = build_glow(p);
    StressRow row = stress_row(std::move(id), "downsample", "rgba32f",
                               fmt::format("glow({},{}) of {}x{} at 1/{} (glow {}x{})", gx, gy, w,
                                           h, n, shape(plan).glow_width, shape(plan).glow_height));
    row.expected = expected;
    row.tolerance = 1e-6; // N² fp32 products of weight 1/N² and their ONE/ONE sums
    row.bound = std::move(bound);
    row = measured_row(row, run_on_ways(plan, scene, o),
                       [&](const WayImages& wi) { return texel_red(wi, kGlowTexture, gx, gy); });
    if (!plan) row.error = plan.message();
    rows.push_back(row);
  };
  one("downsample.1x1.d4", 1, 1, 4, uniform_scene(1, 1, 0.75f, 1), 0, 0, 0.75,
      "16 clamped reads of the one texel, 1/16 each: v");
  img::Image ramp(1, 7, Format::RGBA32F);
  for (uint32_t y = 0; y < 7; ++y) {
    float* t = ramp.at(0, y);
    t[0] = t[1] = t[2] = float(y) / 6.0f;
    t[3] = 1;
  }
  one("downsample.1x7.d3.mid", 1, 7, 3, ramp, 0, 1, 4.0 / 6, "rows 3..5 of the ramp y/6: mean 4/6");
  one("downsample.1x7.d3.edge", 1, 7, 3, ramp, 0, 2, 1.0,
      "rows 6, 7, 8 clamp to row 6: 6/6 (not 2/6 as with zeros beyond the edge)");
  img::Image corner = uniform_scene(7, 5, 0, 0);
  float* t = corner.at(6, 4);
  t[0] = t[1] = t[2] = t[3] = 1;
  one("downsample.7x5.d2.corner", 7, 5, 2, corner, 3, 2, 1.0,
      "the corner texel fills its partial 2×2 block four times by clamping: 1 (not 1/4)");
  return rows;
}

// Intensity 1000 on a uniform 0.25 scene (the glow is 0.25·(Σw)² = 0.25): RGBA8 saturates
// every pixel to 1; RGBA16F holds 0.25 + 250 = 250.25 (a half float: 250.25 = 1001·2^-2).
std::vector<StressRow> intensity(const StressOptions& o, Format f) {
  EffectParams p = small_params(4, 4, 1, f, 1.0);
  p.intensity = 1000;
  const PlanResult plan = build_glow(p);
  StressRow row = stress_row(fmt::format("intensity.1000.{}", fmt_name(f)), "saturation",
                             fmt_name(f), "smallest final value (scene 0.25, intensity 1000)");
  row.has_ideal = true;
  row.ideal = 250.25;
  row.expected = f == Format::RGBA8 ? 1.0 : 250.25;
  // RGBA16F: the glow store is within 2^-13 of 0.25, times 1000 is 0.12, then the final
  // store rounds to a multiple of 2^-3 (half ulp 0.0625).
  row.tolerance = f == Format::RGBA8 ? 0 : 0.25;
  row.bound = f == Format::RGBA8 ? "clamp to 1 at the RGBA8 store" : "0.25 + 1000·0.25";
  row.note = f == Format::RGBA8 ? "every pixel saturated: the glow's shape is lost" : "";
  return {measured_row(row, run_on_ways(plan, uniform_scene(4, 4, 0.25f, 1), o),
                       [](const WayImages& w) {
                         const img::Image& g = w.images.at(std::string(kFinalTexture));
                         double m = std::numeric_limits<double>::infinity();
                         for (size_t i = 0; i < g.rgba.size(); i += 4)
                           m = std::min(m, double(g.rgba[i]));
                         return m;
                       })};
}

// Weights that do not sum to the intended total, on a uniform scene of 1: the glow is S²
// (S = the sum of the weights the passes hold) instead of 1.
StressRow weights_row(const StressOptions& o, std::string id, std::string quantity,
                      const std::vector<double>& weights, std::string bound) {
  EffectParams p = small_params(4, 4, 1, Format::RGBA32F, 2.0, unsigned(weights.size()));
  PlanResult plan = build_glow(p);
  if (plan) set_blur_weights(*plan, weights);
  double s = 0;
  for (double w : weights) s += double(float(w));
  StressRow row = stress_row(std::move(id), "weights", "rgba32f", std::move(quantity));
  row.has_ideal = true;
  row.ideal = 1;
  row.expected = s * s;
  row.tolerance = 1e-6; // two axes of 9 fp32 products and sums
  row.bound = std::move(bound);
  row.note = fmt::format("S = {:.6g}: the glow is {:.3g} % {}", s, std::fabs(1 - s * s) * 100,
                         s < 1 ? "darker" : "brighter");
  row = measured_row(row, run_on_ways(plan, uniform_scene(4, 4, 1, 1), o),
                     [](const WayImages& w) { return texel_red(w, kGlowTexture, 1, 1); });
  if (!plan) row.error = plan.message();
  return row;
}

std::vector<StressRow> weights(const StressOptions& o) {
  // DX7: the nine taps of σ 2 as 8-bit constants (a texture factor holds k/255).
  std::vector<double> q;
  for (double w : gauss_taps(2.0, 4)) q.push_back(std::round(w * 255) / 255);
  // The seed's GLSL blur: nine printed weights that sum to 0.98.
  const std::vector<double> seed = {0.05, 0.09, 0.12, 0.15, 0.16, 0.15, 0.12, 0.09, 0.05};
  return {weights_row(o, "weights.dx7-8bit", "glow of a uniform 1, σ 2 weights as k/255", q,
                      "S² with S = Σ round(255·w_k)/255"),
          weights_row(o, "weights.glsl-0.98", "glow of a uniform 1, the seed's 9-tap kernel", seed,
                      "S² with S = 0.98")};
}

} // namespace

std::vector<StressCase> glow_cases() {
  return {
      {"hdr.6e4.rgba16f", [](const StressOptions& o) { return run_hdr(o, Format::RGBA16F, 6e4); }},
      {"hdr.6e4.rgba32f", [](const StressOptions& o) { return run_hdr(o, Format::RGBA32F, 6e4); }},
      {"hdr.overflow.rgba16f",
       [](const StressOptions& o) { return run_hdr(o, Format::RGBA16F, 1e5); }},
      {"sigma.tiny", sigma_tiny},
      {"sigma.limit.rgba8", [](const StressOptions& o) { return sigma_limit(o, Format::RGBA8); }},
      {"sigma.limit.rgba16f",
       [](const StressOptions& o) { return sigma_limit(o, Format::RGBA16F); }},
      {"downsample.sizes", downsample_sizes},
      {"intensity.1000.rgba8", [](const StressOptions& o) { return intensity(o, Format::RGBA8); }},
      {"intensity.1000.rgba16f",
       [](const StressOptions& o) { return intensity(o, Format::RGBA16F); }},
      {"weights", weights},
  };
}

} // namespace tierlift::effects::stress
