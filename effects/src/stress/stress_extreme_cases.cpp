// Stress cases with non-finite and denormal sources. D3D9 hardware (and tierlift's three
// ways, docs/d3d9-rules.md §8.3) multiply 0 × ∞ and 0 × NaN to +0, so a special texel
// spreads over exactly the taps that reach it with a non-zero weight: the kernel's
// (2R+1)² footprint, and the zero padding taps of a blur pass add nothing.
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stress_common.h"

namespace tierlift::effects::stress {
namespace {

using img::Format;

// NaN, +inf and −inf, one texel each, 9 texels apart in a 27×9 RGBA32F scene, σ 1 (R = 3):
// three 7×7 footprints that do not touch. One row per kind: how many glow texels hold it,
// and where (the masks must be equal on every way).
std::vector<StressRow> non_finite(const StressOptions& o) {
  constexpr uint32_t w = 27, h = 9;
  EffectParams p = small_params(w, h, 1, Format::RGBA32F, 1.0);
  const PlanResult plan = build_glow(p);
  img::Image scene = uniform_scene(w, h, 0, 0);
  const float kinds[3] = {std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()};
  for (int k = 0; k < 3; ++k) {
    float* t = scene.at(uint32_t(4 + 9 * k), 4);
    t[0] = t[1] = t[2] = kinds[k];
    t[3] = 1;
  }
  const std::vector<WayImages> ways = run_on_ways(plan, scene, o);
  const char* names[3] = {"nan", "+inf", "-inf"};
  std::vector<StressRow> rows;
  for (int k = 0; k < 3; ++k) {
    auto is_kind = [&](float v) {
      return k == 0 ? std::isnan(v) : k == 1 ? v == kinds[1] : v == kinds[2];
    };
    StressRow row =
        stress_row(fmt::format("non-finite.{}", names[k]), "non-finite", "rgba32f",
                   fmt::format("glow texels holding {} (one {} source texel)", names[k], names[k]));
    row.expected = 49;
    row.bound = "(2R+1)² = 7² with R = 3: the kernel's footprint (0 × special = 0)";
    measure_masks(row, ways, kGlowTexture, is_kind);
    rows.push_back(std::move(row));
  }
  return rows;
}

// One +inf texel at (8, 8) of a 16×16 RGBA32F scene, σ 1 (R = 3), no downsample, through
// the composite. The glow holds +inf on the (2R+1)² footprint; the composite reads it with
// bilinear filtering at its texel centres (α = 0, exact at a power-of-two size), and the
// filter unit's a + α·(b − a) (NUMERICS.md rule 36) gives NaN wherever the texel itself or
// its right, lower or lower-right neighbour is +inf: the footprint plus a column to its left
// and a row above, (2R+2)² = 64 texels of the final frame. Masks equal on every way.
StressRow infinite_composite(const StressOptions& o) {
  constexpr uint32_t n = 16;
  EffectParams p = small_params(n, n, 1, Format::RGBA32F, 1.0);
  const PlanResult plan = build_glow(p);
  img::Image scene = uniform_scene(n, n, 0, 1);
  float* t = scene.at(8, 8);
  t[0] = t[1] = t[2] = std::numeric_limits<float>::infinity();
  StressRow row =
      stress_row("non-finite.composite", "non-finite", "rgba32f",
                 "final texels holding nan (one +inf scene texel, through the composite)");
  row.expected = 64;
  row.bound = "(2R+2)² = 8²: the filter unit's lerp meets +inf at weight 0 (rule 36)";
  const std::vector<WayImages> ways = run_on_ways(plan, scene, o);
  measure_masks(row, ways, kFinalTexture, [](float v) { return std::isnan(v); });
  return row;
}

// A denormal source through one tap of weight 1 (max_taps 1): the glow is the source.
// RGBA32F: 1e-39 is an fp32 denormal (the smallest normal is 2^-126 ≈ 1.18e-38); lavapipe
// flushes denormals to zero (its LLVM code runs with flush-to-zero), so the Vulkan way may
// store 0 instead: the documented difference (docs/stress.md). RGBA16F: 1e-5 is a half
// denormal (the smallest normal half is 2^-14 ≈ 6.1e-5), stored as the nearest multiple of
// 2^-24; as fp32 it is a normal number, so no device flushes it.
StressRow denormal(const StressOptions& o, Format f) {
  const float v = f == Format::RGBA32F ? 1e-39f : 1e-5f;
  EffectParams p = small_params(3, 3, 1, f, 1.0, 1);
  const PlanResult plan = build_glow(p);
  img::Image scene = uniform_scene(3, 3, 0, 0);
  float* t = scene.at(1, 1);
  t[0] = t[1] = t[2] = v;
  t[3] = 1;
  StressRow row = stress_row(fmt::format("denormal.{}", img::format_name(f)), "denormal",
                             std::string(img::format_name(f)),
                             fmt::format("glow of a {:g} source (one tap of weight 1)", v));
  row.has_ideal = true;
  row.ideal = v;
  // The half store of 1e-5: round(1e-5 · 2^24) · 2^-24 = 168 · 2^-24.
  // RGBA32F: the interpreter does what lavapipe does (NUMERICS.md rule 13: a denormal operand
  // reads as 0), so both store 0; the analytic model's double math keeps the value.
  row.expected = f == Format::RGBA32F ? 0.0 : std::ldexp(std::round(1e-5 * 16777216.0), -24);
  row.tolerance = 0;
  row.bound = f == Format::RGBA32F ? "flush to zero (lavapipe, the interpreter); analytic: v"
                                   : "the half denormal 168·2^-24, exactly";
  if (f == Format::RGBA32F) row.also_expected["analytic"] = double(v);
  const std::vector<WayImages> ways = run_on_ways(plan, scene, o);
  row.error = first_error(ways);
  for (const WayImages& w : ways)
    if (w.error.empty()) row.measured.push_back({w.way, texel_red(w, kGlowTexture, 1, 1), {}});
  for (const StressMeasure& m : row.measured)
    if (m.value == 0 && v != 0)
      row.note += fmt::format("{}{} flushed it to 0", row.note.empty() ? "" : "; ", m.way);
  if (!plan) row.error = plan.message();
  return row;
}

} // namespace

std::vector<StressCase> extreme_cases() {
  return {
      {"non-finite", non_finite},
      {"non-finite.composite",
       [](const StressOptions& o) { return std::vector{infinite_composite(o)}; }},
      {"denormal.rgba32f",
       [](const StressOptions& o) { return std::vector{denormal(o, Format::RGBA32F)}; }},
      {"denormal.rgba16f",
       [](const StressOptions& o) { return std::vector{denormal(o, Format::RGBA16F)}; }},
  };
}

} // namespace tierlift::effects::stress
