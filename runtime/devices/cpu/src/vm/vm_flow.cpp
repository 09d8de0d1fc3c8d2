// vs_2_0 static flow control (docs/d3d9-rules.md §5.3) and the ps_1_4 phase marker. Jump targets
// were matched at preparation; the frames live in the Invocation (fixed arrays, no heap).
// Counts are clamped to the legal ranges and backward jumps are budgeted, so that no
// program can hang the interpreter.
#include <algorithm>
#include <array>

#include "vm_internal.h"

namespace tierlift::cpu::vm {

using ir::Opcode;

namespace {

std::array<int32_t, 4> int_const(const Step& s, const Invocation& inv) {
  if (s.int_def) return *s.int_def;
  return inv.consts->i[static_cast<size_t>(s.aux)];
}

bool bool_const(const Step& s, const Invocation& inv) {
  bool b = s.bool_def ? *s.bool_def : inv.consts->b[static_cast<size_t>(s.aux)];
  return b != s.negate;
}

// Opens a loop or rep frame; a zero count skips the body (pc = past the end).
void open_frame(const Step& s, Invocation& inv, bool is_loop) {
  auto i = int_const(s, inv);
  int32_t count = std::clamp(i[0], 0, 255);
  if (count == 0) {
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
  f.step = is_loop ? std::clamp(i[2], -128, 127) : 0;
  if (is_loop) inv.al = std::clamp(i[1], 0, 255);
}

void close_frame(const Step& s, Invocation& inv) {
  (void)s;
  if (inv.loop_depth == 0) return;
  LoopFrame& f = inv.loops[inv.loop_depth - 1];
  if (f.is_loop) inv.al += f.step;
  if (--f.remaining > 0) {
    if (++inv.backward_jumps > kMaxBackwardJumps) {
      inv.stop = true;
      return;
    }
    inv.pc = f.body_pc;
    return;
  }
  if (f.is_loop) inv.al = f.saved_al;
  --inv.loop_depth;
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

ExecFn flow_exec(Opcode op) {
  return kFlow[op];
}

} // namespace tierlift::cpu::vm
