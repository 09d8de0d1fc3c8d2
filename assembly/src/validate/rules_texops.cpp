// ps_1_1–1_3 texture-address instruction rules (docs/d3d9-rules.md §5.5): the source t(n) comes
// before the destination t(m) (m > n), texm3x2/texm3x3 pads are followed by their final row
// on the next registers with the same source, and a t# read by texbem/texbeml may later be
// read only by another texbem/texbeml.
#include <set>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

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

// The rows of a texm3x2 / texm3x3 product (the table's texm columns): rows - 1 pads on
// consecutive t# with the same source, then the final row on the next t#.
bool product_at(const std::vector<ir::Instruction>& code, size_t first, uint8_t rows) {
  if (first + rows > code.size()) return false;
  for (size_t k = 0; k < rows; ++k) {
    const ir::Instruction& r = code[first + k];
    const bool last = k + 1 == rows;
    if (ir::texm_rows(r.op) != rows || ir::is_texm_pad(r.op) == last) return false;
    if (k > 0 && !continues(code[first + k - 1], r, 1)) return false;
  }
  return true;
}

void check_matrix_rows(Ctx& c, const std::vector<ir::Instruction>& code, size_t i) {
  const ir::Instruction& ins = code[i];
  const uint8_t rows = ir::texm_rows(ins.op);
  if (rows == 0) return;
  // A pad is row 0..rows-2 of some product, the final row only row rows-1.
  bool placed = false;
  const size_t last_row = rows - 1u;
  for (size_t row = ir::is_texm_pad(ins.op) ? 0 : last_row; row <= last_row && !placed; ++row)
    placed = row <= i && product_at(code, i - row, rows);
  if (placed) return;
  const uint32_t m = dst_index(ins);
  if (rows == 2 && ir::is_texm_pad(ins.op))
    c.error(ins.loc, "texture-op",
            fmt::format("texm3x2pad t{} must be followed by texm3x2tex or texm3x2depth t{} "
                        "with the same source",
                        m, m + 1));
  else if (rows == 2)
    c.error(ins.loc, "texture-op",
            fmt::format("{} t{} must directly follow texm3x2pad t{} with the same source",
                        mnemonic(ins), m, m == 0 ? 0 : m - 1));
  else if (ir::is_texm_pad(ins.op))
    c.error(ins.loc, "texture-op",
            "texm3x3pad comes in pairs on consecutive t#, followed by texm3x3tex, texm3x3, "
            "texm3x3spec or texm3x3vspec on the next t#, all with the same source");
  else
    c.error(ins.loc, "texture-op",
            fmt::format("{} t{} must directly follow texm3x3pad t{} and texm3x3pad t{} with "
                        "the same source",
                        mnemonic(ins), m, m < 2 ? 0 : m - 2, m < 1 ? 0 : m - 1));
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

} // namespace tierlift::assembly::detail
