// An effect graph: named textures and an ordered list of full-screen passes over them.
// Each pass is a legacy vertex + pixel listing (ir::Program) with its constants, the
// textures it samples (by name, with sampler state), the texture it renders into and the
// blend mode. A device runs the passes in order (run_graph.h); images live in a map
// between passes. The graph says nothing about which device runs it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/ir/program.h"
#include "tierlift/pass/pass.h"

namespace tierlift::effects {

struct TextureDesc {
  std::string name;
  uint32_t width = 0, height = 0;
  img::Format format = img::Format::RGBA32F;
  // Inputs are supplied by the caller before the run (e.g. the scene); every other texture
  // starts as zero when a pass first renders into it.
  bool input = false;
};

struct TextureBind {
  uint32_t stage = 0; // sampler stage s# (ps_2_0) / texture stage (ps_1_x)
  std::string texture;
  pass::SamplerState sampler;
};

// What the analytic device computes for a pass. Linear: the pixel is a weighted sum of
// texture reads, and the taps (texture, coordinate scale and offset, weight) are read off
// the pass's own listings and constants (analytic::extract_taps), never from the generator's
// parameters. MaskByAlpha: the one non-linear helper, rgb × alpha of a single read at the
// pass's sample point (glow source extraction); alpha passes through.
enum class AnalyticForm { Linear, MaskByAlpha };

struct PassDesc {
  std::string name; // unique, e.g. "blur_h.1"
  AnalyticForm analytic = AnalyticForm::Linear;
  std::shared_ptr<const ir::Program> vs, ps;
  std::vector<pass::Vec4> vs_constants, ps_constants; // c0, c1, …
  std::vector<TextureBind> textures;
  std::string target;
  pass::BlendMode blend = pass::BlendMode::Replace;
  // Per-frame constants (ramped parameters: run_frames). Frame f (from 0) uses entry
  // min(f, size − 1) in place of vs_constants / ps_constants; empty: the same every frame.
  // The devices never see these tables: the runner hands them at_frame(f), an ordinary pass,
  // so every device honours them the same way.
  std::vector<std::vector<pass::Vec4>> vs_constants_per_frame, ps_constants_per_frame;

  // This pass as frame `frame` (from 0) runs it: the per-frame constants put in place.
  PassDesc at_frame(unsigned frame) const;
};

struct EffectGraph {
  std::vector<TextureDesc> textures;
  std::vector<PassDesc> passes;
  ir::Conventions conventions; // for every pass (subtexel_bits: match the device)

  const TextureDesc* find_texture(std::string_view name) const;
};

// Empty when the graph is well formed; otherwise the first problem: duplicate or unknown
// texture or pass names, a pass without both listings, a pass that reads its own target,
// sizes of 0 or above img::kMaxDimension, a sampler stage bound twice, an input used as a
// target, an empty entry in a per-frame constant table.
std::string check_graph(const EffectGraph& graph);

} // namespace tierlift::effects
