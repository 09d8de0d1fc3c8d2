// Executes one ir::Program per vertex or per pixel with Direct3D 9 semantics (docs/d3d9-rules.md
// §5, §7, §8). It knows nothing of rasterisation: the draw model feeds it interpolated
// inputs and a TextureUnit that samples with the bound sampler state.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "tierlift/ir/conventions.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/mip_lod.h"
#include "tierlift/pass/registers.h"

namespace tierlift::cpu {

// The register values of a pass (constants, vertex inputs and outputs, constant pixel
// inputs, texture-stage state) are the device-neutral pass state's (tierlift/pass).
using pass::ConstantBank;
using pass::PixelInput;
using pass::StageState;
using pass::Vec4;
using pass::VertexInput;
using pass::VertexOutput;

// Pixels the block executor (pixel_block.h) runs at once, each register held as four arrays
// of this many lanes (structure of arrays).
inline constexpr int kBlockLanes = 64;
using Lanes = float[kBlockLanes];

// What the VM asks of the device for every texture read. coord holds (u, v, w, q);
// how many components matter is the bound texture's business (2D: u,v). Unbound stages
// return (0, 0, 0, 1) (docs/d3d9-rules.md §10.6).
class TextureUnit {
public:
  virtual ~TextureUnit() = default;
  virtual Vec4 sample(uint32_t stage, const Vec4& coord, float lod_bias) const = 0;
  // A ps_2_0+ read whose level a level of detail chooses (texld, texldp, texldb, texldl,
  // texldd): `lod` says how (NUMERICS.md M4, M5). This default ignores it, as a texture of
  // one level may.
  virtual Vec4 sample_lod(uint32_t stage, const Vec4& coord, const pass::LodInput& lod) const {
    return sample(stage, coord, lod.bias);
  }
  virtual StageState stage_state(uint32_t stage) const {
    (void)stage;
    return {};
  }
  // The block executor's read: lanes 0..n−1 at coordinates (coord[0][l], …, coord[3][l]) with
  // bias[l] (nullptr: 0), results into out[c][l]. Must give exactly what n calls of sample()
  // give; this default makes those calls.
  virtual void sample_block(uint32_t stage, const float* const coord[4], const float* bias, int n,
                            Lanes out[4]) const;
};

struct PixelOutput {
  std::array<Vec4, 4> color{}; // oC0..oC3; ps_1_x: color[0] = r0
  uint8_t color_written = 0;
  std::optional<float> depth;
  bool discarded = false; // texkill
};

// One invocation's record of every instruction it ran (ShaderVM::run_pixel with a trace):
// entry i belongs to instruction i of Program::code. value: the instruction's destination
// register, all four components, after its last run (a0: its integers as floats); hits: how
// many times it ran. Instructions without a destination register keep hits 0.
struct InstructionTrace {
  std::vector<Vec4> value;
  std::vector<uint32_t> hits;
};

// The rule of ShaderVM::create's failures.
inline constexpr std::string_view kVmRule = "vm";

class ShaderVM {
public:
  // The VM for `program`, or why it cannot run it (rule kVmRule, subject "cpu"): a program
  // validate_ir refuses, or one broken past validation (e.g. unmatched flow control). What
  // the library's callers use; nothing fails later, while running.
  static ir::Result<ShaderVM> create(const ir::Program& program,
                                     const ir::Conventions& conventions);
  ~ShaderVM();
  ShaderVM(ShaderVM&&) noexcept;
  ShaderVM& operator=(ShaderVM&&) noexcept;

  const ir::Program& program() const;

  // Thread-safe: all per-invocation state lives on the caller's stack.
  VertexOutput run_vertex(const VertexInput& in, const ConstantBank& constants) const;
  // The same with the vertex stage's samplers (vs_3_0 texldl, vertex texture fetch): stage N
  // of `textures` is the listing's sN, D3D9's D3DVERTEXTEXTURESAMPLER N. Without them every
  // read is (0, 0, 0, 1), as from an unbound sampler.
  VertexOutput run_vertex(const VertexInput& in, const ConstantBank& constants,
                          const TextureUnit& textures) const;
  PixelOutput run_pixel(const PixelInput& in, const ConstantBank& constants,
                        const TextureUnit& textures) const;
  // The same, recording each instruction's destination into `trace` (sized to the program).
  PixelOutput run_pixel(const PixelInput& in, const ConstantBank& constants,
                        const TextureUnit& textures, InstructionTrace& trace) const;

  // Whether the program reads its neighbours (dsx, dsy), so that a draw shades it by quads.
  // run_pixel still runs such a program, the pixel standing in for its own neighbours (every
  // gradient is then x − x: 0, or NaN for an infinity or NaN).
  bool needs_quad() const;
  // Makes the ps_2_0+ texture reads whose lod comes from the coordinate's gradients (texld,
  // texldp, texldb) quad steps, as dsx/dsy: the four lanes meet there, and the read takes
  // the quad's differences from its top-left lane (NUMERICS.md M5). A draw calls it when a
  // stage holds a mip chain read by lod (pass::reads_by_lod).
  void enable_lod_quads();
  // The four pixels of a 2x2 quad, in[0] top-left, in[1] top-right, in[2] bottom-left,
  // in[3] bottom-right, with their gradients taken across the quad (NUMERICS.md rules F8, F9).
  // Every lane runs to its end, helper pixels (outside the primitive) and discarded ones
  // included; the caller stores only the covered lanes that were not discarded.
  // The gradient interface for the texture unit: each dsx/dsy step sees its source operand
  // in all four lanes (vm::Invocation::quad), from which d/dx and d/dy of any value follow.
  void run_quad(const std::array<PixelInput, 4>& in, const ConstantBank& constants,
                const TextureUnit& textures, std::array<PixelOutput, 4>& out) const;
  // The same, recording lane `traced`'s instructions into `trace` (as run_pixel's trace).
  void run_quad(const std::array<PixelInput, 4>& in, const ConstantBank& constants,
                const TextureUnit& textures, std::array<PixelOutput, 4>& out,
                InstructionTrace& trace, int traced) const;

private:
  VertexOutput vertex(const VertexInput& in, const ConstantBank& constants,
                      const TextureUnit* textures) const;
  struct Impl;
  explicit ShaderVM(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace tierlift::cpu
