// The glow plan pruned for one scene (prune.h).
#include "tierlift/effects/prune.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

namespace tierlift::effects {
namespace {

bool is_blur(const PassDesc& p, std::string_view axis) {
  return p.name.starts_with(axis) && p.name.size() > axis.size() && p.name[axis.size()] == '.';
}

// Half an RGBA8 step, less 1 % for the fp32 arithmetic of the sum (a relative error of a
// few 2^-24 per tap, far below 1 %).
constexpr double kBelowHalfStep = 0.5 / 255 * 0.99;

double weight_sum(const PassDesc& p) {
  double s = 0;
  for (const pass::Vec4& c : p.ps_constants)
    s += std::max({std::abs(double(c[0])), std::abs(double(c[1])), std::abs(double(c[2])),
                   std::abs(double(c[3]))});
  return s;
}

// RGBA8: drops the passes of one axis that store 0 everywhere; returns the largest value
// the axis's target can then hold (its input bound times the weights, plus half a step per
// pass kept for the rounding of each store).
double prune_axis(std::vector<PassDesc>& passes, std::string_view axis, double input_bound,
                  std::vector<LeftOut>& out) {
  double total = 0;
  size_t kept = 0;
  bool first_dropped = false;
  std::vector<PassDesc> result;
  for (PassDesc& p : passes) {
    if (!is_blur(p, axis)) {
      result.push_back(std::move(p));
      continue;
    }
    const double s = weight_sum(p);
    total += s;
    // ps_1_x pixel listings keep their own register precision (the tier dx8 passes): the
    // bound of a rounded store holds for ps_2_0 arithmetic only, so those passes all stay.
    if (!p.ps || p.ps->profile != ir::Profile::ps_2_0) {
      ++kept;
      result.push_back(std::move(p));
      continue;
    }
    const bool first_of_axis = p.blend == pass::BlendMode::Replace;
    if (s * input_bound < kBelowHalfStep) {
      out.push_back({p.name, fmt::format("its taps sum to {:.3g} and its input is at most {:.3g} "
                                         "in this scene: every value it adds is below half an "
                                         "RGBA8 step and stores 0",
                                         s, input_bound)});
      first_dropped = first_dropped || first_of_axis;
      continue;
    }
    // The first pass kept after a dropped first one replaces, as the first did.
    if (first_dropped && kept == 0) p.blend = pass::BlendMode::Replace;
    ++kept;
    result.push_back(std::move(p));
  }
  passes = std::move(result);
  return total * input_bound + double(kept) * 0.5 / 255;
}

} // namespace

PrunedGraph prune_unread(const EffectGraph& graph, std::string_view frame) {
  PrunedGraph r;
  r.graph = graph;
  r.passes_before = graph.passes.size();
  std::set<std::string, std::less<>> read = {std::string(frame)};
  std::vector<bool> keep(graph.passes.size(), false);
  for (size_t i = graph.passes.size(); i-- > 0;) {
    const PassDesc& p = graph.passes[i];
    if (!read.contains(p.target)) continue;
    keep[i] = true;
    for (const TextureBind& t : p.textures) read.insert(t.texture);
  }
  r.graph.passes.clear();
  for (size_t i = 0; i < graph.passes.size(); ++i)
    if (keep[i])
      r.graph.passes.push_back(graph.passes[i]);
    else
      r.left_out.push_back(
          {graph.passes[i].name, fmt::format("nothing after it reads {}", graph.passes[i].target)});
  return r;
}

namespace {

// True when a frame's result depends on more than this scene image: per-frame constants
// (keyframed parameters), or a pass that reads a texture no earlier pass of the frame wrote
// and that is not an input (a feedback loop: last frame's value). Every rule below bounds
// values from the scene alone, so such a graph is not pruned.
bool varies_between_frames(const EffectGraph& g) {
  std::set<std::string, std::less<>> written;
  for (const TextureDesc& t : g.textures)
    if (t.input) written.insert(t.name);
  for (const PassDesc& p : g.passes) {
    if (!p.vs_constants_per_frame.empty() || !p.ps_constants_per_frame.empty()) return true;
    for (const TextureBind& t : p.textures)
      if (!written.contains(t.texture)) return true;
    written.insert(p.target);
    written.insert(p.more_targets.begin(), p.more_targets.end());
  }
  return false;
}

} // namespace

PrunedGraph prune_glow(const GlowPlan& plan, const img::Image& scene) {
  PrunedGraph r;
  r.graph = plan.graph;
  r.passes_before = plan.graph.passes.size();
  if (!plan || varies_between_frames(plan.graph)) return r;
  double most = 0; // the largest rgb × alpha of the scene
  bool any_alpha = false;
  for (size_t i = 0; i + 3 < scene.rgba.size(); i += 4) {
    for (size_t c = 0; c < 4; ++c)
      if (!std::isfinite(scene.rgba[i + c])) return r; // not pruned (prune.h)
    const double a = scene.rgba[i + 3];
    any_alpha = any_alpha || a != 0;
    most = std::max(most, a * std::max({double(scene.rgba[i]), double(scene.rgba[i + 1]),
                                        double(scene.rgba[i + 2]), 0.0}));
  }
  std::vector<PassDesc>& passes = r.graph.passes;
  if (!any_alpha) {
    // Extract would write rgb × 0 = 0 and alpha 0: every texture before the composite stays
    // at the zero it starts at.
    std::erase_if(passes, [&](const PassDesc& p) {
      if (p.target == kFinalTexture) return false;
      r.left_out.push_back({p.name, "the scene has no glow sources (alpha is 0 everywhere): "
                                    "its target stays 0, as it starts"});
      return true;
    });
    return r;
  }
  if (plan.graph.textures.front().format == img::Format::RGBA8) {
    // The scene stored in RGBA8 moves a value by at most half a step; each downsample store
    // (the passes are summed) adds at most half a step more.
    size_t downsample_passes = 0;
    for (const PassDesc& p : passes) downsample_passes += p.target == kSmallTexture;
    const double sources = std::min(1.0, most + 0.5 / 255) + 0.5 / 255;
    const double blur_input = sources + double(downsample_passes) * 0.5 / 255;
    const double horizontal = prune_axis(passes, "blur_h", blur_input, r.left_out);
    prune_axis(passes, "blur_v", std::min(horizontal, 1.0), r.left_out);
  }
  PrunedGraph unread = prune_unread(r.graph, kFinalTexture);
  r.graph = std::move(unread.graph);
  r.left_out.insert(r.left_out.end(), unread.left_out.begin(), unread.left_out.end());
  return r;
}

} // namespace tierlift::effects
