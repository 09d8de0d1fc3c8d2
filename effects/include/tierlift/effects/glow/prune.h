// Leaving out what a scene does not need: the glow's plan pruned for the scene at hand, each
// thing left out named with the reason. Every rule is one whose result is provably the same
// (bit for bit in every texture the frame and the glow are made of):
//  - no glow sources (alpha 0 everywhere): extract, downsample and blur would write zeros into
//    textures that start at zero, so none of them runs;
//  - RGBA8 blur passes (ps_2_0 listings: tier dx9) whose taps cannot change any stored value: a
//  pass whose weights sum
//    to S over inputs bounded by B (from this scene's value range, the rounding of every
//    store before it added) writes values below S·B; when S·B is below half a step (1/510,
//    with a margin of 1 % for fp32 arithmetic) each of them stores 0, and ONE/ONE adds 0,
//    so the pass is left out (the next pass of that axis then replaces, as the first did);
//  - blur passes limited (D3D9's scissor rectangle) to where glow sources exist: the box of
//    the scene's pixels with alpha ≠ 0, grown by how far each pass reads (the downsample's
//    block, the taps' reach); outside it every value read is 0 and every value written is 0
//    (prune.cpp, limit_to_sources, gives the margins);
//  - passes whose output nothing reads: walking back from the final frame, a pass is kept
//    when its target is read later (or is the frame);
//  - the SPIR-V pair pruning (unused constants, inputs and outputs of each vertex + pixel
//    pair) happens where every pass is compiled, as before.
// A scene with a non-finite value is not pruned (a NaN or an infinity times a weight of 0
// is not 0).
// A glow whose sources come from a glow image or are fogged (glow_context.h) gets the
// generic rule only: the rules above read the scene image's alpha as the sources.
// Nor is a graph whose frames differ (per-frame constants, or a feedback texture read before
// the frame writes it: the after-image); the caller leaves a moving scene unpruned as well.
#pragma once

#include <string>
#include <vector>

#include "tierlift/effects/glow/glow.h"
#include "tierlift/image/image.h"

namespace tierlift::effects {

struct LeftOut {
  std::string what; // a pass name, or a group ("blur_h.*")
  std::string why;
};

struct PrunedGraph {
  EffectGraph graph;             // what runs
  std::vector<LeftOut> left_out; // whole passes; empty (and `limited` empty): the whole plan
  // Passes that run, but only inside a scissor rectangle (what: "blur_h.* to x a..b, y c..d").
  std::vector<LeftOut> limited;
  // What the tap rule looked at and kept, with the reason (e.g. every tap of an rgba16f
  // blur: the smallest one can still change a stored value in this scene).
  std::vector<LeftOut> kept;
  size_t passes_before = 0;
  bool changed() const { return !left_out.empty() || !limited.empty(); }
};

// `scene` is the scene image the plan runs over (before it is stored in the plan's format).
PrunedGraph prune_glow(const EffectPlan& plan, const img::Image& scene);

// The generic rule alone: passes whose target nothing after them reads and that is not
// `frame`, left out (used by prune_glow; for any graph).
PrunedGraph prune_unread(const EffectGraph& graph, std::string_view frame);

} // namespace tierlift::effects
