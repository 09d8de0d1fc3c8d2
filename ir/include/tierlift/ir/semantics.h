// What an instruction reads and writes, answered from the opcode table's semantic columns.
// The validator (read-before-write, declaration masks), the interpreter (write masks), the
// code generator and the IR passes (liveness, constant reads) all ask here.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/program.h"

namespace tierlift::ir {

// How the lanes a source feeds into the result follow from the destination, when no fixed
// lane set (OpSemantics::src_lanes) says it (the ISA's instruction pages).
enum class LaneRule : uint8_t {
  Written,     // lane i of the source feeds component i of the result (mov, add, frc ...)
  Fixed,       // the lanes in OpSemantics::src_lanes, whatever the mask (dp3, m4x4, texm3x2pad)
  Lit,         // .x/.y/.w feed .y/.z (lit)
  Dst,         // src0 .y/.z, src1 .y/.w (dst)
  Cross,       // each written component reads the two others (crs)
  Normalize,   // xyz always, w when written (nrm)
  FirstOnly,   // src0 per component; the scratch registers src1/src2 are written, not read (sgn)
  Coordinate,  // texld: xy (dcl_2d) or xyz
  CoordinateW, // texldp / texldb: as texld, plus .w (the divisor or the lod bias)
};

// Effects beyond the destination and the listed sources (bit set).
enum Implicit : uint16_t {
  kNoImplicit = 0,
  kReadsTexCoord = 1 << 0,     // ps_1_1..1_3: reads the interpolated TC(m) of its stage m
  kReadsEyeFromRows = 1 << 1,  // texm3x3vspec: eye vector in the .w of TC(m-2), TC(m-1), TC(m)
  kReadsPadRows = 1 << 2,      // texm3x*tex/depth/spec, texm3x3: the pad rows' dot products
  kReadsOperand = 1 << 3,      // texkill tests (ps_1_4, ps_2_0), texdepth divides its operand
  kWritesDepth = 1 << 4,       // texdepth, texm3x2depth replace the fragment depth
  kDiscards = 1 << 5,          // texkill
  kBumpMatrix = 1 << 6,        // bem, texbem, texbeml: the stage's bump-environment matrix
  kWritesLoopCounter = 1 << 7, // loop: aL
  kWritesAddress = 1 << 8,     // mova: a0 (its destination)
};

// The semantic columns of the opcode table (opcode_table.cpp, one entry beside each row).
struct OpSemantics {
  // Rows a matrix macro reads from its second source (m4x4 c0 reads c0..c3); 0 otherwise.
  uint8_t matrix_rows = 0;
  // Components the instruction can write, per profile (frc in vs_1_1 writes .xy only, m3x2
  // .xy, crs .xyz); 0 where the "destination" names a stage or operand, not a result
  // (texm3x*pad, texkill, texdepth, texm3x2depth).
  std::array<uint8_t, kProfileCount> writes{0xF, 0xF, 0xF, 0xF, 0xF, 0xF, 0xF, 0xF, 0xF, 0xF, 0xF};
  LaneRule lanes = LaneRule::Written;
  uint8_t src_lanes = 0; // LaneRule::Fixed: the lanes each vector source reads
  bool samples = false;  // reads a texture (through s#, or stage m in ps_1_x)
  uint16_t implicit = kNoImplicit;
  // ps_1_x texture-matrix products (texm3x2*, texm3x3*): the rows of the product the
  // instruction belongs to (2 or 3; 0 for every other instruction), and whether it is a pad
  // (one of the rows - 1 rows before the last, on consecutive t#) or the final row that
  // completes the product. The validator's ordering rules, the interpreter's pad registers
  // and the code generator read these instead of listing the opcodes.
  uint8_t texm_rows = 0;
  bool texm_pad = false;
};

const OpSemantics& op_semantics(Opcode op);

// Components `op` can write in profile `p` (the writes column).
inline uint8_t op_writes(Opcode op, Profile p) {
  return op_semantics(op).writes[profile_index(p)];
}

// Rows a matrix macro reads from its second source (m4x4 c0 reads c0..c3); 1 for every
// other source and instruction.
uint32_t source_rows(const Instruction& ins, size_t k);

// Components of the destination register the instruction really writes: the mask
// intersected with what the opcode produces in profile `p`. Texture instructions define the
// whole register they name (texcrd only .xyz, .xy with _dw); pads, texkill and the depth
// instructions define nothing readable.
uint8_t written_mask(const Instruction& ins, Profile p);

// Lanes (of the swizzled value) that source `k` feeds into the result, before the swizzle.
// `sampler_dim` is the number of coordinates a ps_2_0 texld reads (2 or 3).
uint8_t source_lanes(const Instruction& ins, size_t k, Profile p, int sampler_dim);

// Components of the *register* that source `k` reads: its lanes mapped through the swizzle
// (scalar operands: their replicate component), plus .w / .z for _dw / _dz.
uint8_t source_read_mask(const Instruction& ins, size_t k, Profile p, int sampler_dim);

// The sampler stage a ps_1_x texture instruction samples is its destination number; ps_2_0
// names s# as a source. True when `ins` samples a texture.
inline bool samples(const Instruction& ins) {
  return op_semantics(ins.op).samples;
}

// Rows of the texm3x2* / texm3x3* product `op` belongs to; 0 outside the family.
inline uint8_t texm_rows(Opcode op) {
  return op_semantics(op).texm_rows;
}
inline bool is_texm_pad(Opcode op) {
  return op_semantics(op).texm_pad;
}
// The last row of a texm3x2* / texm3x3* product (texm3x2tex, texm3x3spec, ...).
inline bool is_texm_final(Opcode op) {
  return texm_rows(op) != 0 && !is_texm_pad(op);
}

inline bool has_implicit(const Instruction& ins, Implicit what) {
  return (op_semantics(ins.op).implicit & what) != 0;
}

} // namespace tierlift::ir
