// Statement order: def/dcl before code; ps_1_1–1_3 texture instructions before arithmetic;
// ps_1_4 phases (one `phase` at most, texture before arithmetic inside each phase, and what
// each phase may use).
#include <set>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

void check_decls_first(Ctx& c) {
  if (c.prog.code.empty()) return;
  const ir::Instruction* first = &c.prog.code.front();
  for (const ir::Instruction& ins : c.prog.code)
    if (ins.seq < first->seq) first = &ins;
  for (const ir::Declaration& d : c.prog.decls)
    if (d.seq > first->seq)
      c.error(d.loc, "order",
              fmt::format("dcl must come before the first instruction ({} at line {})",
                          mnemonic(*first), first->loc.line));
  for (const ir::ConstDef& d : c.prog.defs) {
    if (d.seq < first->seq) continue;
    const char* name = d.file == RegFile::ConstInt    ? "defi"
                       : d.file == RegFile::ConstBool ? "defb"
                                                      : "def";
    // Shipped listings put a def after their tex instructions (Valve's ps_1_1 files), and a
    // definition holds for the whole shader wherever it stands (docs/d3d9-rules.md §12.8).
    if (c.opt.windows_leniency)
      c.sink.warning(d.loc, "order",
                     fmt::format("{} after the first instruction ({} at line {}): shipped "
                                 "listings do this and it is taken, the constant holds for the "
                                 "whole shader; the documented order puts definitions first "
                                 "(--strict rejects it)",
                                 name, mnemonic(*first), first->loc.line));
    else
      c.error(d.loc, "order",
              fmt::format("{} must come before the first instruction ({} at line {})", name,
                          mnemonic(*first), first->loc.line));
  }
}

// nop costs no slot in ps_1_x and may sit anywhere.
bool counts_as_arith(const ir::Instruction& ins) {
  return is_arith_op(ins) && ins.op != Opcode::Nop;
}

void check_tex_before_arith(Ctx& c) {
  const ir::Instruction* last_arith = nullptr;
  for (const ir::Instruction& ins : c.prog.code) {
    if (ins.op == Opcode::Phase) {
      last_arith = nullptr; // ps_1_4: a new phase starts with its texture block
      continue;
    }
    if (counts_as_arith(ins))
      last_arith = &ins;
    else if (is_texture_op(ins) && last_arith)
      c.error(ins.loc, "order",
              fmt::format("{} requires texture instructions before arithmetic ones{}; this {} "
                          "follows {} at line {}",
                          c.pname(), c.ps14() ? " within each phase" : "", mnemonic(ins),
                          mnemonic(*last_arith), last_arith->loc.line));
  }
}

void check_phases(Ctx& c) {
  const ir::Instruction* phase = nullptr;
  for (const ir::Instruction& ins : c.prog.code)
    if (ins.op == Opcode::Phase) {
      if (phase)
        c.error(ins.loc, "phase",
                fmt::format("ps_1_4 allows one phase instruction; the first is at line {}",
                            phase->loc.line));
      else
        phase = &ins;
    }
  // Without a phase marker the whole shader is phase 2.
  bool phase1 = phase != nullptr;
  std::set<uint32_t> written_this_phase; // r# written by texture instructions of phase 2
  for (const ir::Instruction& ins : c.prog.code) {
    if (ins.op == Opcode::Phase) {
      phase1 = false;
      continue;
    }
    if (phase1) {
      if (ins.op == Opcode::TexLd14 && !ins.src.empty() && ins.src[0].file != RegFile::Texture)
        c.error(ins.src[0].loc, "phase", "texld in phase 1 of ps_1_4 may only read t# coordinates");
      if (ins.op == Opcode::TexDepth)
        c.error(ins.loc, "phase", "texdepth is only allowed in phase 2 of ps_1_4");
      for (const ir::SrcOperand& s : ins.src)
        if (s.file == RegFile::Input)
          c.error(s.loc, "phase",
                  fmt::format("{} is only available in phase 2 of ps_1_4 (after phase)",
                              reg_name(s.file, s.index)));
    } else {
      if (ins.op == Opcode::Bem)
        c.error(ins.loc, "phase", "bem is only allowed in phase 1 of ps_1_4 (before phase)");
      if ((ins.op == Opcode::TexLd14 || ins.op == Opcode::TexCrd) && !ins.src.empty() &&
          ins.src[0].file == RegFile::Temp && written_this_phase.count(ins.src[0].index))
        c.error(ins.src[0].loc, "phase",
                fmt::format("{} was written by a texture instruction of this phase; a texld "
                            "source r# must come from phase 1",
                            reg_name(RegFile::Temp, ins.src[0].index)));
      if (is_texture_op(ins) && ins.dst && ins.dst->file == RegFile::Temp)
        written_this_phase.insert(ins.dst->index);
    }
  }
}

} // namespace

void check_order(Ctx& c) {
  check_decls_first(c);
  if (c.ps1x()) check_tex_before_arith(c);
  if (c.ps14()) check_phases(c);
}

} // namespace tierlift::assembly::detail
