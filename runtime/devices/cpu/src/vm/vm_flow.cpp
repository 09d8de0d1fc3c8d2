// Flow control of shader models 2.0 to 3.0 (docs/d3d9-rules.md §5.3): static if/loop/rep/
// call, the dynamic forms of 2.x and 3.0 (if_comp, if p0, break, break_comp, breakp, callnz
// p0), setp and predicated instructions; and the ps_1_4 phase marker. Jump targets were
// matched at preparation; the frames live in the Invocation (fixed arrays, no heap). Counts
// are clamped to the legal ranges and iterations budgeted by the rules of ir/flow_rules.h,
// the ones the generated SPIR-V follows, so that no program can hang either device.
#include <algorithm>
#include <array>

#include "tierlift/ir/flow_rules.h"
#include "tierlift/ir/numerics.h"
#include "vm_internal.h"

namespace tierlift::cpu::vm {

using ir::Opcode;
namespace flow = ir::flow;
namespace num = ir::numerics;

namespace {

std::array<int32_t, 4> int_const(const Step& s, const Invocation& inv) {
  if (s.int_def) return *s.int_def;
  return inv.consts->i[static_cast<size_t>(s.aux)];
}

bool bool_const(const Step& s, const Invocation& inv) {
  bool b = s.bool_def ? *s.bool_def : inv.consts->b[static_cast<size_t>(s.aux)];
  return b != s.negate;
}

// Opens a loop or rep frame; a zero count or a spent budget skips the body (pc = past the
// end).
void open_frame(const Step& s, Invocation& inv, bool is_loop) {
  auto i = int_const(s, inv);
  int32_t count = std::clamp(i[0], flow::kMinCount, flow::kMaxCount);
  inv.iterations += flow::kEntryCost;
  if (count == 0 || inv.iterations > flow::kIterationBudget) {
    inv.pc = s.target;
    return;
  }
  if (inv.loop_depth >= kMaxLoopDepth) {
    inv.stop = true;
    return;
  }
  LoopFrame& f = inv.loops[inv.loop_depth++];
  f.remaining = count;
  f.body_pc = inv.pc;
  f.is_loop = is_loop;
  f.saved_al = inv.al;
  f.step = is_loop ? std::clamp(i[2], flow::kMinStep, flow::kMaxStep) : 0;
  if (is_loop) inv.al = std::clamp(i[1], flow::kMinStart, flow::kMaxStart);
}

// Leaves the innermost loop: aL back to its value before the loop.
void pop_frame(Invocation& inv) {
  const LoopFrame& f = inv.loops[inv.loop_depth - 1];
  if (f.is_loop) inv.al = f.saved_al;
  --inv.loop_depth;
}

// endloop / endrep: the iteration is complete; another starts while the count and the
// invocation's budget both remain (ir::flow::kIterationBudget).
void close_frame(const Step& s, Invocation& inv) {
  (void)s;
  if (inv.loop_depth == 0) return;
  LoopFrame& f = inv.loops[inv.loop_depth - 1];
  if (f.is_loop) inv.al += f.step;
  ++inv.iterations;
  if (--f.remaining > 0 && inv.iterations <= flow::kIterationBudget) {
    inv.pc = f.body_pc;
    return;
  }
  pop_frame(inv);
}

void exec_loop(const Step& s, Invocation& inv) {
  open_frame(s, inv, true);
}
void exec_rep(const Step& s, Invocation& inv) {
  open_frame(s, inv, false);
}
void exec_endloop(const Step& s, Invocation& inv) {
  close_frame(s, inv);
}

void exec_if(const Step& s, Invocation& inv) {
  if (!bool_const(s, inv)) inv.pc = s.target;
}
void exec_else(const Step& s, Invocation& inv) {
  inv.pc = s.target;
}
void exec_marker(const Step& s, Invocation& inv) {
  (void)s, (void)inv;
}

void call_to(const Step& s, Invocation& inv) {
  if (inv.call_depth >= kMaxCallDepth) {
    inv.stop = true;
    return;
  }
  inv.calls[inv.call_depth++] = inv.pc;
  inv.pc = s.target;
}
void exec_call(const Step& s, Invocation& inv) {
  call_to(s, inv);
}
void exec_callnz(const Step& s, Invocation& inv) {
  if (bool_const(s, inv)) call_to(s, inv);
}
// ret in main ends the program; in a subroutine it returns after the call.
void exec_ret(const Step& s, Invocation& inv) {
  (void)s;
  if (inv.call_depth == 0) {
    inv.stop = true;
    return;
  }
  inv.pc = inv.calls[--inv.call_depth];
}

// p0's component `aux`, negated by !p0 (if p0.x, callnz l#, p0.y, breakp !p0.z).
bool predicate(const Step& s, const Invocation& inv) {
  return inv.p0[s.aux & 3] != s.negate;
}

// src0 `compare` src1 on their first components (the validator asks for replicate
// swizzles), by the rule of ir/flow_rules.h.
bool compared(const Step& s, const Invocation& inv) {
  const float a = fetch(s.src[0], inv)[0], b = fetch(s.src[1], inv)[0];
  const auto c = static_cast<flow::Comparison>(s.compare);
  return inv.prog->flush ? flow::compare(num::FloatArith<num::kFlush>{}, c, a, b)
                         : flow::compare(num::FloatArith<num::Denormals::Keep>{}, c, a, b);
}

void exec_if_compare(const Step& s, Invocation& inv) {
  if (!compared(s, inv)) inv.pc = s.target;
}
void exec_if_predicate(const Step& s, Invocation& inv) {
  if (!predicate(s, inv)) inv.pc = s.target;
}
void exec_callnz_predicate(const Step& s, Invocation& inv) {
  if (predicate(s, inv)) call_to(s, inv);
}
// break: out of the innermost loop or rep (target: past its end), as the end of its count.
void exec_break(const Step& s, Invocation& inv) {
  if (inv.loop_depth == 0) return;
  pop_frame(inv);
  inv.pc = s.target;
}
void exec_break_compare(const Step& s, Invocation& inv) {
  if (compared(s, inv)) exec_break(s, inv);
}
void exec_breakp(const Step& s, Invocation& inv) {
  if (predicate(s, inv)) exec_break(s, inv);
}

// ps_1_4 phase: the alpha of every r# is lost across the marker; tierlift defines it to
// read as 0 afterwards (NUMERICS.md "phase alpha").
void exec_phase(const Step& s, Invocation& inv) {
  (void)s;
  for (int r = 0; r < 6; ++r) inv.reg[kTempBase + r][3] = 0.0f;
}

constexpr std::pair<Opcode, ExecFn> kFlowRows[] = {
    {Opcode::Loop, exec_loop},      {Opcode::Rep, exec_rep},      {Opcode::EndLoop, exec_endloop},
    {Opcode::EndRep, exec_endloop}, {Opcode::If, exec_if},        {Opcode::Else, exec_else},
    {Opcode::EndIf, exec_marker},   {Opcode::Label, exec_marker}, {Opcode::Call, exec_call},
    {Opcode::CallNz, exec_callnz},  {Opcode::Ret, exec_ret},      {Opcode::Phase, exec_phase}};
constexpr OpcodeTable<ExecFn> kFlow{kFlowRows};

} // namespace

ExecFn flow_exec(const ir::Instruction& ins) {
  if (flow::comparison_of(ins.op))
    return ir::op_info(ins.op).cls == ir::OpClass::Flow
               ? (ins.op >= Opcode::IfGt ? exec_if_compare : exec_break_compare)
               : nullptr;
  const bool on_p0 = std::any_of(ins.src.begin(), ins.src.end(), [](const ir::SrcOperand& o) {
    return o.file == ir::RegFile::Predicate;
  });
  switch (ins.op) {
  case Opcode::If: return on_p0 ? exec_if_predicate : exec_if;
  case Opcode::CallNz: return on_p0 ? exec_callnz_predicate : exec_callnz;
  case Opcode::Break: return exec_break;
  case Opcode::BreakP: return exec_breakp;
  default: return kFlow[ins.op];
  }
}

// setp_comp p0.mask, src0, src1: each written component of p0 is src0 `compare` src1 in
// that component.
void exec_setp(const Step& s, Invocation& inv) {
  const Vec4 a = fetch(s.src[0], inv), b = fetch(s.src[1], inv);
  const auto c = static_cast<flow::Comparison>(s.compare);
  for (int i = 0; i < 4; ++i) {
    if (!(s.dst.mask & (1 << i))) continue;
    inv.p0[i] = inv.prog->flush
                    ? flow::compare(num::FloatArith<num::kFlush>{}, c, a[i], b[i])
                    : flow::compare(num::FloatArith<num::Denormals::Keep>{}, c, a[i], b[i]);
  }
}

// "(p0.swz) op" / "(!p0.swz) op": destination component i is written when p0's component
// swz[i] holds (does not, under !): the instruction runs with its write mask narrowed.
void exec_predicated(const Step& s, Invocation& inv) {
  uint8_t mask = 0;
  for (int i = 0; i < 4; ++i)
    if (inv.p0[s.pred_swz[i]] != s.pred_not) mask |= static_cast<uint8_t>(1u << i);
  Step narrowed = s;
  narrowed.dst.mask &= mask;
  narrowed.exec = s.inner;
  s.inner(narrowed, inv);
}

} // namespace tierlift::cpu::vm
