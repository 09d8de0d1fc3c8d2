// The state of one listing being generated: its declarations and definitions, the body
// accepted so far, and the validator as the judge of every proposed instruction.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "rng.h"
#include "tierlift/generate/generate.h"
#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/program.h"

namespace tierlift::gen::detail {

// Constants the prelude defines (and the bank ones it leaves to the device).
inline constexpr uint32_t kSinCosConst = 6; // c6, c7: sincos's constants (vs_2_0, ps_2_0)
inline constexpr uint32_t kBankConst = 8;   // c8..: set by the device, not defined
inline constexpr uint32_t kRepCounter = 0;  // i0: rep count
inline constexpr uint32_t kLoopCounter = 1; // i1: loop count, start, step
// r# the generator uses: 8 up to 2.0; the 2.x and 3.0 profiles have 12 or more, and use 12.
constexpr uint32_t generated_temps(ir::Profile p) {
  return ir::is_sm2x(p) || ir::is_sm3(p) ? 12 : 8;
}
inline constexpr uint32_t kPixel30Inputs = 4; // ps_3_0: v0..v3, each with a drawn semantic
// vs_3_0: the o# declarations (o0 the position; finish() keeps the ones written).
inline constexpr std::array<std::pair<ir::DeclUsage, uint8_t>, 5> kVertex30Outputs = {{
    {ir::DeclUsage::Position, 0},
    {ir::DeclUsage::Color, 0},
    {ir::DeclUsage::Color, 1},
    {ir::DeclUsage::TexCoord, 0},
    {ir::DeclUsage::TexCoord, 1},
}};

ir::SrcOperand src_reg(ir::RegFile f, uint32_t index, uint8_t swizzle = ir::kIdentitySwizzle,
                       ir::SrcMod mod = ir::SrcMod::None);
ir::DstOperand dst_reg(ir::RegFile f, uint32_t index, uint8_t mask = ir::kFullMask);
ir::Instruction make(ir::Opcode op, std::optional<ir::DstOperand> dst,
                     std::vector<ir::SrcOperand> src = {});

// The statement that closes a block opened by `opener` (endif, endrep, endloop).
ir::Opcode closer(ir::Opcode opener);

class Builder {
public:
  Builder(ir::Profile profile, const GenerateOptions& options, std::uint64_t seed);

  // Appends `ins` to the body when the program with them (and its tail) validates.
  bool accept(const std::vector<ir::Instruction>& ins);
  // The finished program: body, tail, and only the declarations something reads.
  ir::Program finish() const;

  // Components of a register the body has written so far (temps; t# in ps_1_1..1_3; a0),
  // counting only instructions after the last ps_1_4 phase marker when `this_phase`.
  uint8_t written(ir::RegFile f, uint32_t index, bool this_phase = false) const;
  // Components a source may read now: declared inputs, constants, written registers.
  uint8_t readable(ir::RegFile f, uint32_t index) const;

  ir::Profile profile;
  const GenerateOptions& options;
  Rng rng;
  uint32_t temps;                                     // r# the generator uses (generated_temps)
  std::vector<ir::Opcode> open;                       // open if/if_comp/rep/loop blocks
  std::vector<bool> has_else;                         // per open block
  std::vector<uint32_t> labels;                       // subroutines called so far
  bool want_more_colours = false, want_depth = false; // ps_2_0/2_x/3_0 extra outputs (per listing)
  // ps_1_4: a phase marker will follow (the tail writes one meanwhile), so the instructions
  // proposed now are in phase 1 (bem is legal only there).
  bool pending_phase = false;
  const std::vector<ir::Instruction>& body() const { return body_; }

private:
  ir::Program assemble(const std::vector<ir::Instruction>& extra) const;
  std::vector<ir::Instruction> tail(const std::vector<ir::Instruction>& code) const;
  void prelude();
  void vertex30_declarations();
  void pixel30_inputs();

  ir::Program base_; // profile, decls, defs
  std::vector<ir::Instruction> body_;
};

// Proposes the instructions of one table row (usually one instruction; a flow opener,
// a ps_1_x texture-matrix product or a co-issued pair may give more). Empty when the row
// cannot be used here.
std::vector<ir::Instruction> propose(Builder& b, const ir::OpInfo& row);
// A random readable source of the operand kind (Vector or Scalar), or nullopt.
std::optional<ir::SrcOperand> random_source(Builder& b, ir::OperandKind kind,
                                            const std::vector<ir::RegFile>& files);

// Profile sections (sections.cpp).
void texture_stages_ps11_13(Builder& b);
void texture_section_ps14(Builder& b, bool second_phase);
// `count` instructions proposed from the rows legal in the profile whose class passes.
void instruction_loop(Builder& b, std::size_t count, bool texture_rows, bool arith_rows);

} // namespace tierlift::gen::detail
