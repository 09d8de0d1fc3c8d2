// Internal: the draws a TextureSet keeps between calls. A multi-pass effect draws the same
// passes frame after frame; compiling SPIR-V, creating a pipeline (LLVM on lavapipe), a
// descriptor set and a framebuffer each time cost far more than the draw itself. A prepared
// draw (pass_draw.h) is found again by a key holding everything it was made from, so a hit
// is always the draw a fresh prepare_draw would make.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "pass_draw.h"

namespace tierlift::vulkan {

// The key of drawing `pass` with `textures` (host_target ignored): programs (by identity:
// the entry keeps them alive, so an address cannot be reused while it exists), conventions,
// constants, vertices, viewport, blend, sampler and stage states, the resident textures of
// every stage, the targets and the stencil buffer with its state. nullopt: not cached
// (a pass without a vertex program, or a stage sampling a host image, whose pixels may change
// between draws).
std::optional<std::string> draw_key(const pass::Pass& pass, const DrawTextures& textures);

struct CachedDraw {
  std::shared_ptr<const ir::Program> vs, ps; // keep the keyed addresses alive
  std::shared_ptr<const std::vector<uint32_t>> ps_spirv;
  PreparedDraw draw;
};

class DrawCache {
public:
  // The entry under `key`, nullptr if none.
  PreparedDraw* find(const std::string& key);
  PreparedDraw& insert(const std::string& key, const pass::Pass& pass,
                       std::unique_ptr<CachedDraw> entry);
  // Drops every entry that samples or renders into `r` (before `r` is destroyed).
  void forget(const Resident* r);
  void clear() { entries_.clear(); }
  size_t size() const { return entries_.size(); }

private:
  std::map<std::string, std::unique_ptr<CachedDraw>, std::less<>> entries_;
};

} // namespace tierlift::vulkan
