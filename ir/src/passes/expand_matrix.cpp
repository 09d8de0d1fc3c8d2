// Pass (transform, opt-in): matrix macros as one dot product per row.
#include "tierlift/ir/passes.h"
#include "tierlift/ir/semantics.h"

namespace tierlift::ir {

void expand_matrix_macros(Program& program) {
  std::vector<Instruction> out;
  out.reserve(program.code.size());
  for (const Instruction& ins : program.code) {
    const OpSemantics& sem = op_semantics(ins.op);
    if (sem.matrix_rows == 0 || !ins.dst || ins.src.size() < 2) {
      out.push_back(ins);
      continue;
    }
    // m4xN reads four columns (dp4), m3xN three (dp3).
    const Opcode dot = sem.src_lanes == 0xF ? Opcode::Dp4 : Opcode::Dp3;
    for (uint32_t row = 0; row < sem.matrix_rows; ++row) {
      const auto bit = static_cast<uint8_t>(1u << row);
      if (!(ins.dst->mask & bit)) continue;
      Instruction d = ins;
      d.op = dot;
      d.dst->mask = bit;
      d.src[1].index = ins.src[1].index + row;
      out.push_back(std::move(d));
    }
  }
  program.code = std::move(out);
}

} // namespace tierlift::ir
