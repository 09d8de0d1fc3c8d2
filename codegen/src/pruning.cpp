// Link-time pruning of a VS/PS pair: the pixel shader's live instructions decide which
// interpolants it reads; the vertex shader declares exactly those outputs (plus position
// and point size), drops instructions whose results nobody reads (backward liveness per
// register component, co-issued pairs as one unit), and with them the inputs and constants
// only they read. Everything left out is reported as a PrunedItem.
#include <algorithm>
#include <array>
#include <map>
#include <set>

#include "tierlift/codegen/codegen.h"
#include "tierlift/codegen/emitter.h"

namespace tierlift::codegen {

using ir::Opcode;
using ir::RegFile;
using Reg = std::pair<RegFile, uint32_t>;

namespace {

bool is_flow(const ir::Instruction& ins) {
  return ir::op_info(ins.op).cls == ir::OpClass::Flow && ins.op != Opcode::Phase;
}

// Instructions with an effect beyond their destination register.
bool has_side_effect(const ir::Instruction& ins, ir::Profile p) {
  if (ins.op == Opcode::TexKill || ins.op == Opcode::TexDepth || ins.op == Opcode::TexM3x2Depth)
    return true;
  // ps_1_1…1_3 texture-address instructions pass pad rows to each other implicitly.
  return ir::is_ps11_13(p) && ir::op_info(ins.op).cls == ir::OpClass::Texture;
}

// Components an instruction really writes (macros and sincos narrow the mask).
uint8_t written_mask(const ir::Instruction& ins, ir::Profile p) {
  if (!ins.dst || ins.op == Opcode::TexKill) return 0;
  uint8_t m = ins.dst->mask & 0xF;
  switch (ins.op) {
  case Opcode::M3x2:
  case Opcode::SinCos:
  case Opcode::Bem: return m & 0x3;
  case Opcode::M3x3:
  case Opcode::M4x3:
  case Opcode::Crs: return m & 0x7;
  case Opcode::Frc: return p == ir::Profile::vs_1_1 ? (m & 0x3) : m;
  case Opcode::TexM3x2Pad:
  case Opcode::TexM3x3Pad: return 0;
  default: return m;
  }
}

struct Reads {
  std::vector<Reg> regs; // each read with all four components (conservative)
  bool const_relative = false;
};

Reads reads_of(const ir::Instruction& ins, ir::Profile p) {
  Reads r;
  const ir::OpInfo& info = ir::op_info(ins.op);
  for (size_t i = 0; i < ins.src.size(); ++i) {
    const ir::SrcOperand& s = ins.src[i];
    const int rows = (i == 1 && info.src[1] == ir::OperandKind::Matrix)
                         ? (ins.op == Opcode::M4x4 || ins.op == Opcode::M3x4 ? 4
                            : ins.op == Opcode::M3x2                         ? 2
                                                                             : 3)
                         : 1;
    for (int k = 0; k < rows; ++k) r.regs.push_back({s.file, s.index + static_cast<uint32_t>(k)});
    if (s.rel) {
      r.const_relative = true;
      r.regs.push_back({s.rel->file, 0});
    }
  }
  // Interpolated texture coordinates read implicitly by ps_1_1…1_3 texture instructions.
  if (ir::is_ps11_13(p) && info.cls == ir::OpClass::Texture && ins.dst) {
    const uint32_t m = ins.dst->index;
    if (ins.op != Opcode::TexReg2Ar && ins.op != Opcode::TexReg2Gb && ins.op != Opcode::TexReg2Rgb)
      r.regs.push_back({RegFile::Texture, 1000 + m}); // 1000+: TC(m), not the t# register
    if (ins.op == Opcode::TexM3x3VSpec)
      for (uint32_t k = 1; k <= 2 && k <= m; ++k)
        r.regs.push_back({RegFile::Texture, 1000 + m - k});
  }
  if (ins.op == Opcode::TexKill && ins.dst && !ir::is_ps11_13(p))
    r.regs.push_back({ins.dst->file, ins.dst->index});
  if (ins.op == Opcode::TexDepth && ins.dst) r.regs.push_back({RegFile::Temp, ins.dst->index});
  return r;
}

std::string describe(const ir::Instruction& ins) {
  std::string s(ir::op_info(ins.op).mnemonic);
  if (ins.dst)
    s += " " + ir::register_name(ins.dst->file, ins.dst->index) + ir::mask_text(ins.dst->mask);
  return s;
}

// Backward liveness over straight-line code. live: register → component mask.
std::vector<bool> dead_instructions(const ir::Program& prog, std::map<Reg, uint8_t> live) {
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
      bool is_live =
          has_side_effect(ins, prog.profile) || ir::op_info(ins.op).cls == ir::OpClass::Flow;
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
      for (const Reg& r : reads_of(prog.code[i], prog.profile).regs) live[r] = 0xF;
    end = begin;
  }
  return dead;
}

void note_unread(const ir::Program& prog, const std::vector<bool>& dead, ir::ShaderStage stage,
                 std::vector<PrunedItem>& out) {
  std::set<Reg> read_live, read_dead;
  bool relative = false;
  for (size_t i = 0; i < prog.code.size(); ++i) {
    const Reads r = reads_of(prog.code[i], prog.profile);
    for (const Reg& reg : r.regs) (dead[i] ? read_dead : read_live).insert(reg);
    if (!dead[i] && r.const_relative) relative = true;
  }
  for (size_t i = 0; i < prog.code.size(); ++i)
    if (dead[i])
      out.push_back({PrunedItem::Kind::DeadInstruction, stage, describe(prog.code[i]),
                     "its result is never used", prog.code[i].loc});
  for (const ir::Declaration& d : prog.decls) {
    const RegFile f = d.reg.file;
    if (f != RegFile::Input && f != RegFile::Texture) continue;
    Reg key{f, d.reg.index};
    bool used = read_live.count(key) > 0 || read_live.count({f, 1000 + d.reg.index}) > 0;
    if (!used)
      out.push_back({stage == ir::ShaderStage::Vertex ? PrunedItem::Kind::VertexInput
                                                      : PrunedItem::Kind::PixelInput,
                     stage, ir::register_name(f, d.reg.index), "never read", d.loc});
  }
  if (relative) return;
  for (const Reg& r : read_dead)
    if (r.first == RegFile::Const && !read_live.count(r))
      out.push_back({PrunedItem::Kind::Constant,
                     stage,
                     ir::register_name(r.first, r.second),
                     "read only by removed instructions",
                     {}});
}

// Interpolants a pixel program reads: (TexCrdOut, n) for t#/TC(n), (AttrOut, n) for v#.
std::set<Reg> pixel_interpolants(const ir::Program& ps, const std::vector<bool>& dead) {
  std::set<Reg> out;
  const bool ps11_13 = ir::is_ps11_13(ps.profile);
  for (size_t i = 0; i < ps.code.size(); ++i) {
    if (dead[i]) continue;
    for (const Reg& r : reads_of(ps.code[i], ps.profile).regs) {
      if (r.first == RegFile::Input) out.insert({RegFile::AttrOut, r.second});
      if (r.first == RegFile::Texture && r.second >= 1000)
        out.insert({RegFile::TexCrdOut, r.second - 1000});
      if (r.first == RegFile::Texture && r.second < 1000 && !ps11_13)
        out.insert({RegFile::TexCrdOut, r.second});
    }
  }
  return out;
}

std::map<Reg, uint8_t> pixel_outputs_live(const ir::Program& ps) {
  std::map<Reg, uint8_t> live;
  if (ir::is_ps1x(ps.profile)) live[{RegFile::Temp, 0}] = 0xF;
  for (uint32_t n = 0; n < 4; ++n) live[{RegFile::ColorOut, n}] = 0xF;
  live[{RegFile::DepthOut, 0}] = 0xF;
  return live;
}

} // namespace

std::optional<CompiledPair> compile_pair(const ir::Program& vs, const ir::Program& ps,
                                         const CodegenOptions& options, ir::DiagnosticSink& diags) {
  if (vs.stage() != ir::ShaderStage::Vertex || ps.stage() != ir::ShaderStage::Pixel) {
    diags.error(vs.version_loc, "codegen", "compile_pair needs a vertex and a pixel shader");
    return std::nullopt;
  }
  CompiledPair pair;
  EmitPlan ps_plan;
  ps_plan.skip = dead_instructions(ps, pixel_outputs_live(ps));
  const std::set<Reg> wanted = pixel_interpolants(ps, ps_plan.skip);

  EmitPlan vs_plan;
  vs_plan.vs_outputs = wanted;
  std::set<Reg> written;
  for (const ir::Instruction& ins : vs.code)
    if (ins.dst) written.insert({ins.dst->file, ins.dst->index});
  for (const Reg& r : written) {
    if (r.first == RegFile::RastOut && r.second == ir::kRastPts) vs_plan.vs_outputs->insert(r);
    const bool varying = r.first == RegFile::TexCrdOut || r.first == RegFile::AttrOut ||
                         (r.first == RegFile::RastOut && r.second == ir::kRastFog);
    if (varying && !wanted.count(r)) {
      const char* reads = r.first == RegFile::AttrOut ? "v" : "t";
      pair.pruned.push_back(
          {PrunedItem::Kind::VertexOutput,
           ir::ShaderStage::Vertex,
           ir::register_name(r.first, r.second),
           r.first == RegFile::RastOut
               ? std::string("fog is fixed-function state, no pixel shader reads it")
               : "the pixel shader never reads " + std::string(reads) + std::to_string(r.second),
           {}});
    }
  }
  for (const Reg& r : wanted)
    if (!written.count(r))
      diags.warning(ps.version_loc, "link",
                    "the pixel shader reads " +
                        std::string(r.first == RegFile::AttrOut ? "v" : "t") +
                        std::to_string(r.second) + ", which the vertex shader never writes (" +
                        ir::register_name(r.first, r.second) + " reads (0,0,0,0))");
  std::map<Reg, uint8_t> vs_live;
  for (const Reg& r : *vs_plan.vs_outputs) vs_live[r] = 0xF;
  vs_live[{RegFile::RastOut, ir::kRastPos}] = 0xF;
  vs_plan.skip = dead_instructions(vs, vs_live);
  note_unread(vs, vs_plan.skip, ir::ShaderStage::Vertex, pair.pruned);
  note_unread(ps, ps_plan.skip, ir::ShaderStage::Pixel, pair.pruned);

  Emitter ve(vs, options, vs_plan, diags);
  auto vm = ve.run();
  Emitter pe(ps, options, ps_plan, diags);
  auto pm = pe.run();
  if (!vm || !pm) return std::nullopt;
  pair.vs = std::move(*vm);
  pair.ps = std::move(*pm);
  return pair;
}

} // namespace tierlift::codegen
