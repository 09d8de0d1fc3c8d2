// Scans a program for the registers the run must supply.
#include "program_reads.h"

#include <algorithm>

namespace tierlift::pass::detail {
namespace {

// Rows a matrix macro reads from its second source (m4x4 c0 reads c0..c3).
uint32_t matrix_rows(ir::Opcode op) {
  switch (op) {
  case ir::Opcode::M4x4:
  case ir::Opcode::M3x4: return 4;
  case ir::Opcode::M4x3:
  case ir::Opcode::M3x3: return 3;
  case ir::Opcode::M3x2: return 2;
  default: return 1;
  }
}

bool samples(ir::Opcode op) {
  switch (op) {
  case ir::Opcode::Tex:
  case ir::Opcode::TexLd14:
  case ir::Opcode::TexBem:
  case ir::Opcode::TexBemL:
  case ir::Opcode::TexReg2Ar:
  case ir::Opcode::TexReg2Gb:
  case ir::Opcode::TexReg2Rgb:
  case ir::Opcode::TexM3x2Tex:
  case ir::Opcode::TexM3x3Tex:
  case ir::Opcode::TexM3x3Spec:
  case ir::Opcode::TexM3x3VSpec:
  case ir::Opcode::TexDp3Tex: return true;
  default: return false;
  }
}

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
      uint32_t rows = s == 1 ? matrix_rows(ins.op) : 1;
      for (uint32_t r = 0; r < rows; ++r) add_once(out, op.file, op.index + r, op.loc);
    }
  }
  return out;
}

std::vector<RegRead> sampler_reads(const ir::Program& program) {
  std::vector<RegRead> out;
  if (program.stage() != ir::ShaderStage::Pixel) return out;
  for (const ir::Instruction& ins : program.code) {
    for (const ir::SrcOperand& op : ins.src)
      if (op.file == ir::RegFile::Sampler) add_once(out, ir::RegFile::Sampler, op.index, op.loc);
    if (ir::is_ps1x(program.profile) && samples(ins.op) && ins.dst)
      add_once(out, ir::RegFile::Sampler, ins.dst->index, ins.loc);
  }
  return out;
}

bool is_defined(const ir::Program& program, ir::RegFile file, uint32_t index) {
  return std::any_of(program.defs.begin(), program.defs.end(),
                     [&](const ir::ConstDef& d) { return d.file == file && d.index == index; });
}

} // namespace tierlift::pass::detail
