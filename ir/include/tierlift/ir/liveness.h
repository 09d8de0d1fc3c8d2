// Liveness passes over a linked vertex/pixel pair, split per side: which inputs a stage's
// live code reads (live_inputs), which outputs nothing downstream consumes (dead_outputs),
// and the instructions whose results nobody reads (dead_instructions). The code generator
// prunes with them and reports what it left out.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "tierlift/ir/program.h"

namespace tierlift::ir {

using RegKey = std::pair<RegFile, uint32_t>;
// Key offset of the interpolated coordinate TC(m) that ps_1_1..1_3 texture instructions
// read implicitly: {Texture, kTexCoordKey + m}, apart from the t# register {Texture, m}.
inline constexpr uint32_t kTexCoordKey = 1000;

struct RegisterReads {
  std::vector<RegKey> regs; // each read with all four components (conservative)
  bool const_relative = false;
};
// The registers an instruction reads: its sources (matrix rows, relative bases) and the
// implicit reads of the table's semantic columns.
RegisterReads registers_read(const Instruction& ins, Profile p);

// Instructions with an effect beyond their destination register (discard, depth, and the
// ps_1_1..1_3 texture-address chain that passes pad rows implicitly).
bool has_side_effect(const Instruction& ins, Profile p);

// Backward liveness per register component over straight-line code (co-issued pairs as one
// unit), from the registers live at the end. With flow control only writes to outputs not
// in `live_out` are dead. Result: one flag per instruction of program.code.
std::vector<bool> dead_instructions(const Program& program, std::map<RegKey, uint8_t> live_out);

// What a pixel program's results are: oC0..oC3 and oDepth, and r0 in ps_1_x (its colour).
std::map<RegKey, uint8_t> pixel_live_out(const Program& ps);

// What the pixel program's live code reads from the vertex stage: {TexCrdOut, n} for
// t# / TC(n), {AttrOut, n} for v#.
std::set<RegKey> live_inputs(const Program& ps, const std::vector<bool>& dead);

// The varyings (oT#, oD#, oFog) a vertex program writes that `consumed` does not name.
std::vector<RegKey> dead_outputs(const Program& vs, const std::set<RegKey>& consumed);

} // namespace tierlift::ir
