// The structural IR validator: the invariants every pass leaves behind. Unlike the
// assembler's validator it knows no listing rules (read ports, slot counts, ordering); it
// guards what the backends index and dispatch on.
#include <algorithm>
#include <iterator>

#include <fmt/format.h>

#include "tierlift/ir/passes.h"
#include "tierlift/ir/semantics.h"
#include "tierlift/ir/sm3_interface.h"

namespace tierlift::ir {
namespace {

// Registers of a file the profile can address (the devices' constant count in a vertex
// shader, which goes past the 96 / 256 a listing is guaranteed).
uint32_t addressable(RegFile f, Profile p) {
  const ProfileLimits& l = limits(p);
  const bool vs = is_vertex(p);
  switch (f) {
  case RegFile::Temp: return l.temps;
  case RegFile::Input: return l.inputs;
  case RegFile::Const: return vs ? 8192 : l.float_consts;
  case RegFile::Addr: return vs ? 1 : 0;
  case RegFile::Texture: return vs ? 0 : l.texcoords;
  case RegFile::RastOut: return vs ? 3 : 0;
  case RegFile::AttrOut: return vs ? l.color_outputs : 0;
  case RegFile::TexCrdOut: return vs ? l.tex_outputs : 0;
  case RegFile::ConstInt: return l.int_consts;
  case RegFile::ColorOut: return vs ? 0 : 4;
  case RegFile::DepthOut: return vs ? 0 : 1;
  case RegFile::Sampler: return vs ? l.samplers : 16; // vs_3_0: its 4 vertex samplers
  case RegFile::ConstBool: return l.bool_consts;
  case RegFile::Loop: return vs || p == Profile::ps_3_0 ? 1 : 0; // aL
  case RegFile::Label: return l.labels;
  case RegFile::Output: return vs ? l.tex_outputs : 0;
  case RegFile::Predicate: return has_predication(p) ? 1 : 0;
  case RegFile::Misc: return p == Profile::ps_3_0 ? 2 : 0;
  }
  return 0;
}

void check_register(DiagnosticSink& sink, Profile p, RegFile f, uint64_t last, SourceLoc loc) {
  const uint32_t n = addressable(f, p);
  if (last >= n)
    sink.error(loc, "ir",
               fmt::format("{} is outside the {} registers {} can address",
                           register_name(f, static_cast<uint32_t>(last)), n, profile_name(p)));
}

void check_instruction(DiagnosticSink& sink, Profile p, const Instruction& ins) {
  const auto v = static_cast<int>(ins.op);
  if (v < 0 || v >= kOpcodeCount) {
    sink.error(ins.loc, "ir", fmt::format("opcode value {} is not in the table", v));
    return;
  }
  const OpInfo& info = op_info(ins.op);
  if (!legal_in(info, p) || info.cls == OpClass::Decl)
    sink.error(ins.loc, "ir",
               fmt::format("{} is not an instruction of {}", info.mnemonic, profile_name(p)));
  if (info.has_dst != ins.dst.has_value())
    sink.error(ins.loc, "ir",
               fmt::format("{} {} a destination", info.mnemonic,
                           info.has_dst ? "lacks" : "must not have"));
  if (ins.src.size() < info.num_src)
    sink.error(ins.loc, "ir",
               fmt::format("{} has {} sources, the table says {}", info.mnemonic, ins.src.size(),
                           info.num_src));
  if (ins.dst) {
    if (ins.dst->mask == 0 || ins.dst->mask > kFullMask)
      sink.error(ins.dst->loc, "ir", fmt::format("{} has an empty write mask", info.mnemonic));
    check_register(sink, p, ins.dst->file, ins.dst->index, ins.dst->loc);
  }
  // Direct3D 9 predicates arithmetic and texture instructions only ([MS-ASM] setp_comp,
  // "Applying the Predicate Register"); flow control takes p0 as an operand instead (if p0.x,
  // callnz l#, p0.x, breakp p0.x). The assembler's validator refuses it too; this guards
  // programs built or loaded without it.
  if (ins.pred && info.cls == OpClass::Flow)
    sink.error(ins.pred->loc.valid() ? ins.pred->loc : ins.loc, "ir",
               fmt::format("{} cannot be predicated: Direct3D 9 predicates arithmetic and "
                           "texture instructions only (flow control reads p0 as an operand: "
                           "if p0.x, callnz l#, p0.x, breakp p0.x)",
                           info.mnemonic));
  for (size_t k = 0; k < ins.src.size(); ++k) {
    const SrcOperand& s = ins.src[k];
    // Matrix rows must all exist; a relative base only needs to be addressable itself.
    const uint32_t rows = s.rel ? 1 : source_rows(ins, k);
    check_register(sink, p, s.file, uint64_t{s.index} + rows - 1, s.loc);
  }
}

} // namespace

Status validate_ir(const Program& program) {
  DiagnosticSink sink;
  for (const Instruction& ins : program.code) check_instruction(sink, program.profile, ins);
  for (const ConstDef& d : program.defs) {
    if (d.file != RegFile::Const && d.file != RegFile::ConstInt && d.file != RegFile::ConstBool)
      sink.error(d.loc, "ir", "a definition must name c#, i# or b#");
    else
      check_register(sink, program.profile, d.file, d.index, d.loc);
  }
  if (sink.has_errors()) return fail(sink);
  return ok_status();
}

Status check_executable(const Program& program, std::string_view backend) {
  if (std::find(std::begin(kExecutableProfiles), std::end(kExecutableProfiles), program.profile) !=
      std::end(kExecutableProfiles))
    return ok_status();
  // Shader models 2.x and 3.0 run whole (texldl in both stages, NUMERICS.md F11 and F14; a
  // predicate on flow control is refused by validate_ir as not Direct3D 9). What is left to
  // check is relative addressing a program built without the assembler may hold.
  DiagnosticSink sink;
  // Relative addressing: c# everywhere, a vs_3_0's or ps_3_0's v# read through the table of
  // its declared inputs (sm3_interface.h relative_input_links) and a vs_3_0's o# written
  // through the table of its declared outputs (relative_output_links). No profile allows
  // another relative destination; one built without the assembler is refused here.
  const bool sm3 = program.profile == Profile::vs_3_0 || program.profile == Profile::ps_3_0;
  for (const Instruction& ins : program.code) {
    auto refuse = [&](RegFile f, uint32_t index, SourceLoc loc, std::string_view why) {
      sink.error(loc, "not-supported",
                 fmt::format("not supported yet by {}: {} addressed relatively ({})", backend,
                             register_name(f, index), why));
    };
    if (ins.dst && ins.dst->rel &&
        !(program.profile == Profile::vs_3_0 && ins.dst->file == RegFile::Output))
      refuse(ins.dst->file, ins.dst->index, ins.dst->loc,
             "only a vs_3_0's o# is written relatively");
    for (const SrcOperand& s : ins.src)
      if (s.rel && s.file != RegFile::Const && !(sm3 && s.file == RegFile::Input))
        refuse(s.file, s.index, s.loc, "only c# and, in vs_3_0 and ps_3_0, v# are");
  }
  check_semantic_interface(program, backend, sink);
  if (sink.has_errors()) return fail(sink);
  return ok_status();
}

Result<Program> run_pass(Program program, std::string_view name,
                         const std::function<void(Program&)>& pass) {
  pass(program);
  Status valid = validate_ir(program);
  if (!valid.ok()) {
    Failure f = std::move(valid).failure();
    for (Diagnostic& d : f.diagnostics) d.message = fmt::format("after {}: {}", name, d.message);
    return f;
  }
  return program;
}

} // namespace tierlift::ir
