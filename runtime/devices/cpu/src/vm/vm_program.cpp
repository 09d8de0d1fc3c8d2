// Preparation: turns an ir::Program into Steps once (operands decoded, executor and
// compute function chosen, flow control matched, labels resolved), so that running a
// program per pixel does no decoding and no allocation.
#include <algorithm>
#include <bit>
#include <string>
#include <vector>

#include "tierlift/ir/flow_rules.h"
#include "tierlift/ir/numerics.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/semantics.h"
#include "tierlift/ir/sm3_interface.h"
#include "vm_internal.h"

namespace tierlift::cpu::vm {

using ir::OpClass;
using ir::Opcode;
using ir::RegFile;

namespace {

// Why the VM cannot run a program: the rule and subject of every ShaderVM::create failure.
ir::Failure refuse(std::string message) {
  return ir::fail("cpu", std::string(kVmRule), std::move(message));
}

// A program broken past validation at `ins` (unmatched flow control, a missing operand).
ir::Failure broken(const ir::Instruction& ins, const std::string& what) {
  return refuse("line " + std::to_string(ins.loc.line) + ": " +
                std::string(ir::op_info(ins.op).mnemonic) + ": " + what);
}

void collect_defs(Prepared& p, std::vector<std::optional<std::array<int32_t, 4>>>& ints,
                  std::vector<std::optional<bool>>& bools) {
  ints.assign(16, std::nullopt);
  bools.assign(16, std::nullopt);
  // The fold-defs pass decides which definition of a register wins.
  const ir::FoldedDefs folded = ir::fold_defs(p.program);
  for (const auto& [index, d] : folded.floats) {
    if (index >= 8192) continue; // past any device's constant count
    if (p.const_defs.size() <= index) p.const_defs.resize(index + 1);
    Vec4 v{d.f(0), d.f(1), d.f(2), d.f(3)};
    // NUMERICS.md rule 13: lavapipe folds arithmetic on def constants at compile time with
    // denormals kept, and flushes the same arithmetic at run time; loading a def's
    // denormals as zeros of their sign (as the SPIR-V does under the same convention) makes
    // the folding invisible.
    if (p.flush)
      for (float& x : v) x = ir::numerics::flush_denormal(x);
    p.const_defs[index] = v;
  }
  for (const auto& [index, d] : folded.ints)
    if (index < 16) ints[index] = std::array<int32_t, 4>{d.i(0), d.i(1), d.i(2), d.i(3)};
  for (const auto& [index, d] : folded.bools)
    if (index < 16) bools[index] = d.b();
}

ir::Status prepare_arith(Step& s, const ir::Instruction& ins, const Prepared& p) {
  s.compute = arith_compute(ins.op, p.flush);
  if (!s.compute) return broken(ins, "no interpreter function");
  s.exec = exec_arith;
  s.rows = ir::op_semantics(ins.op).matrix_rows;
  if (ins.op == Opcode::Bem && ins.dst) s.aux = static_cast<int32_t>(ins.dst->index);
  if (ins.dst) {
    ir::Result<DstDesc> dst = decode_dst(*ins.dst, ins.mods, p);
    if (!dst) return refuse(dst.message());
    s.dst = *dst;
    // Writes outside what the opcode produces are dropped, as DXVK and wined3d do.
    s.dst.mask &= ir::op_writes(ins.op, p.program.profile);
  } else if (ins.op != Opcode::Nop) {
    return broken(ins, "missing destination");
  }
  return ir::ok_status();
}

ir::Status prepare_texture(Step& s, const ir::Instruction& ins, const Prepared& p) {
  s.exec = texture_exec(ins.op, p.flush);
  if (!s.exec) return broken(ins, "no interpreter function");
  if (!ins.dst) return broken(ins, "missing register operand");
  s.aux = static_cast<int32_t>(ins.dst->index); // texture stage m = destination number
  if (ins.op == Opcode::TexKill || ins.op == Opcode::TexDepth) {
    // The operand is read, not written: texkill tests it, texdepth divides r5.r by r5.g.
    ir::SrcOperand src;
    src.file = ins.dst->file;
    src.index = ins.dst->index;
    s.src[0] = decode_src(src, p);
    s.nsrc = 1;
    s.dst.kind = DstKind::None;
    return ir::ok_status();
  }
  ir::Result<DstDesc> dst = decode_dst(*ins.dst, ins.mods, p);
  if (!dst) return refuse(dst.message());
  s.dst = *dst;
  if (ins.op == Opcode::TexLd || ins.op == Opcode::TexLdP || ins.op == Opcode::TexLdB ||
      ins.op == Opcode::TexLdD || ins.op == Opcode::TexLdL) {
    if (ins.src.size() < 2) return broken(ins, "missing sampler");
    s.aux = static_cast<int32_t>(ins.src[1].index);
  }
  return ir::ok_status();
}

// The index of flow operand k, an i# or b# register (`kind` "integer" or "boolean") below 16.
ir::Result<uint32_t> constant_index(const ir::Instruction& ins, size_t k, const char* kind) {
  if (k >= ins.src.size()) return broken(ins, "missing operand");
  if (ins.src[k].index >= 16) return broken(ins, std::string(kind) + " constant out of range");
  return ins.src[k].index;
}

ir::Status prepare_flow(Step& s, const ir::Instruction& ins,
                        const std::vector<std::optional<std::array<int32_t, 4>>>& ints,
                        const std::vector<std::optional<bool>>& bools) {
  s.exec = flow_exec(ins);
  if (!s.exec) return broken(ins, "no interpreter function");
  if (const auto c = ir::flow::comparison_of(ins.op)) {
    if (ins.src.size() < 2) return broken(ins, "missing operand");
    s.compare = static_cast<uint8_t>(*c);
    return ir::ok_status();
  }
  // if p0.x, callnz l#, !p0.y, breakp p0.z: the component and its negation.
  for (const ir::SrcOperand& o : ins.src)
    if (o.file == RegFile::Predicate) {
      s.aux = ir::swizzle_component(o.swizzle, 0);
      s.negate = o.mod == ir::SrcMod::Not;
      return ir::ok_status();
    }
  switch (ins.op) {
  case Opcode::Loop:
  case Opcode::Rep: {
    const ir::Result<uint32_t> i = constant_index(ins, ins.op == Opcode::Loop ? 1 : 0, "integer");
    if (!i) return i.failure();
    s.aux = static_cast<int32_t>(*i);
    s.int_def = ints[*i];
    break;
  }
  case Opcode::If:
  case Opcode::CallNz: {
    const size_t k = ins.op == Opcode::If ? 0 : 1;
    const ir::Result<uint32_t> b = constant_index(ins, k, "boolean");
    if (!b) return b.failure();
    s.aux = static_cast<int32_t>(*b);
    s.bool_def = bools[*b];
    s.negate = ins.src[k].mod == ir::SrcMod::Not;
    break;
  }
  default: break;
  }
  return ir::ok_status();
}

bool opens_if(Opcode op) {
  return op == Opcode::If || (op >= Opcode::IfGt && op <= Opcode::IfLe);
}
bool is_break(Opcode op) {
  return op == Opcode::Break || op == Opcode::BreakP ||
         (op >= Opcode::BreakGt && op <= Opcode::BreakLe);
}

// Matches if/else/endif, loop/endloop, rep/endrep, each break with its innermost loop;
// resolves call targets to labels.
ir::Status match_flow(Prepared& p) {
  std::vector<int32_t> open;
  std::vector<std::vector<int32_t>> breaks; // per open loop or rep: its breaks' pcs
  std::vector<int32_t> label_pc(32, -1);
  int depth = 0, max_depth = 0;
  auto& code = p.program.code;
  for (int32_t pc = 0; pc < static_cast<int32_t>(code.size()); ++pc) {
    const ir::Instruction& ins = code[pc];
    auto top_is = [&](std::initializer_list<Opcode> ops) {
      return !open.empty() && std::find(ops.begin(), ops.end(), code[open.back()].op) != ops.end();
    };
    auto top_is_if = [&] { return !open.empty() && opens_if(code[open.back()].op); };
    if (opens_if(ins.op)) {
      open.push_back(pc);
      continue;
    }
    if (is_break(ins.op)) {
      if (breaks.empty()) return broken(ins, "break outside a loop");
      breaks.back().push_back(pc);
      continue;
    }
    switch (ins.op) {
    case Opcode::Loop:
    case Opcode::Rep:
      open.push_back(pc);
      breaks.emplace_back();
      max_depth = std::max(max_depth, ++depth);
      break;
    case Opcode::Else:
      if (!top_is_if()) return broken(ins, "else without if");
      p.steps[open.back()].target = pc + 1; // a false condition runs the else block
      open.back() = pc;
      break;
    case Opcode::EndIf:
      if (!top_is_if() && !top_is({Opcode::Else})) return broken(ins, "endif without if");
      p.steps[open.back()].target = pc + 1;
      open.pop_back();
      break;
    case Opcode::EndLoop:
    case Opcode::EndRep: {
      Opcode want = ins.op == Opcode::EndLoop ? Opcode::Loop : Opcode::Rep;
      if (!top_is({want})) return broken(ins, "unmatched end of loop");
      p.steps[open.back()].target = pc + 1; // a zero count skips the body
      p.steps[pc].target = open.back() + 1; // the body starts after loop/rep
      for (const int32_t b : breaks.back()) p.steps[b].target = pc + 1;
      breaks.pop_back();
      open.pop_back();
      --depth;
      break;
    }
    case Opcode::Label:
      if (ins.src.empty() || ins.src[0].index >= label_pc.size()) return broken(ins, "bad label");
      label_pc[ins.src[0].index] = pc;
      break;
    default: break;
    }
  }
  if (!open.empty()) return broken(code[open.back()], "block is never closed");
  if (max_depth > kMaxLoopDepth) return broken(code.front(), "loops nest too deeply");
  for (int32_t pc = 0; pc < static_cast<int32_t>(code.size()); ++pc) {
    const ir::Instruction& ins = code[pc];
    if (ins.op != Opcode::Call && ins.op != Opcode::CallNz) continue;
    uint32_t l = ins.src.empty() ? 9999 : ins.src[0].index;
    if (l >= label_pc.size() || label_pc[l] < 0) return broken(ins, "call to a missing label");
    p.steps[pc].target = label_pc[l] + 1;
  }
  return ir::ok_status();
}

// The executor of `ins` by its class (arithmetic, texture, flow).
ir::Status prepare_class(Step& s, const ir::Instruction& ins, const Prepared& p,
                         const std::vector<std::optional<std::array<int32_t, 4>>>& ints,
                         const std::vector<std::optional<bool>>& bools) {
  const auto comparison = ir::flow::comparison_of(ins.op);
  switch (ir::op_info(ins.op).cls) {
  case OpClass::Arith:
    if (comparison) { // setp_comp p0.mask, src0, src1
      s.exec = exec_setp;
      s.compare = static_cast<uint8_t>(*comparison);
      s.dst.mask = ins.dst ? ins.dst->mask & 0xF : 0;
      return ir::ok_status();
    }
    return prepare_arith(s, ins, p);
  case OpClass::Texture: return prepare_texture(s, ins, p);
  case OpClass::Flow: return prepare_flow(s, ins, ints, bools);
  case OpClass::Decl: return broken(ins, "declaration among the instructions");
  }
  return ir::ok_status();
}

} // namespace

ir::Result<Prepared> prepare(const ir::Program& program, const ir::Conventions& conv) {
  // The structural checks every backend runs first (ir/passes.h); the interpreter refuses
  // a program it cannot run as it refuses any other (rule kVmRule).
  if (ir::Status s = ir::validate_ir(program); !s) return refuse(s.message());
  if (ir::Status s = ir::check_executable(program, "the interpreter"); !s)
    return refuse(s.message());
  Prepared p;
  // Shader model 3's o#/v# become the 2.0 registers of their semantics (sm3_interface.h).
  p.program = ir::link_by_semantic(program);
  p.conv = conv;
  const ir::Profile prof = program.profile;
  p.ps1x = ir::is_ps1x(prof);
  p.ps11_13 = ir::is_ps11_13(prof);
  p.ps14 = prof == ir::Profile::ps_1_4;
  p.vs11 = prof == ir::Profile::vs_1_1;
  p.saturate_colors = ir::saturates_colors(prof);
  for (const auto& link : ir::relative_input_links(program))
    p.rel_inputs.push_back(
        link ? static_cast<int16_t>(flat_slot(link->first, link->second, program.stage()))
             : int16_t{-1});
  for (const auto& link : ir::relative_output_links(program))
    p.rel_outputs.push_back(
        link ? static_cast<int16_t>(flat_slot(link->first, link->second, program.stage()))
             : int16_t{-1});
  p.flush = conv.rounding == ir::Rounding::Llvmpipe;
  // Relative reads may reach any constant the device offers: 256 for vertex shaders (the
  // value DXVK and most D3D9 drivers report for MaxVertexShaderConst).
  p.const_limit = static_cast<int32_t>(ir::relative_constant_limit(prof));

  std::vector<std::optional<std::array<int32_t, 4>>> ints;
  std::vector<std::optional<bool>> bools;
  collect_defs(p, ints, bools);

  const auto& code = p.program.code;
  p.steps.resize(code.size());
  int8_t pad_run = 0;
  for (size_t i = 0; i < code.size(); ++i) {
    const ir::Instruction& ins = code[i];
    Step& s = p.steps[i];
    s.ins = &ins;
    s.nsrc = static_cast<uint8_t>(std::min<size_t>(ins.src.size(), 4));
    for (int k = 0; k < s.nsrc; ++k) s.src[k] = decode_src(ins.src[k], p);
    s.gradient = ins.op == Opcode::Dsx || ins.op == Opcode::Dsy;
    if (ir::Status made = prepare_class(s, ins, p, ints, bools); !made) return made.failure();
    if (ins.pred) {
      s.inner = s.exec;
      s.exec = exec_predicated;
      for (int c = 0; c < 4; ++c) s.pred_swz[c] = ir::swizzle_component(ins.pred->swizzle, c);
      s.pred_not = ins.pred->mod == ir::SrcMod::Not;
    }
    // Pad rows count up within a run of texm3x2pad/texm3x3pad.
    const bool pad = ir::is_texm_pad(ins.op);
    s.pad_row = pad ? std::min<int8_t>(pad_run, 1) : 0;
    pad_run = pad ? static_cast<int8_t>(pad_run + 1) : 0;
    if (ins.dst && ins.dst->file == RegFile::RastOut) {
      uint8_t c =
          static_cast<uint8_t>(std::countr_zero(static_cast<unsigned>(ins.dst->mask | 0x10)) & 3);
      if (ins.dst->index == ir::kRastFog) p.fog_component = c;
      if (ins.dst->index == ir::kRastPts) p.pts_component = c;
    }
  }
  // Co-issued pairs: the first half runs both (read before write).
  for (size_t i = 0; i + 1 < code.size(); ++i)
    if (code[i + 1].coissue && p.steps[i].exec == exec_arith && p.steps[i + 1].exec == exec_arith)
      p.steps[i].exec = exec_arith_pair;
  if (ir::Status matched = match_flow(p); !matched) return matched.failure();
  return p;
}

void run(const Prepared& p, Invocation& inv) {
  const Step* steps = p.steps.data();
  const auto n = static_cast<int32_t>(p.steps.size());
  while (inv.pc < n && !inv.stop) {
    const Step& s = steps[inv.pc++];
    s.exec(s, inv);
  }
}

namespace {

// Instruction `at`'s destination register as it is now (a0: its integers as floats; the
// depth instructions: oDepth).
void record(const Prepared& p, const Invocation& inv, int32_t at, InstructionTrace& trace) {
  const ir::Instruction& ins = p.program.code[static_cast<size_t>(at)];
  if (!ins.dst) return;
  Vec4 value{};
  if (ins.op == Opcode::TexDepth || ins.op == Opcode::TexM3x2Depth) {
    // They write the pixel's depth, not their destination register (as the SPIR-V does).
    if (!inv.pout || !inv.pout->depth) return;
    value[0] = *inv.pout->depth;
  } else if (ins.dst->file == RegFile::Addr) {
    for (int c = 0; c < 4; ++c) value[c] = static_cast<float>(inv.a0[c]);
  } else {
    const int slot = flat_slot(ins.dst->file, ins.dst->index, p.program.stage());
    if (slot < 0) return;
    value = inv.reg[slot];
  }
  trace.value[static_cast<size_t>(at)] = value;
  ++trace.hits[static_cast<size_t>(at)];
}

} // namespace

void start_trace(const Prepared& p, InstructionTrace& trace) {
  trace.value.assign(p.steps.size(), Vec4{0, 0, 0, 0});
  trace.hits.assign(p.steps.size(), 0);
}

void record_step(const Prepared& p, const Invocation& inv, int32_t at, InstructionTrace& trace) {
  record(p, inv, at, trace);
  if (p.steps[static_cast<size_t>(at)].exec == exec_arith_pair)
    record(p, inv, at + 1, trace); // it ran the second half too
}

void run_traced(const Prepared& p, Invocation& inv, InstructionTrace& trace) {
  start_trace(p, trace);
  const Step* steps = p.steps.data();
  const auto n = static_cast<int32_t>(p.steps.size());
  while (inv.pc < n && !inv.stop) {
    const int32_t at = inv.pc;
    const Step& s = steps[inv.pc++];
    s.exec(s, inv);
    record_step(p, inv, at, trace);
  }
}

} // namespace tierlift::cpu::vm
