// The flow-control rules of shader models 2.0 to 3.0 (NUMERICS.md "Flow control"), written
// once for the interpreter (runtime/devices/cpu/src/vm/vm_flow.cpp) and the code generator
// (codegen/src/emit_flow.cpp): the legal ranges a loop's integer constant is clamped to, the
// per-invocation iteration budget that keeps any program finite, and the comparisons of
// if_comp, break_comp and setp_comp as a template over the numeric back ends of
// numeric_rules.h.
#pragma once

#include <cstdint>
#include <optional>

#include "tierlift/ir/opcodes.h"

namespace tierlift::ir::flow {

// loop aL, i#: i#.x iterations, aL starts at i#.y and steps by i#.z; rep i#: i#.x
// iterations. Direct3D 9 defines the integer constants only within these ranges (the
// defi/loop pages of the assembly reference): the iteration count and the start 0..255,
// the step −128..127. Both devices clamp a constant from the bank to them.
inline constexpr int32_t kMinCount = 0, kMaxCount = 255;
inline constexpr int32_t kMinStart = 0, kMaxStart = 255;
inline constexpr int32_t kMinStep = -128, kMaxStep = 127;

// The loop work of one invocation is budgeted in units: reaching a loop or rep costs
// kEntryCost (its first test and its leaving), each completed iteration (reaching
// endloop/endrep) one more; break costs nothing. A loop starts an iteration only while its
// own count remains and the units spent so far, this test's included, are at most
// kIterationBudget; once they are not, every loop leaves at its next test and the code
// after it runs as usual. Why these numbers: no legal program comes near them
// (D3DCAPS9's MaxVShaderInstructionsExecuted / MaxPShaderInstructionsExecuted are at least
// 65535 for shader model 3), and lavapipe ends any loop by itself after 65535 loop
// iterations of a SIMD group, counting about two more per loop reached (llvmpipe's loop
// limiter): a budget that costs as much and stops first is the one both devices can keep.
inline constexpr uint32_t kIterationBudget = 65000;
inline constexpr uint32_t kEntryCost = 2;

// The comparison of if_comp / break_comp / setp_comp (bytecode control field 1..6).
enum class Comparison : uint8_t { Gt = 1, Eq = 2, Ge = 3, Lt = 4, Ne = 5, Le = 6 };

// The comparison an opcode carries, nullopt for every other opcode.
constexpr std::optional<Comparison> comparison_of(Opcode op) {
  auto in = [op](Opcode first) {
    const int d = static_cast<int>(op) - static_cast<int>(first);
    return d >= 0 && d < 6 ? std::optional<Comparison>(static_cast<Comparison>(d + 1))
                           : std::nullopt;
  };
  if (auto c = in(Opcode::BreakGt)) return c;
  if (auto c = in(Opcode::IfGt)) return c;
  return in(Opcode::SetpGt);
}

// x `c` y. gt, ge, lt, le and eq are ordered: a NaN operand makes them false. ne is the
// negation of eq, so a NaN operand makes it true (for any pair exactly one of eq and ne
// holds, as in C and in Direct3D 10). le is ge with the operands swapped. Under
// Rounding::Llvmpipe the back end's compares read denormals as zero (NUMERICS.md rule 13).
template <class A, class V = typename A::V>
typename A::B compare(const A& a, Comparison c, V x, V y) {
  switch (c) {
  case Comparison::Gt: return a.gt(x, y);
  case Comparison::Eq: return a.eq(x, y);
  case Comparison::Ge: return a.ge(x, y);
  case Comparison::Lt: return a.lt(x, y);
  case Comparison::Le: return a.ge(y, x);
  case Comparison::Ne: break;
  }
  return a.lor(a.lor(a.lt(x, y), a.gt(x, y)), a.lor(a.is_nan(x), a.is_nan(y)));
}

} // namespace tierlift::ir::flow
