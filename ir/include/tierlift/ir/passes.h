// Passes over an ir::Program and the structural IR validator. Analyses (fold_defs,
// relative_constant_limit) compute once what the interpreter, the code generator and the run
// planner would otherwise work out on their own; the one transform, zero_constant_products,
// runs in the device pipeline (device_pipeline.h), through run_pass.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string_view>

#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::ir {

// --- structural IR validator ------------------------------------------------------------
// Checks what every pass must preserve, independent of the assembler's profile rules:
// opcodes known and legal in the profile, a destination exactly where the table has one,
// write masks non-empty, enough sources for the row, register indices inside what the
// profile can address (relative constant bases and matrix rows included), defs in a
// constant file. Errors point at the instruction or operand, rule "ir".
Status validate_ir(const Program& program);
// OK when `backend` ("the interpreter", "SPIR-V") can run the program: every program of
// shader models 1 and 2.0; in 2.x and 3.0 all but gradients (dsx, dsy, texldd), texldl,
// predicated flow control or texkill, relative addressing of anything but c# (vs_3_0's
// v[aL], o[aL]) and semantics the 2.0 interface cannot carry (sm3_interface.h): each of
// those gets a positioned "not-supported" error.
Status check_executable(const Program& program, std::string_view backend);

// Runs `pass` over `program`, then validate_ir; a failure names the pass (device_pipeline.h
// runs its steps through it).
Result<Program> run_pass(Program program, std::string_view name,
                         const std::function<void(Program&)>& pass);

// --- fold defs --------------------------------------------------------------------------
// The values `def`, `defi`, `defb` give their registers, the later definition of a register
// winning (the ISA's rule, decided here once).
struct FoldedDefs {
  std::map<uint32_t, ConstDef> floats; // c#
  std::map<uint32_t, ConstDef> ints;   // i#
  std::map<uint32_t, ConstDef> bools;  // b#
  // The winning def of a register, or nullptr when the listing does not define it. The
  // pointer lives as long as this object: asking a temporary is refused at compile time.
  const ConstDef* find(RegFile file, uint32_t index) const&;
  const ConstDef* find(RegFile file, uint32_t index) const&& = delete;
};
FoldedDefs fold_defs(const Program& program);
// The value of c# as a program reads it: its winning def, else bank[index] (the constants a
// device binds); nullopt when neither holds the register.
std::optional<std::array<float, 4>> constant_value(const FoldedDefs& defs, uint32_t index,
                                                   std::span<const std::array<float, 4>> bank);

// --- relative addressing ------------------------------------------------------------------
// The c# a relative read c[a0.x + n] / c[aL + n] can reach. Nothing bounds a0 or aL
// statically, so every register the device offers is reachable: [0, limit), with limit the
// profile's float-constant count, at least 256 in a vertex shader (the devices' count; the
// interpreter and the generated code read (0, 0, 0, 0) outside it).
uint32_t relative_constant_limit(Profile p);

// --- products with a zero constant ------------------------------------------------------
// mul d, a, b / mad d, a, b, c where a or b reads a c# (no relative addressing, no modifier
// but negation) that is ±0 in every component d keeps, after the swizzle: the listing's def,
// else bank[index]. NUMERICS.md rule 8 makes the product +0 whatever the other factor holds,
// so the other factor is replaced by the zero one (mul d, z, z / mad d, z, z, c): the same
// result bit for bit, in every conventions mode, and the other factor's register is no
// longer read. Liveness (dead_instructions) then finds the texture reads that only fed such
// products: the glow's blur passes weight the slots past the last tap by 0 (7 of 32 reads
// per axis at the default 25 taps). Returns how many instructions it rewrote. A device that
// binds `bank` runs it before planning the draw: step 1 of ir::prepare_for_device.
size_t zero_constant_products(Program& program, std::span<const std::array<float, 4>> bank);

} // namespace tierlift::ir
