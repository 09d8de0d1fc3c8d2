// Textures that live on the Vulkan device: a multi-pass effect uploads its inputs once,
// every pass samples earlier passes' targets and renders into its own without a trip
// through host memory, and images come back only when read.
//
//   vulkan::TextureSet set(device);
//   vulkan::TextureId scene = *set.create(1280, 720, img::Format::RGBA8); // zeros until written
//   set.upload(scene, image);                           // stored with RGBA8's store rule
//   vulkan::TextureId glow = *set.create(1280, 720, img::Format::RGBA8);
//   vulkan::StageTextures stages{};
//   stages[0] = scene;                                  // s0 samples `scene`
//   set.draw(pass, stages, glow);                       // no upload, no readback
//   img::Image out = *set.read(glow);                   // RGBA8 values as floats
// (each call returns an ir::Result or ir::Status: check it before using the value).
//
// What a texture is on the device:
//   * Stored in its own format (RGBA8 UNORM, RGBA16F, RGBA32F): a draw renders into it with
//     loadOp LOAD, so blending reads the stored destination exactly as Device::draw does
//     with a host target, and read() returns it as Device::draw reads a target back (RGBA8:
//     k/255; RGBA16F: the half's value).
//   * Sampled as R32G32B32A32_SFLOAT, as Device::draw samples host images: RGBA32F textures
//     directly; RGBA8 and RGBA16F through a float copy made on the device when a pass
//     samples the texture after it changed — exactly k/255.0f and the half's value (RGBA16F:
//     a same-size NEAREST blit; RGBA8: a table lookup in a compute shader, since lavapipe's
//     blit computes k·fl(1/255), one ulp off in 126 of 256 levels). lavapipe filters float
//     textures with exact float weights; that is what keeps the CPU device and lavapipe
//     bit-identical, and a pass drawn here returns the same bits as through Device::draw.
// Layouts and barriers between uses are tracked per texture. Every call waits for its own
// work (no call leaves work in flight), except draws while batching is on: they are
// recorded into one command buffer, with barriers between them, that the next other call
// (or flush) submits and waits for — one submit per frame of an effect instead of one per
// pass. A pass may not sample its own target.
//
// What a draw needs besides commands (SPIR-V, pipeline, descriptor set, framebuffer, vertex
// and uniform buffers) is made once and kept while its textures exist: drawing the same
// pass again (same programs, constants, states, textures) only records it. prepare() makes
// it ahead of the first draw (an effect's setup). Passes without a vertex program, or with a
// stage sampling a host image, are made anew on every draw.
// Nothing throws: every failure is returned as an ir::Result (or ir::Status) whose error is
// about "vulkan", rule kDrawRule (device.h); a failed call changes no texture.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::vulkan {

// A texture of one TextureSet. None (0) is no texture; ids are never reused within a set.
enum class TextureId : uint32_t { None = 0 };

// The texture each sampler reads in TextureSet::draw, by pass::sampler_slot: the pixel
// stage's s# at #, the vertex stage's sN (vs_3_0 texldl) at pass::kMaxSamplers + N. None: the
// pass's own host image for that sampler (pass.textures[s].image, or
// pass.vertex_textures[N].image, uploaded for that draw only, as Device::draw does), or the
// unbound texture (0, 0, 0, 1) when it has none. Sampler state always comes from the pass's
// binding of that sampler.
using StageTextures = std::array<TextureId, pass::kSamplerSlots>;

// What a draw renders into: oC0..oC(n−1) in color[0..n−1] (n = pass.color_targets, every
// one the same size, the rest None) and, for a pass with a stencil test, an 8-bit stencil
// buffer made by create_stencil (None: no stencil buffer); for a pass with a depth state, a
// depth buffer made by create_depth (not both at once yet).
struct RenderTargets {
  std::array<TextureId, 4> color{};
  TextureId stencil = TextureId::None;
  TextureId depth = TextureId::None;
};

// What TextureSet::draw_traced records of one pixel (codegen::TracePixel): entry i belongs to
// instruction i of the pass's pixel program. points: the instructions the module records
// (those storing a register: not flow control, not one the code generator left out as dead);
// value: the destination register after the instruction's last run at the pixel (a0: its
// integers as floats); hits: how many times it ran there (0: never, or no triangle covered
// the pixel).
struct ShaderTrace {
  std::vector<uint32_t> points;
  std::vector<std::array<float, 4>> value;
  std::vector<uint32_t> hits;
};

class TextureSet {
public:
  // `device` must outlive the set. Destroying the set frees every texture.
  explicit TextureSet(Device& device);
  ~TextureSet();
  TextureSet(const TextureSet&) = delete;
  TextureSet& operator=(const TextureSet&) = delete;

  // A new `width` × `height` texture (1..img::kMaxDimension each) stored in `format`, all
  // zero.
  ir::Result<TextureId> create(uint32_t width, uint32_t height, img::Format format);
  // A new `width` × `height` 8-bit stencil buffer, all zero. It cannot be sampled or
  // uploaded; read() returns it as RGBA32F with the stencil value (0..255) in red and zeros
  // elsewhere.
  ir::Result<TextureId> create_stencil(uint32_t width, uint32_t height);
  // A new `width` × `height` depth buffer (D32_SFLOAT), every pixel `clear`. It cannot be
  // sampled; upload() replaces its values with an image's red channel, read() returns it as
  // RGBA32F with the depth in red and zeros elsewhere.
  ir::Result<TextureId> create_depth(uint32_t width, uint32_t height, float clear);
  // Replaces the texture's contents with `image` (same size; stored with the texture's
  // format's store rule whatever image.format says).
  ir::Status upload(TextureId id, const img::Image& image);
  // The texture's contents: width × height in its format.
  ir::Result<img::Image> read(TextureId id);
  // Draws `pass` into `target`, sampling `stages` (see StageTextures). The target's current
  // contents are the destination blending reads. Nothing is read back. The report holds
  // setup_ms and draw_ms (as Device::draw's); the pixel counters stay 0.
  ir::Result<pass::DrawReport> draw(const pass::Pass& pass, const StageTextures& stages,
                                    TextureId target);
  // The same into several render targets and a stencil buffer (MRT, stencil test).
  ir::Result<pass::DrawReport> draw(const pass::Pass& pass, const StageTextures& stages,
                                    const RenderTargets& targets);
  // draw(pass, stages, target) with the pixel program instrumented to record pixel (x, y)
  // (ShaderTrace): made for this draw only (never cached), submitted and waited for. Fails
  // when the device cannot store from a pixel shader (fragmentStoresAndAtomics).
  ir::Result<ShaderTrace> draw_traced(const pass::Pass& pass, const StageTextures& stages,
                                      TextureId target, uint32_t x, uint32_t y);
  // Makes what draw(pass, stages, targets) needs, without drawing.
  ir::Status prepare(const pass::Pass& pass, const StageTextures& stages, TextureId target);
  ir::Status prepare(const pass::Pass& pass, const StageTextures& stages,
                     const RenderTargets& targets);
  // Batching on: draw() records; off: draw() submits and waits (flushing first). A draw's
  // DrawReport::draw_ms is then the recording time; the work is timed by flush().
  ir::Status set_batching(bool on);
  // Program reuse on: each program pair is compiled (and validated) once for any constants,
  // which reach it through the uniform block only (no specialisation for the constants of a
  // draw), and one pipeline serves every draw of it, across clear() too, until the set is
  // destroyed or reuse is turned off. For a caller that draws the same programs on many sets
  // of constants (`tierlift test`'s differential run); the images are the same either way.
  void set_reuse_programs(bool on);
  // The pipelines program reuse holds (0 when it is off).
  size_t reused_pipelines() const;
  // Submits what batched draws recorded and waits for it.
  ir::Status flush();
  // Frees one texture (unknown ids are ignored) or all of them (after a flush).
  void destroy(TextureId id);
  void clear();
  size_t size() const;

  struct State;

private:
  Device& device_;
  std::unique_ptr<State> state_;
};

} // namespace tierlift::vulkan
