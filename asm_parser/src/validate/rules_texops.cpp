// ps_1_1–1_3 texture-address instruction rules (docs/d3d9-rules.md §5.5): the source t(n) comes
// before the destination t(m) (m > n), texm3x2/texm3x3 pads are followed by their final row
// on the next registers with the same source, and a t# read by texbem/texbeml may later be
// read only by another texbem/texbeml.
#include <set>

#include "context.h"

namespace tierlift::as::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

bool is_3x2_final(Opcode op) {
  return op == Opcode::TexM3x2Tex || op == Opcode::TexM3x2Depth;
}
bool is_3x3_final(Opcode op) {
  return op == Opcode::TexM3x3Tex || op == Opcode::TexM3x3 || op == Opcode::TexM3x3Spec ||
         op == Opcode::TexM3x3VSpec;
}

uint32_t dst_index(const ir::Instruction& ins) {
  return ins.dst ? ins.dst->index : 0;
}
bool same_source(const ir::Instruction& a, const ir::Instruction& b) {
  return !a.src.empty() && !b.src.empty() && a.src[0].file == b.src[0].file &&
         a.src[0].index == b.src[0].index;
}
// `row` continues the matrix started by `prev` (`step` registers further, same source).
bool continues(const ir::Instruction& prev, const ir::Instruction& row, uint32_t step) {
  return dst_index(row) == dst_index(prev) + step && same_source(prev, row);
}

void check_m_greater_n(Ctx& c, const ir::Instruction& ins) {
  if (!ins.dst || ins.src.empty() || ins.src[0].file != RegFile::Texture) return;
  if (ins.dst->file != RegFile::Texture) return;
  if (ins.src[0].index >= ins.dst->index)
    c.error(ins.src[0].loc, "texture-op",
            fmt::format("{} t{} reads t{}: the source must be a lower-numbered t# than the "
                        "destination (m > n)",
                        mnemonic(ins), ins.dst->index, ins.src[0].index));
}

void check_matrix_rows(Ctx& c, const std::vector<ir::Instruction>& code, size_t i) {
  const ir::Instruction& ins = code[i];
  auto at = [&](size_t k) -> const ir::Instruction* {
    return k < code.size() ? &code[k] : nullptr;
  };
  const ir::Instruction* prev = i > 0 ? &code[i - 1] : nullptr;
  const ir::Instruction* prev2 = i > 1 ? &code[i - 2] : nullptr;
  const ir::Instruction* next = at(i + 1);
  const ir::Instruction* next2 = at(i + 2);
  uint32_t m = dst_index(ins);
  switch (ins.op) {
  case Opcode::TexM3x2Pad:
    if (!(next && is_3x2_final(next->op) && continues(ins, *next, 1)))
      c.error(ins.loc, "texture-op",
              fmt::format("texm3x2pad t{} must be followed by texm3x2tex or texm3x2depth t{} "
                          "with the same source",
                          m, m + 1));
    break;
  case Opcode::TexM3x2Tex:
  case Opcode::TexM3x2Depth:
    if (!(prev && prev->op == Opcode::TexM3x2Pad && continues(*prev, ins, 1)))
      c.error(ins.loc, "texture-op",
              fmt::format("{} t{} must directly follow texm3x2pad t{} with the same source",
                          mnemonic(ins), m, m == 0 ? 0 : m - 1));
    break;
  case Opcode::TexM3x3Pad: {
    bool first = next && next->op == Opcode::TexM3x3Pad && continues(ins, *next, 1) && next2 &&
                 is_3x3_final(next2->op) && continues(ins, *next2, 2);
    bool second = prev && prev->op == Opcode::TexM3x3Pad && continues(*prev, ins, 1) && next &&
                  is_3x3_final(next->op) && continues(ins, *next, 1);
    if (!first && !second)
      c.error(ins.loc, "texture-op",
              "texm3x3pad comes in pairs on consecutive t#, followed by texm3x3tex, texm3x3, "
              "texm3x3spec or texm3x3vspec on the next t#, all with the same source");
    break;
  }
  case Opcode::TexM3x3Tex:
  case Opcode::TexM3x3:
  case Opcode::TexM3x3Spec:
  case Opcode::TexM3x3VSpec:
    if (!(prev && prev2 && prev->op == Opcode::TexM3x3Pad && prev2->op == Opcode::TexM3x3Pad &&
          continues(*prev2, *prev, 1) && continues(*prev, ins, 1)))
      c.error(ins.loc, "texture-op",
              fmt::format("{} t{} must directly follow texm3x3pad t{} and texm3x3pad t{} with "
                          "the same source",
                          mnemonic(ins), m, m < 2 ? 0 : m - 2, m < 1 ? 0 : m - 1));
    break;
  default: break;
  }
}

void check_bem_reuse(Ctx& c) {
  std::set<uint32_t> bumped;
  for (const ir::Instruction& ins : c.prog.code) {
    bool bem = ins.op == Opcode::TexBem || ins.op == Opcode::TexBemL;
    for (const ir::SrcOperand& s : ins.src) {
      if (s.file != RegFile::Texture) continue;
      if (!bem && bumped.count(s.index))
        c.error(s.loc, "texture-op",
                fmt::format("t{} was read by texbem/texbeml; afterwards only another "
                            "texbem/texbeml may read it",
                            s.index));
    }
    if (bem && !ins.src.empty() && ins.src[0].file == RegFile::Texture)
      bumped.insert(ins.src[0].index);
  }
}

} // namespace

void check_texture_ops(Ctx& c) {
  if (!c.ps11_13()) return;
  const auto& code = c.prog.code;
  for (size_t i = 0; i < code.size(); ++i) {
    if (!is_texture_op(code[i])) continue;
    check_m_greater_n(c, code[i]);
    check_matrix_rows(c, code, i);
  }
  check_bem_reuse(c);
}

} // namespace tierlift::as::detail
