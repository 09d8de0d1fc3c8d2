// Operand rules of particular instructions (docs/d3d9-rules.md §5, §6): cnd's r0.a, cmp and matrix
// aliasing, sincos constants, crs/nrm/sgn temps, bem, a0 writers, texture-instruction
// register files, texdepth's r5.
#include <set>

#include "context.h"
#include "registers_util.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

bool same_reg(const ir::DstOperand& d, const ir::SrcOperand& s) {
  return d.file == s.file && d.index == s.index && !s.rel;
}

void check_matrix(Ctx& c, const ir::Instruction& ins) {
  const int rows = ir::op_semantics(info_of(ins).op).matrix_rows;
  if (rows == 0 || ins.src.size() < 2) return;
  const ir::SrcOperand& m = ins.src[1];
  if (m.file != RegFile::Const && m.file != RegFile::Temp)
    c.error(m.loc, "operand-kind",
            fmt::format("the matrix operand of {} must be c# or r#, not {}", mnemonic(ins),
                        reg_name(m.file, m.index)));
  uint32_t n = file_count(c, m.file);
  if (c.vs() && m.file == RegFile::Const) n = 8192; // a device cap: see rules_registers.cpp
  if (!m.rel && n > 0 && m.index < n && m.index + rows > n)
    c.error(m.loc, "register-range",
            fmt::format("{} reads {}..{}: {} has {}..{}", mnemonic(ins), reg_name(m.file, m.index),
                        reg_name(m.file, m.index + rows - 1), c.pname(), reg_name(m.file, 0),
                        reg_name(m.file, n - 1)));
  if (!ins.dst) return;
  const ir::DstOperand& d = *ins.dst;
  if (same_reg(d, ins.src[0]))
    c.error(d.loc, "macro-alias",
            fmt::format("the destination of {} must not be its first source ({})", mnemonic(ins),
                        reg_name(d.file, d.index)));
  if (d.file == m.file && !m.rel && d.index >= m.index && d.index < m.index + rows)
    c.error(d.loc, "macro-alias",
            fmt::format("the destination of {} must not be one of the matrix rows {}..{}",
                        mnemonic(ins), reg_name(m.file, m.index),
                        reg_name(m.file, m.index + rows - 1)));
}

void need_temp_dst(Ctx& c, const ir::Instruction& ins) {
  if (ins.dst && ins.dst->file != RegFile::Temp)
    c.error(ins.dst->loc, "operand-kind",
            fmt::format("the destination of {} must be a temporary r#, not {}", mnemonic(ins),
                        reg_name(ins.dst->file, ins.dst->index)));
}

void not_a_source(Ctx& c, const ir::Instruction& ins, size_t from, size_t to) {
  if (!ins.dst) return;
  for (size_t k = from; k < to && k < ins.src.size(); ++k)
    if (same_reg(*ins.dst, ins.src[k]))
      c.error(ins.dst->loc, "instruction-rule",
              fmt::format("the destination of {} must differ from source {} ({})", mnemonic(ins),
                          k + 1, reg_name(ins.dst->file, ins.dst->index)));
}

void check_arith(Ctx& c, const ir::Instruction& ins) {
  const auto& s = ins.src;
  switch (ins.op) {
  case Opcode::Cnd:
    if (c.ps11_13() && !s.empty() &&
        !(s[0].file == RegFile::Temp && s[0].index == 0 &&
          s[0].swizzle == ir::replicate_swizzle(3) && s[0].mod == ir::SrcMod::None && !s[0].rel))
      c.error(s[0].loc, "instruction-rule",
              fmt::format("cnd in {} compares r0.a: its first source must be r0.a", c.pname()));
    break;
  case Opcode::Cmp:
    if (c.target == ir::Profile::ps_1_2 || c.target == ir::Profile::ps_1_3)
      not_a_source(c, ins, 0, 3);
    break;
  case Opcode::SinCos:
    need_temp_dst(c, ins);
    if (s.size() == 3 && s[1].file == RegFile::Const && s[2].file == RegFile::Const &&
        s[1].index == s[2].index && !s[1].rel && !s[2].rel)
      c.error(s[2].loc, "instruction-rule",
              "sincos needs two different constants (D3DSINCOSCONST1 and D3DSINCOSCONST2)");
    break;
  case Opcode::Crs:
    need_temp_dst(c, ins);
    not_a_source(c, ins, 0, 2);
    break;
  case Opcode::Nrm:
    need_temp_dst(c, ins);
    not_a_source(c, ins, 0, 1);
    break;
  case Opcode::Sgn:
    need_temp_dst(c, ins);
    if (s.size() == 3 && s[1].file == s[2].file && s[1].index == s[2].index)
      c.error(s[2].loc, "instruction-rule", "sgn needs two different scratch temporaries");
    break;
  case Opcode::Mova:
    if (ins.dst && ins.dst->file != RegFile::Addr)
      c.error(ins.dst->loc, "operand-kind", "mova writes a0 only");
    break;
  default: break;
  }
  // Who may write a0: mov in vs_1_1, mova in vs_2_0.
  if (ins.dst && ins.dst->file == RegFile::Addr) {
    if (c.vs11() && ins.op != Opcode::Mov)
      c.error(ins.dst->loc, "instruction-rule", "vs_1_1 writes a0 with mov only");
    if (c.vs2up() && ins.op != Opcode::Mova)
      c.error(ins.dst->loc, "instruction-rule",
              fmt::format("{} writes a0 with mova only (not mov)", c.pname()));
  }
  check_matrix(c, ins);
}

void check_texture(Ctx& c, const ir::Instruction& ins) {
  if (!ins.dst) return;
  const ir::DstOperand& d = *ins.dst;
  if (c.ps11_13()) {
    if (d.file != RegFile::Texture)
      c.error(d.loc, "operand-kind",
              fmt::format("{} in {} writes a texture register t#, not {}", mnemonic(ins), c.pname(),
                          reg_name(d.file, d.index)));
    if (!ins.src.empty() && ins.src[0].file != RegFile::Texture)
      c.error(ins.src[0].loc, "operand-kind",
              fmt::format("{} reads a texture register t#, not {}", mnemonic(ins),
                          reg_name(ins.src[0].file, ins.src[0].index)));
    return;
  }
  if (ins.op == Opcode::TexKill) {
    if (c.ps30() && d.file != RegFile::Temp && d.file != RegFile::Input)
      c.error(d.loc, "operand-kind",
              fmt::format("texkill in ps_3_0 tests r# or v#, not {}", reg_name(d.file, d.index)));
    else if (!c.ps30() && d.file != RegFile::Temp && d.file != RegFile::Texture)
      c.error(d.loc, "operand-kind",
              fmt::format("texkill tests r# or t#, not {}", reg_name(d.file, d.index)));
    return;
  }
  if (ins.op == Opcode::TexDepth) {
    if (!(d.file == RegFile::Temp && d.index == 5))
      c.error(d.loc, "operand-kind", "texdepth works on r5 only");
    return;
  }
  // ps_3_0 may sample straight into a colour output: fxc writes `texld oC0, v0, s0` for a
  // plain copy, and Direct3D 9 runs it (tests/corpus/bgfx). Earlier models take r# only.
  if (!(c.ps30() && ins.dst && ins.dst->file == RegFile::ColorOut)) need_temp_dst(c, ins);
  if (c.sm3()) {
    // 3.0 texture coordinates come from r#, v# or c#.
    const RegFile f = ins.src.empty() ? RegFile::Temp : ins.src[0].file;
    if (f != RegFile::Temp && f != RegFile::Input && f != RegFile::Const)
      c.error(ins.src[0].loc, "operand-kind",
              fmt::format("{} reads coordinates from r#, v# or c#, not {}", mnemonic(ins),
                          reg_name(f, ins.src[0].index)));
  } else if ((c.ps14() || c.ps2up()) && !ins.src.empty() && ins.src[0].file != RegFile::Temp &&
             ins.src[0].file != RegFile::Texture)
    c.error(ins.src[0].loc, "operand-kind",
            fmt::format("{} reads coordinates from t# or r#, not {}", mnemonic(ins),
                        reg_name(ins.src[0].file, ins.src[0].index)));
}

} // namespace

void check_special(Ctx& c) {
  int bems = 0;
  for (const ir::Instruction& ins : c.prog.code) {
    if (is_texture_op(ins))
      check_texture(c, ins);
    else
      check_arith(c, ins);
    if (ins.op == Opcode::Bem && ++bems == 2)
      c.error(ins.loc, "instruction-rule", "bem may be used once per shader; this is the 2nd");
  }
}

} // namespace tierlift::assembly::detail
