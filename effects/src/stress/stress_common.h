// What the stress cases share: running a glow plan over a scene on every way, reading a
// texture back, making small scenes, and the list of cases.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/report/stress.h"

namespace tierlift::effects::stress {

// One way's images after a run (every texture of the graph), or why it failed.
struct WayImages {
  std::string way;
  ImageMap images;
  std::string error;
};

// The plan over `scene` on each way of `options` that has a device (a way without one is
// left out: the Vulkan device may be missing on a machine without Vulkan).
std::vector<WayImages> run_on_ways(const PlanResult& plan, const img::Image& scene,
                                   const StressOptions& options);

// What a device stores for an fp32 value `v` in format f: RGBA8 rounds to nearest of 255
// steps (ties aside), RGBA16F rounds toward zero as lavapipe does (and the interpreter and
// the analytic model with it: rounding.h), RGBA32F keeps the float.
double device_store(img::Format f, double v);

// A w×h RGBA32F scene of colour (v, v, v) with alpha a everywhere.
img::Image uniform_scene(uint32_t w, uint32_t h, float v, float a);

// Glow parameters for a small scene: tier dx9, one Gaussian (σ, weight 1), half texel on.
EffectParams small_params(uint32_t w, uint32_t h, unsigned downsample, img::Format format,
                          double sigma, unsigned max_taps = 0);

// A row not yet measured: what it is (its id, regime, format and quantity in words); each
// case sets its expected value, bound and measures after.
StressRow stress_row(std::string id, std::string regime, std::string format, std::string quantity);

// The first error among the ways ("" when none), for StressRow::error.
std::string first_error(const std::vector<WayImages>& ways);

// Sets row.error to the first error among the ways and measures, for each way that ran, the
// mask of the texels of `texture` whose red channel `hit` holds (its value: how many).
void measure_masks(StressRow& row, const std::vector<WayImages>& ways, std::string_view texture,
                   const std::function<bool(float)>& hit);

// Texel (x, y)'s red channel of `texture` in a way's images (NaN when missing).
double texel_red(const WayImages& w, std::string_view texture, uint32_t x, uint32_t y);

// Replaces the blur weights of every blur pass with `weights` (one per tap, in the plan's
// tap order; padding taps keep weight 0): what a device that stores its weights otherwise
// (8-bit constants, a printed kernel) runs.
void set_blur_weights(EffectPlan& plan, const std::vector<double>& weights);
// The plan, or an empty one (no taps, size 0) when it failed: a row still describes what
// was asked, and says why it did not run (its error).
const EffectPlan& shape(const PlanResult& plan);

// The stress cases: an id and what runs it (rows not yet judged).
struct StressCase {
  std::string id;
  std::function<std::vector<StressRow>(const StressOptions&)> run;
};
std::vector<StressCase> glow_cases();     // stress_glow_cases.cpp
std::vector<StressCase> extreme_cases();  // stress_extreme_cases.cpp
std::vector<StressCase> feedback_cases(); // stress_feedback.cpp

} // namespace tierlift::effects::stress
