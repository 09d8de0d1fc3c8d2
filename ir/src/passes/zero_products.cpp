// Pass: products with a constant factor that is ±0 where the result is kept (passes.h).
#include "tierlift/ir/numerics.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/registers.h"

namespace tierlift::ir {
namespace {

// Whether source `s` reads ±0 in every component of `mask` (after its swizzle; negation
// keeps a zero a zero, other modifiers are not taken).
bool reads_zero(const SrcOperand& s, uint8_t mask, const FoldedDefs& defs,
                std::span<const std::array<float, 4>> bank) {
  if (s.file != RegFile::Const || s.rel || (s.mod != SrcMod::None && s.mod != SrcMod::Neg))
    return false;
  const auto v = constant_value(defs, s.index, bank);
  if (!v) return false;
  for (uint32_t c = 0; c < 4; ++c)
    if ((mask & (1u << c)) && !numerics::signed_zero((*v)[swizzle_component(s.swizzle, c)]))
      return false;
  return true;
}

} // namespace

size_t zero_constant_products(Program& program, std::span<const std::array<float, 4>> bank) {
  const FoldedDefs defs = fold_defs(program);
  size_t rewritten = 0;
  for (Instruction& ins : program.code) {
    if ((ins.op != Opcode::Mul && ins.op != Opcode::Mad) || !ins.dst || ins.src.size() < 2)
      continue;
    const uint8_t mask = ins.dst->mask;
    for (size_t zero = 0; zero < 2; ++zero) {
      const size_t other = 1 - zero;
      if (!reads_zero(ins.src[zero], mask, defs, bank)) continue;
      if (ins.src[other].file == ins.src[zero].file &&
          ins.src[other].index == ins.src[zero].index && !ins.src[other].rel)
        break; // already reads nothing else
      const SourceLoc loc = ins.src[other].loc;
      ins.src[other] = ins.src[zero];
      ins.src[other].loc = loc;
      ++rewritten;
      break;
    }
  }
  return rewritten;
}

} // namespace tierlift::ir
