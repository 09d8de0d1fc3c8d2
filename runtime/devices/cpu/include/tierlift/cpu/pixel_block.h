// The block executor: runs a pixel program over kBlockLanes pixels at once, every register as
// four lane arrays (structure of arrays), so that each instruction is decoded once per block
// and its arithmetic runs as loops over lanes the compiler vectorises. It computes exactly
// what ShaderVM::run_pixel computes lane by lane — bit for bit — because it evaluates every
// numeric rule through the same functions (ir/numerics.h and the VM's operand rules), per
// lane, in the same order; tests/cpu_vm/block_identity_test.cpp holds it to that on every
// listing we have and on random inputs.
//
// It takes straight-line pixel programs: arithmetic (matrix macros excepted), co-issue,
// ps_1_4 phase, and the texture instructions that read a coordinate (tex, texcoord, texkill,
// texld in all its forms, texcrd). Anything else — flow control, the ps_1_1–1_3
// texture-address instructions (texbem, texm3x*, texreg2*, texdp3*), texdepth, relative
// constant reads — makes create() return nullptr and the caller runs ShaderVM::run_pixel.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "tierlift/cpu/shader_vm.h"
#include "tierlift/ir/conventions.h"
#include "tierlift/ir/program.h"

namespace tierlift::cpu {

// One vec4 per lane: c[component][lane].
struct alignas(64) LaneVec4 {
  Lanes c[4];
};

// The pixel stage's inputs for lanes 0..count−1, as PixelInput holds them for one pixel.
// Only the registers color_reads()/tex_reads() name need to be filled.
struct PixelBlockInput {
  int count = 0;
  LaneVec4 color[2]; // v0, v1 (the executor saturates them, as run_pixel does)
  LaneVec4 tex[8];   // TC(0..7)
};

struct PixelBlockOutput {
  // oC0; ps_1_x: r0. The register itself in the Scratch the run used, not a copy (1 KB a
  // block): valid until that Scratch runs again.
  const LaneVec4* color = nullptr;
  std::array<bool, kBlockLanes> discarded{}; // texkill
};

class PixelBlockVM {
public:
  // nullptr when the program has an instruction the block path does not run (see the top of
  // the file) or the VM refuses it. `constants` is read once here: the block executor folds
  // every constant operand (clamped, swizzled, modified) into lane arrays. `coords_2d`: the
  // texture unit it will run with reads only u and v of a texld coordinate (BoundTextures),
  // so tex_components() may leave the other two out.
  static std::unique_ptr<PixelBlockVM> create(const ir::Program& program,
                                              const ir::Conventions& conventions,
                                              const ConstantBank& constants,
                                              bool coords_2d = false);
  ~PixelBlockVM();
  PixelBlockVM(const PixelBlockVM&) = delete;
  PixelBlockVM& operator=(const PixelBlockVM&) = delete;

  // Bit n: v(n) / TC(n) is read by the program (the other inputs may be left unset).
  uint8_t color_reads() const;
  uint8_t tex_reads() const;
  // Bits 4r..4r+3: the components of TC(r) that can reach the output (the others may be left
  // unset in PixelBlockInput).
  uint32_t tex_components() const;

  // Per-thread working memory (the register file of one block).
  struct Scratch;
  std::unique_ptr<Scratch, void (*)(Scratch*)> make_scratch() const;

  // Thread-safe given one Scratch per thread.
  void run(const PixelBlockInput& in, const TextureUnit& textures, PixelBlockOutput& out,
           Scratch& scratch) const;

  struct Impl;

private:
  explicit PixelBlockVM(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace tierlift::cpu
