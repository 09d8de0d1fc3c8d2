// `tierlift report`: the glow swept over the choices a user has (tier, downsample, taps per
// axis, target format, half texel), each configuration run on the interpreter, on Vulkan and
// as analytic math, with its distance to the ideal glow (ideal_glow.h), the agreement of the
// three ways (docs/design.md's targets) and the run time per device (setup apart from
// steady-state frames, as `glow --frames` measures them).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/effects/graph/run_graph.h"
#include "tierlift/effects/report/ideal_glow.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::vulkan {
class Device;
}

namespace tierlift::effects {

// One point of the sweep. taps 0: the whole profile (sample_blur_profile's radius).
struct SweepConfig {
  Tier tier = Tier::Dx9;
  unsigned downsample = 2;
  unsigned taps = 0;
  img::Format format = img::Format::RGBA32F;
  bool half_texel = true;
  bool operator==(const SweepConfig&) const = default;
};
std::string config_label(const SweepConfig& c); // "dx9 ds2 taps25 rgba32f half-texel"

// What to sweep. The lists are crossed; `taps` lists fractions of the whole kernel's radius
// (1 = every tap, 0.5 = the radius halved and so on; never fewer than one tap), since the
// whole kernel has a different number of taps at each downsample factor.
struct SweepSettings {
  std::vector<Tier> tiers;
  std::vector<unsigned> downsamples;
  std::vector<double> taps;
  std::vector<img::Format> formats;
  std::vector<bool> half_texels;
  unsigned frames = 3; // steady-state frames timed per device
  std::vector<std::string> timed = {"cpu", "vulkan", "analytic"}; // devices timed
  bool quick = false;
};
// The whole sweep: every tier, downsample 1..4, radius × {1, ½, ¼}, every format, half texel
// on and off. --quick: every tier, downsample 2 and 4, radius × {1, ½}, rgba8 and rgba32f,
// half texel on, 2 frames timed on cpu and vulkan only.
SweepSettings full_sweep();
SweepSettings quick_sweep();
// The configurations the settings name, the scene's own first (added when the lists leave
// it out), without repeats (two radius fractions giving the same tap count are one point).
// Empty when a list is empty.
std::vector<SweepConfig> sweep_configs(const SweepSettings& s, const EffectParams& scene);

struct DeviceTime {
  std::string device;
  double setup_ms = 0, median_ms = 0, min_ms = 0, max_ms = 0;
  unsigned frames = 0;
};

struct PairResult {
  std::string a, b;
  bool within = false;      // every pass and the frame within design.md's targets
  double frame_max_abs = 0; // of the final frame
};

struct ConfigResult {
  SweepConfig config;
  bool scene_choice = false; // the configuration the scene asked for
  std::string skipped;       // non-empty: not run, and why (e.g. dx8's intensity limit)
  unsigned taps = 0;         // taps per axis actually run
  unsigned passes = 0;       // passes of the graph
  uint32_t glow_width = 0, glow_height = 0;
  IdealError glow, final; // against the ideal, measured on the Vulkan run (else the cpu one)
  std::vector<PairResult> agreement;
  bool all_agree = false;
  std::vector<DeviceTime> times;
  // The plan pruned for this scene (prune.h): how many passes it leaves out and the frame
  // time then (the same device as frame_ms(); equal to it when nothing is left out).
  size_t pruned_left_out = 0;
  size_t pruned_limited = 0; // pass groups drawn only inside the sources' box
  double pruned_frame_ms = 0;
  // The frame time the plot and the Pareto front use: Vulkan's median, else the cpu's.
  double frame_ms() const;
};

struct SweepResult {
  std::vector<ConfigResult> configs;     // the scene's own first
  std::vector<size_t> pareto;            // indices into configs, by frame time
  std::optional<size_t> cheapest_within; // the fastest whose final RMSE is ≤ 1/255
};

// Progress before each configuration: index from 0, count, the configuration.
using SweepProgress = std::function<void(size_t, size_t, const SweepConfig&)>;

// Runs every configuration over the scene image (at the scene's size). `vk` may be null:
// then no Vulkan device runs (and the agreement is that of the others). Errors of a single
// configuration (one the tier cannot build) skip it with the reason; a device failing fails
// the sweep (rule "run"), as does an empty sweep or an image not of the scene's size.
ir::Result<SweepResult> run_sweep(const Scene& scene, const img::Image& image,
                                  const SweepSettings& s, vulkan::Device* vk,
                                  const SweepProgress& progress = {});

// Two final RMSEs the Pareto front counts as equal: within kParetoRelativeTolerance of the
// larger, or within kParetoAbsoluteTolerance (for errors near 0). Far below anything a
// person sees (1/255 = 3.9e-3) and above the run-to-run noise of a sum of squares in double:
// without it a configuration twice as slow stayed on the front for 2e-12 less error.
inline constexpr double kParetoRelativeTolerance = 1e-6;
inline constexpr double kParetoAbsoluteTolerance = 1e-9;
bool same_error(double a, double b);

// Indices of the configurations no other one beats on both frame time and final RMSE
// (ties kept; RMSEs within same_error are ties), ordered by frame time. Skipped
// configurations are left out.
std::vector<size_t> pareto_front(const std::vector<ConfigResult>& configs);

} // namespace tierlift::effects
