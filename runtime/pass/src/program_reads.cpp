// Scans a program for the registers the run must supply.
#include "program_reads.h"

#include <algorithm>

#include "tierlift/ir/semantics.h"

namespace tierlift::pass::detail {
namespace {

void add_once(std::vector<RegRead>& list, ir::RegFile f, uint32_t index, ir::SourceLoc loc) {
  bool seen = std::any_of(list.begin(), list.end(),
                          [&](const RegRead& r) { return r.file == f && r.index == index; });
  if (!seen) list.push_back({f, index, loc});
}

} // namespace

std::vector<RegRead> constant_reads(const ir::Program& program, std::vector<RegRead>* relative) {
  std::vector<RegRead> out;
  for (const ir::Instruction& ins : program.code) {
    for (size_t s = 0; s < ins.src.size(); ++s) {
      const ir::SrcOperand& op = ins.src[s];
      if (op.file != ir::RegFile::Const && op.file != ir::RegFile::ConstInt &&
          op.file != ir::RegFile::ConstBool)
        continue;
      if (op.rel) {
        if (relative) add_once(*relative, op.file, op.index, op.loc);
        continue;
      }
      const uint32_t rows = ir::source_rows(ins, s);
      for (uint32_t r = 0; r < rows; ++r) add_once(out, op.file, op.index + r, op.loc);
    }
  }
  return out;
}

std::vector<RegRead> sampler_reads(const ir::Program& program) {
  std::vector<RegRead> out; // a vs_3_0 names its samplers as operands too (texldl)
  for (const ir::Instruction& ins : program.code) {
    for (const ir::SrcOperand& op : ins.src)
      if (op.file == ir::RegFile::Sampler) add_once(out, ir::RegFile::Sampler, op.index, op.loc);
    if (ir::is_ps1x(program.profile) && ir::samples(ins) && ins.dst)
      add_once(out, ir::RegFile::Sampler, ins.dst->index, ins.loc);
  }
  return out;
}

} // namespace tierlift::pass::detail
