// What the block executor's two halves share: the plan made once per program
// (vm_block_plan.cpp) and the lanes it runs over per block (vm_block.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "tierlift/cpu/pixel_block.h"
#include "vm_internal.h"

// The step functions (vm_block.cpp, vm_block_store.h) are inlined into both builds of the
// steps (run_steps, run_steps_avx2), so that each vectorises its lane loops for its own target.
#define TL_INLINE [[gnu::always_inline]] inline

namespace tierlift::cpu {

namespace block {

constexpr int L = kBlockLanes;

enum class BlockOp : uint8_t {
  Skip, // nop, the second half of a co-issued pair (run by the first)
  Arith,
  ArithPair,
  Tex,      // ps_1_1–1_3 tex
  TexCoord, // ps_1_1–1_3 texcoord
  TexKill,
  TexLd14,
  TexCrd,
  TexLd,
  TexLdP,
  TexLdB,
  Phase,
};

// How a source operand reaches the lanes.
enum class SrcWay : uint8_t {
  Reg,     // a register's lane arrays, swizzle applied by choosing arrays
  Folded,  // a constant (or a read-as-zero operand), fetched and modified once per draw
  Neg,     // a register negated after the swizzle
  General, // per lane through vm::modify_src
};

struct BlockSrc {
  SrcWay way = SrcWay::Folded;
  uint16_t slot = 0;
  uint8_t comp[4] = {0, 1, 2, 3};
  int32_t folded = -1;
  // Folded: bit c set when component c never compares equal to zero (a non-zero exponent
  // field), so a product with it needs to test only the other factor (rule::mul_y_nonzero).
  uint8_t nonzero = 0;
  // Folded: bit c set when component c is ±0, so a product with it is +0 whatever the other
  // factor (rule 8): mul stores +0 and mad adds +0 to its addend.
  uint8_t zero = 0;
  // Reads PixelBlockInput::tex[slot − kTexBase] in place of the register: t# that no step
  // writes hold the coordinates unchanged, so the 1 KB copy into the register per block and
  // per coordinate is saved (find_input_reads).
  bool input = false;
  // Folded: no component is a denormal.
  bool no_denormal = false;
};

struct BlockStep {
  const vm::Step* step = nullptr;
  BlockOp op = BlockOp::Skip;
  std::array<BlockSrc, 4> src{};
  // The lane loops write the destination register's masked components themselves, with no
  // copy through Scratch::dst (vm_block_plan.cpp's direct_write says when that is safe).
  bool direct = false;
  // No source can hold a denormal (vm_block_plan.cpp's find_clean_sources): under
  // Denormals::Flush the rules run as Denormals::FlushResults, without flushing operands.
  bool clean = false;
};

struct View {
  const float* c[4];
};

} // namespace block

struct PixelBlockVM::Impl {
  vm::Prepared p;
  std::vector<block::BlockStep> steps;
  std::vector<LaneVec4> folded;
  // Register components that may be read (or returned) before the program writes them: the
  // per-pixel VM starts every register at zero, so these are zeroed per block.
  std::vector<std::pair<uint16_t, uint8_t>> zero_components;
  uint8_t color_reads = 0, tex_reads = 0;
  uint32_t tex_components = 0; // bits 4r..4r+3: the components of TC(r) that matter
  uint16_t out_slot = 0;
  uint8_t tex_copies = 0; // bit i: TC(i) is copied into t# (some read of it is not `input`)
};

struct PixelBlockVM::Scratch {
  LaneVec4 reg[vm::kSlotCount]{};
  LaneVec4 src[2][4]{}; // sources modified per lane: [pair half][operand]
  LaneVec4 dst[2]{};    // results before the store: [pair half]
  LaneVec4 coord{};     // texture coordinates built per lane
  Lanes zero{}, one{};
  const PixelBlockInput* in = nullptr; // the block being run (BlockSrc::input reads)
};

} // namespace tierlift::cpu
