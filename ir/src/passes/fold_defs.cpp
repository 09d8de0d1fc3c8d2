// Pass: fold the listing's def / defi / defb statements into one table, the later
// definition of a register winning.
#include "tierlift/ir/passes.h"

namespace tierlift::ir {

const ConstDef* FoldedDefs::find(RegFile file, uint32_t index) const& {
  const std::map<uint32_t, ConstDef>* table = file == RegFile::Const       ? &floats
                                              : file == RegFile::ConstInt  ? &ints
                                              : file == RegFile::ConstBool ? &bools
                                                                           : nullptr;
  if (!table) return nullptr;
  auto it = table->find(index);
  return it == table->end() ? nullptr : &it->second;
}

FoldedDefs fold_defs(const Program& program) {
  FoldedDefs out;
  for (const ConstDef& d : program.defs) {
    switch (d.file) {
    case RegFile::Const: out.floats.insert_or_assign(d.index, d); break;
    case RegFile::ConstInt: out.ints.insert_or_assign(d.index, d); break;
    case RegFile::ConstBool: out.bools.insert_or_assign(d.index, d); break;
    default: break; // validate_ir reports a def of another file
    }
  }
  return out;
}

std::optional<std::array<float, 4>> constant_value(const FoldedDefs& defs, uint32_t index,
                                                   std::span<const std::array<float, 4>> bank) {
  if (const ConstDef* d = defs.find(RegFile::Const, index))
    return std::array<float, 4>{d->f(0), d->f(1), d->f(2), d->f(3)};
  if (index < bank.size()) return bank[index];
  return std::nullopt;
}

} // namespace tierlift::ir
