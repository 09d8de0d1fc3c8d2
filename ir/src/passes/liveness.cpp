// Liveness passes: dead instructions, the inputs a pixel stage reads, the vertex outputs
// nobody consumes. Read and write sets come from the opcode table (semantics.h).
#include "tierlift/ir/liveness.h"

#include <algorithm>

#include "tierlift/ir/semantics.h"

namespace tierlift::ir {
namespace {

bool is_flow(const Instruction& ins) {
  return op_info(ins.op).cls == OpClass::Flow && ins.op != Opcode::Phase;
}

bool is_varying(const RegKey& r) {
  return r.first == RegFile::TexCrdOut || r.first == RegFile::AttrOut ||
         (r.first == RegFile::RastOut && r.second == kRastFog);
}

} // namespace

bool has_side_effect(const Instruction& ins, Profile p) {
  if (has_implicit(ins, kDiscards) || has_implicit(ins, kWritesDepth)) return true;
  // ps_1_1…1_3 texture-address instructions pass pad rows to each other implicitly.
  return is_ps11_13(p) && op_info(ins.op).cls == OpClass::Texture;
}

RegisterReads registers_read(const Instruction& ins, Profile p) {
  RegisterReads r;
  const OpInfo& info = op_info(ins.op);
  for (size_t i = 0; i < ins.src.size(); ++i) {
    const SrcOperand& s = ins.src[i];
    const uint32_t rows = source_rows(ins, i);
    // A relative v# read (vs_3_0, ps_3_0) reaches the declared inputs through
    // relative_input_links, not the register its base names: a caller that needs the
    // inputs read takes them from there (codegen's pruning).
    if (!(s.rel && s.file == RegFile::Input))
      for (uint32_t k = 0; k < rows; ++k) r.regs.push_back({s.file, s.index + k});
    if (s.rel) {
      r.const_relative = true;
      r.regs.push_back({s.rel->file, 0});
    }
  }
  // Interpolated texture coordinates read implicitly by ps_1_1…1_3 texture instructions.
  if (is_ps11_13(p) && info.cls == OpClass::Texture && ins.dst) {
    const uint32_t m = ins.dst->index;
    if (has_implicit(ins, kReadsTexCoord)) r.regs.push_back({RegFile::Texture, kTexCoordKey + m});
    if (has_implicit(ins, kReadsEyeFromRows))
      for (uint32_t k = 1; k <= 2 && k <= m; ++k)
        r.regs.push_back({RegFile::Texture, kTexCoordKey + m - k});
  }
  // texkill (ps_1_4, ps_2_0) tests its operand; texdepth divides r5.r by r5.g.
  if (has_implicit(ins, kReadsOperand) && ins.dst && !is_ps11_13(p))
    r.regs.push_back({ins.dst->file, ins.dst->index});
  return r;
}

std::map<RegKey, uint8_t> pixel_live_out(const Program& ps) {
  std::map<RegKey, uint8_t> live;
  if (is_ps1x(ps.profile)) live[{RegFile::Temp, 0}] = 0xF;
  for (uint32_t n = 0; n < 4; ++n) live[{RegFile::ColorOut, n}] = 0xF;
  live[{RegFile::DepthOut, 0}] = 0xF;
  return live;
}

std::vector<bool> dead_instructions(const Program& prog, std::map<RegKey, uint8_t> live) {
  std::vector<bool> dead(prog.code.size(), false);
  if (std::any_of(prog.code.begin(), prog.code.end(), is_flow)) {
    // With flow control only writes to registers nobody reads at the end are dropped:
    // output registers that the other stage does not consume.
    for (size_t i = 0; i < prog.code.size(); ++i) {
      const auto& ins = prog.code[i];
      if (!ins.dst || has_side_effect(ins, prog.profile)) continue;
      const RegFile f = ins.dst->file;
      const bool output = f == RegFile::TexCrdOut || f == RegFile::AttrOut ||
                          f == RegFile::RastOut || f == RegFile::ColorOut;
      if (output && !live.count({f, ins.dst->index})) dead[i] = true;
    }
    return dead;
  }
  size_t end = prog.code.size();
  while (end > 0) {
    size_t begin = end - 1; // a co-issued pair [begin, end) is one unit
    while (begin > 0 && prog.code[begin].coissue) --begin;
    std::vector<size_t> live_here;
    for (size_t i = begin; i < end; ++i) {
      const auto& ins = prog.code[i];
      const uint8_t w = written_mask(ins, prog.profile);
      bool is_live = has_side_effect(ins, prog.profile) || op_info(ins.op).cls == OpClass::Flow;
      if (ins.dst && (live[{ins.dst->file, ins.dst->index}] & w)) is_live = true;
      if (is_live)
        live_here.push_back(i);
      else
        dead[i] = true;
    }
    for (size_t i : live_here) {
      const auto& ins = prog.code[i];
      if (ins.dst)
        live[{ins.dst->file, ins.dst->index}] &=
            static_cast<uint8_t>(~written_mask(ins, prog.profile));
    }
    for (size_t i : live_here)
      for (const RegKey& r : registers_read(prog.code[i], prog.profile).regs) live[r] = 0xF;
    end = begin;
  }
  return dead;
}

std::set<RegKey> live_inputs(const Program& ps, const std::vector<bool>& dead) {
  std::set<RegKey> out;
  const bool ps11_13 = is_ps11_13(ps.profile);
  for (size_t i = 0; i < ps.code.size(); ++i) {
    if (dead[i]) continue;
    for (const RegKey& r : registers_read(ps.code[i], ps.profile).regs) {
      if (r.first == RegFile::Input) out.insert({RegFile::AttrOut, r.second});
      if (r.first == RegFile::Texture && r.second >= kTexCoordKey)
        out.insert({RegFile::TexCrdOut, r.second - kTexCoordKey});
      if (r.first == RegFile::Texture && r.second < kTexCoordKey && !ps11_13)
        out.insert({RegFile::TexCrdOut, r.second});
    }
  }
  return out;
}

std::vector<RegKey> dead_outputs(const Program& vs, const std::set<RegKey>& consumed) {
  std::set<RegKey> written;
  for (const Instruction& ins : vs.code)
    if (ins.dst) written.insert({ins.dst->file, ins.dst->index});
  std::vector<RegKey> out;
  for (const RegKey& r : written)
    if (is_varying(r) && !consumed.count(r)) out.push_back(r);
  return out;
}

} // namespace tierlift::ir
