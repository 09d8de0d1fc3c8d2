// The glow plan pruned for one scene (prune.h).
#include "tierlift/effects/glow/prune.h"

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
  for (const pass::Vec4& c : p.draw.ps_constants.f)
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
    if (!p.draw.pixel_program || p.draw.pixel_program->profile != ir::Profile::ps_2_0) {
      ++kept;
      result.push_back(std::move(p));
      continue;
    }
    const bool first_of_axis = p.draw.blend == pass::BlendMode::Replace;
    if (s * input_bound < kBelowHalfStep) {
      out.push_back({p.name, fmt::format("its taps sum to {:.3g} and its input is at most {:.3g} "
                                         "in this scene: every value it adds is below half an "
                                         "RGBA8 step and stores 0",
                                         s, input_bound)});
      first_dropped = first_dropped || first_of_axis;
      continue;
    }
    // The first pass kept after a dropped first one replaces, as the first did.
    if (first_dropped && kept == 0) p.draw.blend = pass::BlendMode::Replace;
    ++kept;
    result.push_back(std::move(p));
  }
  passes = std::move(result);
  return total * input_bound + double(kept) * 0.5 / 255;
}

// The float targets: a ONE/ONE sum that may start at 0 changes with any addend of at least
// half the format's smallest step above 0 (binary16: half of 2^-24; fp32: 2^-126, below
// which lavapipe and the interpreter flush), so a tap is left out only when its weight
// times the input bound stays below that. Says why every tap stays (no Gaussian within the
// schema's limits comes near it), or that the rule would drop one and is not applied.
void explain_float_taps(const EffectGraph& graph, img::Format format, double bound,
                        PrunedGraph& r) {
  const bool half = format == img::Format::RGBA16F;
  const double threshold = half ? std::ldexp(1.0, -25) : std::ldexp(1.0, -126);
  double smallest = INFINITY;
  for (const PassDesc& p : graph.passes)
    if (is_blur(p, "blur_h") || is_blur(p, "blur_v")) {
      // A stated kernel (tier dx9c) keeps offsets beside the weights in its constants.
      for (const KernelTap& k : p.kernel)
        for (double w : k.weight)
          if (w != 0) smallest = std::min(smallest, std::abs(w));
      if (p.analytic == AnalyticForm::Kernel) continue;
      for (const pass::Vec4& c : p.draw.ps_constants.f)
        for (float w : c)
          if (w != 0) smallest = std::min(smallest, std::abs(double(w)));
    }
  if (!std::isfinite(smallest)) return; // no weights in constants (tier dx7's vertex colours)
  const double adds = smallest * bound;
  r.kept.push_back(
      {"every blur tap",
       adds >= threshold
           ? fmt::format("in {} a ONE/ONE sum that starts at 0 changes with any addend of at "
                         "least {:.3g}, and this scene's smallest tap adds up to {:.3g} (weight "
                         "{:.3g} × input bound {:.3g}): every tap can change a stored value",
                         img::format_name(format), threshold, adds, smallest, bound)
           : fmt::format("in {} a tap adding at most {:.3g} (below {:.3g}) stores nothing into a "
                         "sum of 0, but float targets keep every tap (the rule is applied to "
                         "rgba8 only)",
                         img::format_name(format), adds, threshold)});
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

// The glow's own graph (the tiers' build_glow): its extract pass reads the scene image and
// nothing else. Other effects (the outline's extract reads the object's mask; radial and
// GLSL graphs) take their sources elsewhere, so the scene-image rules below do not apply;
// nor do they to a glow with a rendering context (glow_context.h): its extract reads a glow
// image (the scene's alpha says nothing about what glows) or a depth texture (fog of a
// colour other than black makes sources where the scene has none).
bool is_glow_graph(const EffectGraph& g) {
  for (const PassDesc& p : g.passes)
    if (p.target == kSourcesTexture)
      return !p.textures.empty() &&
             std::all_of(p.textures.begin(), p.textures.end(),
                         [](const TextureBind& t) { return t.texture == kSceneTexture; });
  return false;
}

// A box of pixels, right and bottom exclusive.
struct Box {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  Box grown(int64_t gx, int64_t gy, int64_t w, int64_t h) const {
    return {std::max<int64_t>(0, x0 - gx), std::max<int64_t>(0, y0 - gy),
            std::min<int64_t>(w, x1 + gx), std::min<int64_t>(h, y1 + gy)};
  }
  int64_t area() const { return (x1 - x0) * (y1 - y0); }
};

// Blur passes (and extract, downsample) drawn only inside the box where their values can be
// non-zero: the box of the scene's pixels with alpha ≠ 0 (outside it extract writes rgb × 0
// = 0 and alpha 0), carried through each pass grown by how far that pass reads. Outside the
// box every texel a pass reads is 0 and every weight is finite, so it would write 0 (RGBA8
// and RGBA16F store 0 exactly; ONE/ONE adds 0) into a texture that starts at 0: the scissor
// changes no stored bit. The margins are generous on purpose (2 pixels at full resolution,
// a block and one texel more per downsample, the taps' reach plus 2 texels per blur axis:
// bilinear neighbours and the half-texel shift); every sampler must clamp (a wrapping one
// would read the far side).
void limit_to_sources(const EffectPlan& plan, const Box& sources, PrunedGraph& r) {
  // (the reasons below read "drawn only in …": r.limited)
  for (const PassDesc& p : r.graph.passes)
    for (const TextureBind& t : p.textures)
      if (p.target != kFinalTexture &&
          (t.stage >= pass::kMaxSamplers ||
           p.draw.textures[t.stage].sampler.address_u != pass::AddressMode::Clamp ||
           p.draw.textures[t.stage].sampler.address_v != pass::AddressMode::Clamp))
        return;
  const TextureDesc* scene = r.graph.find_texture(kSceneTexture);
  if (!scene || plan.glow_width == 0 || plan.downsample == 0) return;
  const int64_t w = scene->width, h = scene->height;
  const int64_t gw = plan.glow_width, gh = plan.glow_height, d = plan.downsample;
  int64_t reach = 0;
  for (const BlurTap& t : plan.taps) reach = std::max<int64_t>(reach, std::abs(t.offset));
  reach += 2;
  const Box full = sources.grown(2, 2, w, h);
  Box small = full;
  if (d > 1) {
    small = {full.x0 / d, full.y0 / d, (full.x1 - 1) / d + 1, (full.y1 - 1) / d + 1};
    small = small.grown(1, 1, gw, gh);
  }
  const Box horizontal = small.grown(reach, 2, gw, gh);
  const Box vertical = horizontal.grown(2, reach, gw, gh);
  struct Rule {
    std::string_view target, group;
    Box box;
    int64_t width, height;
    std::string margin; // how the sources' box grew to reach this pass group's box
  };
  const std::string taps =
      fmt::format("{} texels (the taps' reach of {}, and 2)", reach, reach - 2);
  const Rule rules[] = {
      {kSourcesTexture, "extract", full, w, h, "grown by 2 pixels"},
      {kSmallTexture, "downsample.*", small, gw, gh,
       d > 1 ? fmt::format("grown by 2 pixels, taken to 1/{} resolution and grown by 1 texel", d)
             : std::string("grown by 2 pixels")},
      {kBlurHTexture, "blur_h.*", horizontal, gw, gh,
       fmt::format("carried as for the downsample, then grown by {} along x and 2 along y", taps)},
      {kGlowTexture, "blur_v.*", vertical, gw, gh,
       fmt::format("carried as for blur_h, then grown by {} along y and 2 along x", taps)}};
  for (const Rule& rule : rules) {
    if (rule.box.area() >= rule.width * rule.height) continue; // nothing to save
    bool any = false;
    for (PassDesc& p : r.graph.passes)
      if (p.target == rule.target) {
        p.draw.scissor = pass::ScissorRect{int32_t(rule.box.x0), int32_t(rule.box.y0),
                                           int32_t(rule.box.x1), int32_t(rule.box.y1)};
        any = true;
      }
    if (!any) continue;
    r.limited.push_back(
        {fmt::format("{} to x {}..{}, y {}..{}", rule.group, rule.box.x0, rule.box.x1 - 1,
                     rule.box.y0, rule.box.y1 - 1),
         fmt::format("{:.1f} % of the {}x{} texture not drawn: the glow sources' box (alpha ≠ 0) "
                     "{}; outside it every value read is 0, so every value written is 0, as "
                     "the texture starts",
                     100.0 * double(rule.width * rule.height - rule.box.area()) /
                         double(rule.width * rule.height),
                     rule.width, rule.height, rule.margin)});
  }
}

} // namespace

PrunedGraph prune_glow(const EffectPlan& plan, const img::Image& scene) {
  PrunedGraph r;
  r.graph = plan.graph;
  r.passes_before = plan.graph.passes.size();
  if (varies_between_frames(plan.graph)) return r;
  if (!is_glow_graph(plan.graph)) return prune_unread(plan.graph, kFinalTexture);
  double most = 0; // the largest value of the glow sources (rgb × alpha, and alpha)
  bool any_alpha = false;
  Box box{int64_t{scene.width}, int64_t{scene.height}, 0, 0}; // of the pixels with alpha ≠ 0
  for (size_t i = 0; i + 3 < scene.rgba.size(); i += 4) {
    for (size_t c = 0; c < 4; ++c)
      if (!std::isfinite(scene.rgba[i + c])) return r; // not pruned (prune.h)
    const double a = scene.rgba[i + 3];
    if (a != 0 && scene.width > 0) {
      const int64_t x = int64_t(i / 4 % scene.width), y = int64_t(i / 4 / scene.width);
      box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x + 1),
             std::max(box.y1, y + 1)};
    }
    any_alpha = any_alpha || a != 0;
    // The glow sources are rgb × alpha, and alpha itself passes through extract into the
    // blurred textures: the bound covers all four channels.
    most = std::max({most, a,
                     a * std::max({double(scene.rgba[i]), double(scene.rgba[i + 1]),
                                   double(scene.rgba[i + 2]), 0.0})});
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
    if (std::any_of(passes.begin(), passes.end(), [](const PassDesc& p) {
          return (is_blur(p, "blur_h") || is_blur(p, "blur_v")) &&
                 (!p.draw.pixel_program || p.draw.pixel_program->profile != ir::Profile::ps_2_0);
        }))
      r.kept.push_back({"every blur pass", "its pixel listing is ps.1.x (tiers dx8, dx7), whose "
                                           "registers round on their own, or ps_3_0 (tier "
                                           "dx9c): the half-step bound is proven for ps_2_0 "
                                           "arithmetic only"});
  } else {
    explain_float_taps(r.graph, plan.graph.textures.front().format, most, r);
  }
  limit_to_sources(plan, box, r);
  PrunedGraph unread = prune_unread(r.graph, kFinalTexture);
  r.graph = std::move(unread.graph);
  r.left_out.insert(r.left_out.end(), unread.left_out.begin(), unread.left_out.end());
  return r;
}

} // namespace tierlift::effects
