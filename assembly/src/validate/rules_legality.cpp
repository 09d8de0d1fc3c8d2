// Is the instruction in the target profile at all (the opcode table's `slots` column), and do
// its operands have the shape the table row asks for (count and OperandKind)?
#include <string>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::OperandKind;
using ir::RegFile;

std::string profiles_with(std::string_view mn) {
  std::string out;
  for (ir::Profile p : ir::kAllProfiles) {
    bool legal = false;
    for (const ir::OpInfo* r : ir::rows_for_mnemonic(mn)) legal = legal || ir::legal_in(*r, p);
    if (!legal) continue;
    if (!out.empty()) out += ", ";
    out += ir::profile_name(p);
  }
  return out.empty() ? "no profile" : out;
}

void report_not_in_profile(Ctx& c, const ir::OpInfo& info, const ir::SourceLoc& loc) {
  std::string where = profiles_with(info.mnemonic);
  bool other_form = false;
  for (const ir::OpInfo* r : ir::rows_for_mnemonic(info.mnemonic))
    other_form = other_form || ir::legal_in(*r, c.target);
  if (other_form)
    c.error(loc, "not-in-profile",
            fmt::format("this form of {} ({} source operand{}) is not available in {}",
                        info.mnemonic, info.num_src, info.num_src == 1 ? "" : "s", c.pname()));
  else
    c.error(
        loc, "not-in-profile",
        fmt::format("{} is not available in {}; it exists in {}", info.mnemonic, c.pname(), where));
}

bool is_data_file(RegFile f) {
  return f == RegFile::Temp || f == RegFile::Input || f == RegFile::Const || f == RegFile::Texture;
}

// The register file an operand kind demands, or nullopt for "any data register".
const char* kind_text(OperandKind k) {
  switch (k) {
  case OperandKind::Sampler: return "a sampler s#";
  case OperandKind::Bool: return "a boolean constant b#";
  case OperandKind::Int: return "an integer constant i#";
  case OperandKind::Label: return "a label l#";
  case OperandKind::LoopReg: return "the loop counter aL";
  case OperandKind::Const: return "a float constant c#";
  case OperandKind::Temp: return "a temporary r#";
  case OperandKind::Predicate: return "the predicate p0";
  default: return "a data register (r#, v#, c# or t#)";
  }
}

bool kind_accepts(OperandKind k, RegFile f) {
  switch (k) {
  case OperandKind::Sampler: return f == RegFile::Sampler;
  // if and callnz take b# or, in 2.x and 3.0, the predicate (if p0.x, callnz l0, !p0.z).
  case OperandKind::Bool: return f == RegFile::ConstBool || f == RegFile::Predicate;
  case OperandKind::Predicate: return f == RegFile::Predicate;
  case OperandKind::Int: return f == RegFile::ConstInt;
  case OperandKind::Label: return f == RegFile::Label;
  case OperandKind::LoopReg: return f == RegFile::Loop;
  case OperandKind::Const: return f == RegFile::Const;
  case OperandKind::Temp: return f == RegFile::Temp;
  // Outputs and a0 in a data position are reported by the register-access rule.
  default:
    return is_data_file(f) || f == RegFile::Addr || f == RegFile::RastOut ||
           f == RegFile::AttrOut || f == RegFile::TexCrdOut || f == RegFile::ColorOut ||
           f == RegFile::DepthOut || f == RegFile::Output || f == RegFile::Misc;
  }
}

void check_operands(Ctx& c, const ir::Instruction& ins) {
  const ir::OpInfo& info = info_of(ins);
  if (ins.src.size() != info.num_src) {
    c.error(ins.loc, "operand-kind",
            fmt::format("{} takes {} source operand{}; this one has {}", info.mnemonic,
                        info.num_src, info.num_src == 1 ? "" : "s", ins.src.size()));
  }
  if (info.has_dst != ins.dst.has_value())
    c.error(ins.loc, "operand-kind",
            fmt::format("{} {} a destination operand", info.mnemonic,
                        info.has_dst ? "needs" : "takes no"));
  for (size_t k = 0; k < ins.src.size() && k < info.num_src; ++k) {
    const ir::SrcOperand& s = ins.src[k];
    if (!kind_accepts(info.src[k], s.file))
      c.error(s.loc, "operand-kind",
              fmt::format("source {} of {} must be {}, not {}", k + 1, info.mnemonic,
                          kind_text(info.src[k]), reg_name(s.file, s.index)));
  }
}

} // namespace

void check_legality(Ctx& c) {
  for (const ir::Instruction& ins : c.prog.code) {
    const ir::OpInfo& info = info_of(ins);
    if (info.cls == ir::OpClass::Decl) {
      c.error(ins.loc, "operand-kind",
              fmt::format("{} is a declaration, not an executable instruction", info.mnemonic));
      continue;
    }
    if (!ir::legal_in(info, c.target)) report_not_in_profile(c, info, ins.loc);
    check_operands(c, ins);
  }
  // Declarations and definitions are rows of the table too.
  for (const ir::Declaration& d : c.prog.decls) {
    const ir::OpInfo& info = ir::op_info(ir::Opcode::Dcl);
    if (!ir::legal_in(info, c.target)) report_not_in_profile(c, info, d.loc);
  }
  for (const ir::ConstDef& d : c.prog.defs) {
    ir::Opcode op = d.file == RegFile::ConstInt    ? ir::Opcode::DefI
                    : d.file == RegFile::ConstBool ? ir::Opcode::DefB
                                                   : ir::Opcode::Def;
    const ir::OpInfo& info = ir::op_info(op);
    if (!ir::legal_in(info, c.target)) report_not_in_profile(c, info, d.loc);
  }
}

} // namespace tierlift::assembly::detail
