// Coverage: the names of what a listing uses, counted, for the coverage tests and the
// `tierlift generate` summary.
#include <cctype>
#include <sstream>

#include <fmt/format.h>

#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/generate/generate.h"
#include "tierlift/ir/source_modifiers.h"

namespace tierlift::gen {
namespace {

// "r", "oD", "oPos", "oFog": the register's name without its number.
std::string file_name(ir::RegFile f, uint32_t index) {
  const bool named_by_index = f == ir::RegFile::RastOut || f == ir::RegFile::Misc; // vFace
  std::string n = ir::register_name(f, named_by_index ? index : 0);
  while (!n.empty() && std::isdigit(static_cast<unsigned char>(n.back()))) n.pop_back();
  return n;
}

std::string full_text(const std::string& text) {
  return text.empty() ? ".xyzw" : text;
}

void count_instruction(Coverage& c, const ir::Instruction& ins) {
  ++c.opcodes[std::string(ir::op_info(ins.op).mnemonic)];
  if (ins.mods.sat) ++c.instruction_modifiers["_sat"];
  if (ins.mods.pp) ++c.instruction_modifiers["_pp"];
  if (ins.coissue) ++c.instruction_modifiers["+"];
  if (ins.mods.shift) {
    const int s = ins.mods.shift;
    ++c.instruction_modifiers[fmt::format("_{}{}", s > 0 ? 'x' : 'd', 1 << (s > 0 ? s : -s))];
  }
  if (ins.pred) ++c.instruction_modifiers["(p0)"];
  if (ins.dst) {
    std::string file = file_name(ins.dst->file, ins.dst->index);
    if (ins.dst->rel) file += ins.dst->rel->file == ir::RegFile::Loop ? "[aL]" : "[a0]";
    ++c.register_files[file];
    ++c.write_masks[full_text(ir::mask_text(ins.dst->mask))];
  }
  for (const ir::SrcOperand& s : ins.src) {
    std::string file = file_name(s.file, s.index);
    if (s.rel) file += s.rel->file == ir::RegFile::Loop ? "[aL]" : "[a0]";
    ++c.register_files[file];
    ++c.swizzles[full_text(ir::swizzle_text(s.swizzle))];
    if (s.mod != ir::SrcMod::None) ++c.source_modifiers[std::string(ir::src_mod_info(s.mod).name)];
  }
}

// "dcl_texcoord v", "dcl_position o", "dcl_2d s", "dcl vPos" for a declaration line of the
// listing ("dcl_texcoord1 v0"): the statement and register without their numbers and masks.
void count_declarations(Coverage& c, const std::string& listing) {
  std::istringstream lines(listing);
  for (std::string text; std::getline(lines, text);) {
    std::istringstream words(text);
    std::string statement, reg;
    if (!(words >> statement >> reg) || statement.rfind("dcl", 0) != 0) continue;
    while (std::isdigit(static_cast<unsigned char>(statement.back()))) statement.pop_back();
    reg = reg.substr(0, reg.find_first_of("0123456789."));
    ++c.declarations[statement + " " + reg];
  }
}

std::string line(const char* what, const std::map<std::string, std::size_t>& m) {
  std::string out = fmt::format("{} {}:", what, m.size());
  for (const auto& [name, count] : m) out += " " + name;
  return out + "\n";
}

} // namespace

void Coverage::add(const std::string& listing) {
  assembly::ParseResult r = assembly::parse_text(listing, "generated.asm");
  if (!r.program || !assembly::validate(*r.program, r.diags)) {
    ++invalid;
    return;
  }
  ++listings;
  for (const ir::Instruction& ins : r.program->code) count_instruction(*this, ins);
  count_declarations(*this, listing);
}

std::string Coverage::summary() const {
  return fmt::format("listings {} (invalid {})\n", listings, invalid) + line("opcodes", opcodes) +
         line("source modifiers", source_modifiers) +
         line("instruction modifiers", instruction_modifiers) +
         line("register files", register_files) + line("swizzles", swizzles) +
         line("write masks", write_masks) + line("declarations", declarations);
}

} // namespace tierlift::gen
