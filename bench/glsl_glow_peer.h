// The peer of the Vulkan glow frame: the same graph (the plan's textures, sizes and formats;
// its passes in order with their taps, weights, samplers and blending) written by hand in
// GLSL, compiled with the glslang library and run on raw Vulkan on the same device
// (lavapipe), one command buffer a frame. It is what the lift must cost no more than.
//
// What a hand-written chain does and ours need not: it samples RGBA8 and RGBA16F textures
// directly (tierlift samples an exact float copy, see runtime/devices/vulkan/src/resident.h), and
// a pass that replaces its target does not load it (loadOp DONT_CARE).
#pragma once

#include <memory>
#include <string>

#include "tierlift/effects/graph/graph.h"
#include "tierlift/image/image.h"

namespace tierlift::bench {

class GlslGlowPeer {
public:
  // Device, textures (the scene uploaded), pipelines. nullptr and *error on failure.
  static std::unique_ptr<GlslGlowPeer> create(const effects::EffectGraph& graph,
                                              const img::Image& scene, std::string* error);
  ~GlslGlowPeer();
  GlslGlowPeer(const GlslGlowPeer&) = delete;
  GlslGlowPeer& operator=(const GlslGlowPeer&) = delete;

  // One frame: every pass recorded into one command buffer, submitted, waited for.
  std::string frame();
  // A texture's contents as floats (RGBA32F graphs only; a sanity check of the peer).
  std::string read(const std::string& texture, img::Image& out);
  std::string device_name() const;

  struct Impl;

private:
  explicit GlslGlowPeer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace tierlift::bench
