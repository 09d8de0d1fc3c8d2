// An effect graph: named textures and an ordered list of passes over them. Each pass is a
// draw as every device takes it (pass::Pass: the legacy vertex + pixel listings with their
// constant banks, sampler state, geometry, blend) plus what the graph adds: the textures it
// samples and the ones it renders into, by name. A device runs the passes in order (run_graph.h);
// images live in a map between passes. The graph says nothing about which device runs it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/image/image.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/pass.h"

namespace tierlift::effects {

struct TextureDesc {
  std::string name;
  uint32_t width = 0, height = 0;
  img::Format format = img::Format::RGBA32F;
  // Inputs are supplied by the caller before the run (e.g. the scene); every other texture
  // starts as zero when a pass first renders into it.
  bool input = false;
  // A stencil buffer (8 bits per pixel, starting at zero) instead of a colour texture: a
  // pass names it in PassDesc::stencil; it is never sampled. read_texture returns it as an
  // image whose red channel holds the stencil value (0..255), the other channels 0; `format`
  // is ignored.
  bool stencil = false;
  // A depth buffer (a float per pixel) instead of a colour texture: a pass names it in
  // PassDesc::depth; it is never sampled. It starts at `contents`' red channel when the graph
  // carries one (a depth image given to `tierlift run --depth-in`), else at `depth_clear`
  // (D3D9's usual clear, 1.0, by default). read_texture returns it as an RGBA32F image whose red
  // channel holds the depth, the other channels 0; `format` is ignored.
  bool depth = false;
  float depth_clear = 1.0f;
  bool attachment() const { return stencil || depth; } // never sampled nor a colour target
  // An input the graph carries itself (a glow image or a depth image a scene named, made
  // when the graph was built): used when the caller gives no image of that name.
  std::shared_ptr<const img::Image> contents{};
};

// A graph texture bound to a sampler stage of a pass's draw, by name. Everything else about
// the stage is the draw's own (PassDesc::draw.textures[stage]: the sampler state, the ps_1_x
// texture-stage state, a cube's or volume's shape and host layers, `texture` then naming the
// first layer): the device that owns the texture puts its image there when it draws, so a
// description holds no image.
struct TextureBind {
  // Sampler stage s# (ps_2_0) / texture stage (ps_1_x); 257 + N: the vertex stage's sN (vs_3_0
  // texldl, pass::is_vertex_sampler), bound to draw.vertex_textures[N].
  uint32_t stage = 0;
  std::string texture;
};

// What the analytic device computes for a pass. Linear: the pixel is a weighted sum of
// texture reads, and the taps (texture, coordinate scale and offset, weight) are read off
// the pass's own listings and constants (analytic::extract_taps), never from the generator's
// parameters. MaskByAlpha: the one non-linear helper, rgb × alpha of a single read at the
// pass's sample point (glow source extraction); alpha passes through.
// Coverage: an object pass — the pixel listing writes constants (mov oC#, c#) to its targets
// and the model computes which pixels the pass's triangles cover (the object's exact
// coverage at the sample points).
// Kernel: a GLSL pass, whose source the model cannot read: the weighted sum of
// PassDesc::kernel's reads.
// MaskByAlphaFogged: MaskByAlpha of the first read, fogged by the second (the depth) with
// D3D's linear fog (glow_context.h): f = saturate(m·(c0·d + c1)) per channel, rgb =
// f·(rgb × alpha) + (1 − f)·c2, alpha passes through; c0..c2 are the pass's own constants
// and m the result scale its profile needs (4 for ps_1_x, whose constants clamp to ±1).
enum class AnalyticForm { Linear, MaskByAlpha, Coverage, Kernel, MaskByAlphaFogged };

// One read of AnalyticForm::Kernel: the texture bound to `stage`, sampled at the pass's sample
// point (pixel_uv of the conventions) plus `offset` (in uv), times `weight` per channel.
struct KernelTap {
  uint32_t stage = 0;
  std::array<double, 2> offset{};
  std::array<double, 4> weight{};
  // The pixel listing adds `offset` (fp32 values) to the quad uv it receives unchanged, in
  // one fp32 add per axis (tier dx9c): the model then computes the coordinate as the devices
  // do. False: the GLSL pass's coordinate, interpolated in double.
  bool pixel_add = false;
};

struct PassDesc {
  std::string name; // unique, e.g. "blur_h.1"
  // The draw itself, as every device takes it (pass::Pass): the listings and their constant
  // banks (c#, i#, b#; the analytic device refuses a pass that sets any i# or b#), each
  // sampler stage's state, the geometry, the blend, scissor, stencil state and front face,
  // and for a GLSL pass its fragment SPIR-V (pixel_spirv; docs/glsl.md: pixel_program is then
  // the pass's ps_2_0 twin, which the CPU device runs in the GLSL's place — the interpreter
  // has no GLSL — and the analytic device evaluates `kernel` instead).
  // An effect's pass has both listings; `tierlift run` (single_pass.h) may leave out either:
  // without a vertex listing the full-screen quad with draw.constant_inputs at every pixel (no
  // vertices then), without a pixel listing D3D9's fixed function passes oD0 to the target
  // (one target, no stencil: what the devices draw so). With a vertex listing and no vertices:
  // the full-screen quad (graph_draw, run_graph.h).
  // What the graph decides stays out of it and the device fills it in when it draws
  // (graph_draw): the images (bound by name: `textures`), the number of colour targets
  // (`more_targets`), the conventions (EffectGraph::conventions).
  pass::Pass draw;
  AnalyticForm analytic = AnalyticForm::Linear;
  std::vector<TextureBind> textures;
  std::string target;
  // Render targets 1..3 (oC1..oC3) beside `target` (oC0); empty: one target. D3D9 MRT: every
  // target has the target's size; the blend mode applies to each.
  std::vector<std::string> more_targets;
  // A stencil texture (TextureDesc::stencil) for draw.depth_stencil; no stencil test when
  // `stencil` is empty (the state must then be disabled). No depth buffer.
  std::string stencil;
  // A depth texture (TextureDesc::depth) for draw.depth_stencil's depth state (ZENABLE,
  // ZWRITEENABLE, ZFUNC); required with that state, refused with it off or beside a stencil.
  std::string depth;
  // A GLSL pass's source file (draw.pixel_spirv holds what it compiled to), and the reads the
  // analytic device evaluates for it (analytic = Kernel).
  std::string glsl_file;
  std::vector<KernelTap> kernel;

  // Per-frame constants (ramped parameters: run_frames). Frame f (from 0) uses entry
  // min(f, size − 1) in place of draw.vs_constants.f / draw.ps_constants.f; empty: the same
  // every frame. The devices never see these tables: the runner hands them at_frame(f), an
  // ordinary pass, so every device honours them the same way.
  std::vector<std::vector<pass::Vec4>> vs_constants_per_frame, ps_constants_per_frame;

  // This pass as frame `frame` (from 0) runs it: the per-frame constants put in place.
  PassDesc at_frame(unsigned frame) const;
  // The draw's own state of the stage `b` (one of `textures`) binds: its sampler state,
  // texture-stage state and shape (std::out_of_range for a number that names no sampler,
  // which check_graph refuses).
  const pass::TextureBinding& binding(const TextureBind& b) const {
    const pass::TextureBinding* found = pass::sampler_binding(draw, b.stage);
    if (!found) throw std::out_of_range("sampler stage out of range");
    return *found;
  }
};

// A pass named `name` drawing `vs` + `ps` into `target`, everything else at its default:
// what every effect builder starts a pass from.
PassDesc listing_pass(std::string name, std::shared_ptr<const ir::Program> vs,
                      std::shared_ptr<const ir::Program> ps, std::string_view target);

// Binds `texture` (sampler state `s`, set on each stage of d.draw) for a pixel listing that reads
// it `reads` times from `stage` on: once on that sampler when one s# serves every read (ps_2_0's
// texld tK, sN), or on stages stage .. stage + reads − 1 when each read samples its own stage
// (`one_stage_per_read`: ps_1_x, where tex tN reads stage N).
void bind_reads(PassDesc& d, uint32_t stage, std::string_view texture, const pass::SamplerState& s,
                unsigned reads, bool one_stage_per_read);

struct EffectGraph {
  std::vector<TextureDesc> textures;
  std::vector<PassDesc> passes;
  ir::Conventions conventions; // for every pass (subtexel_bits: match the device)

  const TextureDesc* find_texture(std::string_view name) const;
};

// Fails (rule "graph", subject "graph") with the first problem of a malformed graph: duplicate or
// unknown texture or pass names, vertices without a vertex listing, a pass without a pixel
// listing that has more than one target, a stencil or GLSL, a pass that reads its own target,
// a draw with what the graph decides itself or no graph device draws (pre-transformed
// vertices, a viewport, a count of colour targets, the scalar executor),
// sizes of 0 or above img::kMaxDimension, a sampler stage bound twice, an input used as a
// target, a target or stencil named twice in a pass, more than 4 targets or targets of
// different sizes, a stencil texture used as a colour texture (or the reverse), a stencil
// state without a stencil texture or out of range (a reference above 255, a depth
// test), a triangle index past the vertices, an empty entry in a per-frame constant table.
ir::Status check_graph(const EffectGraph& graph);

} // namespace tierlift::effects
