// Rules only shader models 2.x and 3.0 have (docs/d3d9-rules.md §14): predicated
// instructions and p0, setp, the comparison forms of if and break, 3.0's one-source sincos,
// and the optional 2.x features (predication, gradient instructions) checked against the
// caps the listing is validated for.
#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

bool is_setp(Opcode op) {
  return op == Opcode::SetpGt || op == Opcode::SetpEq || op == Opcode::SetpGe ||
         op == Opcode::SetpLt || op == Opcode::SetpNe || op == Opcode::SetpLe;
}
bool compares_two_sources(Opcode op) {
  return (op >= Opcode::BreakGt && op <= Opcode::BreakLe) ||
         (op >= Opcode::IfGt && op <= Opcode::IfLe);
}
bool is_gradient(Opcode op) {
  return op == Opcode::Dsx || op == Opcode::Dsy || op == Opcode::TexLdD;
}

void no_predication(Ctx& c, const ir::SourceLoc& loc, std::string_view what) {
  c.error(loc, "predicate",
          fmt::format("{} needs predication, which these {} caps do not have", what, c.pname()));
}

void check_predicate(Ctx& c, const ir::Instruction& ins) {
  const ir::SrcOperand& p = *ins.pred;
  if (!ir::has_predication(c.target)) {
    c.error(p.loc, "predicate",
            fmt::format("predicated instructions exist in vs_2_x, ps_2_x, vs_3_0 and ps_3_0, not "
                        "in {}",
                        c.pname()));
    return;
  }
  if (!c.caps.predication) no_predication(c, p.loc, "a predicated instruction");
  if (info_of(ins).cls == ir::OpClass::Flow)
    c.error(p.loc, "predicate",
            fmt::format("{} cannot be predicated: Direct3D 9 predicates arithmetic and texture "
                        "instructions only (flow control reads p0 as an operand: if p0.x, "
                        "callnz l#, p0.x, breakp p0.x)",
                        mnemonic(ins)));
  if (p.swizzle != ir::kIdentitySwizzle && !ir::is_replicate(p.swizzle))
    c.error(p.loc, "swizzle",
            fmt::format("the predicate takes one component (.x .y .z .w) or none, not {}",
                        swizzle_name(p.swizzle)));
  if (p.mod != ir::SrcMod::None && p.mod != ir::SrcMod::Not)
    c.error(p.loc, "modifier", "the predicate takes only ! (not)");
}

void check_instruction(Ctx& c, const ir::Instruction& ins) {
  if (ins.pred) check_predicate(c, ins);
  const bool setp = is_setp(ins.op);
  if (setp && !c.caps.predication) no_predication(c, ins.loc, std::string(mnemonic(ins)));
  if (ins.op == Opcode::BreakP && !c.caps.predication) no_predication(c, ins.loc, "breakp");
  if (ins.dst && setp && ins.dst->file != RegFile::Predicate)
    c.error(ins.dst->loc, "operand-kind",
            fmt::format("{} writes the predicate p0, not {}", mnemonic(ins),
                        reg_name(ins.dst->file, ins.dst->index)));
  if (ins.dst && !setp && ins.dst->file == RegFile::Predicate)
    c.error(ins.dst->loc, "register-access",
            fmt::format("p0 is written by setp only, not by {}", mnemonic(ins)));
  const ir::OpInfo& info = info_of(ins);
  for (size_t k = 0; k < ins.src.size() && k < info.num_src; ++k) {
    const ir::SrcOperand& s = ins.src[k];
    const bool reads_p0 =
        info.src[k] == ir::OperandKind::Bool || info.src[k] == ir::OperandKind::Predicate;
    if (s.file == RegFile::Predicate && !reads_p0)
      c.error(s.loc, "register-access",
              "p0 is read only as a predicate: (p0) instr, if p0.x, callnz l#, p0.x, breakp p0.x");
    // if_comp / break_comp compare one component of each source.
    if (compares_two_sources(ins.op) && !ir::is_replicate(s.swizzle))
      c.error(s.loc, "swizzle",
              fmt::format("{} compares single components: source {} needs a replicate swizzle "
                          "(.x .y .z .w), not {}",
                          mnemonic(ins), k + 1, swizzle_name(s.swizzle)));
  }
  if (is_gradient(ins.op) && !c.caps.gradients)
    c.error(ins.loc, "not-in-profile",
            fmt::format("{} is a gradient instruction, which these {} caps do not have",
                        mnemonic(ins), c.pname()));
  if (ins.op == Opcode::SinCos3 && ins.dst && ins.dst->file != RegFile::Temp)
    c.error(ins.dst->loc, "operand-kind",
            fmt::format("the destination of sincos must be a temporary r#, not {}",
                        reg_name(ins.dst->file, ins.dst->index)));
}

} // namespace

void check_later(Ctx& c) {
  for (const ir::Instruction& ins : c.prog.code) check_instruction(c, ins);
}

} // namespace tierlift::assembly::detail
