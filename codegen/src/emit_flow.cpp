// Flow control of shader models 2.0 to 3.0 as structured SPIR-V control flow:
// if/if_comp/if p0 … else … endif → selection constructs; loop/rep → loop constructs with a
// Private iteration counter, the counts clamped and the invocation's iterations budgeted by
// the rules of ir/flow_rules.h (the interpreter's), so no constant can hang the device;
// break/break_comp/breakp → a branch to the innermost loop's merge block; label/ret → one
// SPIR-V function per subroutine (registers are Private, so subroutines share them),
// call/callnz → OpFunctionCall. ps_1_4 phase needs no code.
#include <algorithm>

#include <fmt/format.h>

#include "tierlift/codegen/emitter.h"

namespace tierlift::codegen {

using ir::Opcode;
using spv::Op;
using SC = spv::StorageClass;

Id Emitter::clamp_int(Id v, int32_t lo, int32_t hi) {
  const Id l = b.const_int(lo), h = b.const_int(hi);
  v = b.op(Op::OpSelect, t_int, {b.op(Op::OpSLessThan, t_bool, {v, l}), l, v});
  return b.op(Op::OpSelect, t_int, {b.op(Op::OpSGreaterThan, t_bool, {v, h}), h, v});
}

Id Emitter::label_fn(uint32_t label) {
  if (auto it = label_fns_.find(label); it != label_fns_.end()) return it->second;
  const Id id = b.fresh_id();
  label_fns_.emplace(label, id);
  // Built with append: GCC 12 at -O3 reports a false -Wrestrict on "l" + std::string.
  std::string name = "l";
  name += std::to_string(label);
  b.name(id, name);
  return id;
}

Id Emitter::iterations_var() {
  if (!iterations_var_) {
    iterations_var_ =
        b.global_variable(b.type_pointer(SC::Private, t_int), SC::Private, b.const_int(0));
    b.name(iterations_var_, "iterations");
  }
  return iterations_var_;
}

Emitter::FlowFrame* Emitter::innermost_loop() {
  for (auto it = flow_.rbegin(); it != flow_.rend(); ++it)
    if (it->kind != FlowFrame::Kind::If) return &*it;
  return nullptr;
}

void Emitter::branch_if_open(Id target) {
  if (b.block_open()) b.op_void(Op::OpBranch, {target});
}

Id Emitter::bool_operand(const ir::SrcOperand& s) {
  Id c = load_bool_const(s.index);
  if (s.mod == ir::SrcMod::Not) c = b.op(Op::OpLogicalNot, t_bool, {c});
  return c;
}

void Emitter::begin_loop(FlowFrame::Kind kind, uint32_t int_reg) {
  FlowFrame fr;
  fr.kind = kind;
  const Id iv = load_int_const(int_reg);
  const Id count = clamp_int(b.op(Op::OpCompositeExtract, t_int, {iv, 0}), ir::flow::kMinCount,
                             ir::flow::kMaxCount);
  fr.counter = b.global_variable(b.type_pointer(SC::Private, t_int), SC::Private, b.const_int(0));
  b.op_void(Op::OpStore, {fr.counter, count});
  if (kind == FlowFrame::Kind::Loop) {
    // aL starts at i.y and steps by i.z, each clamped to its legal range (ir/flow_rules.h,
    // as the interpreter clamps them).
    fr.saved_al = b.op(Op::OpLoad, t_int, {loop_var()});
    b.op_void(Op::OpStore, {loop_var(), clamp_int(b.op(Op::OpCompositeExtract, t_int, {iv, 1}),
                                                  ir::flow::kMinStart, ir::flow::kMaxStart)});
    fr.step = clamp_int(b.op(Op::OpCompositeExtract, t_int, {iv, 2}), ir::flow::kMinStep,
                        ir::flow::kMaxStep);
  }
  // Reaching the loop costs ir::flow::kEntryCost units of the invocation's budget.
  const Id before = b.op(Op::OpLoad, t_int, {iterations_var()});
  b.op_void(Op::OpStore, {iterations_var(),
                          b.op(Op::OpIAdd, t_int,
                               {before, b.const_int(static_cast<int32_t>(ir::flow::kEntryCost))})});
  fr.header = b.fresh_id();
  fr.merge = b.fresh_id();
  fr.cont = b.fresh_id();
  const Id body = b.fresh_id();
  b.op_void(Op::OpBranch, {fr.header});
  b.begin_block(fr.header);
  // Another iteration while the count and the invocation's budget both remain.
  const Id n = b.op(Op::OpLoad, t_int, {fr.counter});
  const Id spent = b.op(Op::OpLoad, t_int, {iterations_var()});
  const Id budget = b.const_int(static_cast<int32_t>(ir::flow::kIterationBudget));
  const Id more = b.op(Op::OpLogicalAnd, t_bool,
                       {b.op(Op::OpSGreaterThan, t_bool, {n, b.const_int(0)}),
                        b.op(Op::OpSLessThanEqual, t_bool, {spent, budget})});
  b.op_void(Op::OpLoopMerge,
            {fr.merge, fr.cont, static_cast<uint32_t>(spv::LoopControlMask::MaskNone)});
  b.op_void(Op::OpBranchConditional, {more, body, fr.merge});
  b.begin_block(body);
  flow_.push_back(fr);
}

bool Emitter::end_loop(const ir::Instruction& ins, FlowFrame::Kind kind) {
  if (flow_.empty() || flow_.back().kind != kind) {
    std::string message = "'";
    message.append(ir::op_info(ins.op).mnemonic).append("' without a matching opening");
    error(ins.loc, message);
    return false;
  }
  const FlowFrame fr = flow_.back();
  flow_.pop_back();
  branch_if_open(fr.cont);
  b.begin_block(fr.cont);
  const Id n = b.op(Op::OpLoad, t_int, {fr.counter});
  b.op_void(Op::OpStore, {fr.counter, b.op(Op::OpISub, t_int, {n, b.const_int(1)})});
  const Id spent = b.op(Op::OpLoad, t_int, {iterations_var()});
  b.op_void(Op::OpStore, {iterations_var(), b.op(Op::OpIAdd, t_int, {spent, b.const_int(1)})});
  if (kind == FlowFrame::Kind::Loop) {
    const Id al = b.op(Op::OpLoad, t_int, {loop_var()});
    b.op_void(Op::OpStore, {loop_var(), b.op(Op::OpIAdd, t_int, {al, fr.step})});
  }
  b.op_void(Op::OpBranch, {fr.header});
  b.begin_block(fr.merge);
  if (kind == FlowFrame::Kind::Loop) b.op_void(Op::OpStore, {loop_var(), fr.saved_al});
  return true;
}

void Emitter::open_if(Id cond) {
  FlowFrame fr;
  fr.kind = FlowFrame::Kind::If;
  fr.merge = b.fresh_id();
  fr.else_label = b.fresh_id();
  const Id then = b.fresh_id();
  b.op_void(Op::OpSelectionMerge,
            {fr.merge, static_cast<uint32_t>(spv::SelectionControlMask::MaskNone)});
  b.op_void(Op::OpBranchConditional, {cond, then, fr.else_label});
  b.begin_block(then);
  flow_.push_back(fr);
}

bool Emitter::else_branch(const ir::Instruction& ins) {
  if (flow_.empty() || flow_.back().kind != FlowFrame::Kind::If || flow_.back().has_else) {
    error(ins.loc, "'else' without a matching 'if'");
    return false;
  }
  branch_if_open(flow_.back().merge);
  b.begin_block(flow_.back().else_label);
  flow_.back().has_else = true;
  return true;
}

bool Emitter::end_if(const ir::Instruction& ins) {
  if (flow_.empty() || flow_.back().kind != FlowFrame::Kind::If) {
    error(ins.loc, "'endif' without a matching 'if'");
    return false;
  }
  const FlowFrame fr = flow_.back();
  flow_.pop_back();
  branch_if_open(fr.merge);
  if (!fr.has_else) {
    b.begin_block(fr.else_label);
    b.op_void(Op::OpBranch, {fr.merge});
  }
  b.begin_block(fr.merge);
  return true;
}

// break: a branch to the innermost loop's merge block (which restores aL). cond: break only
// when it holds (break_comp, breakp). A plain break branches on the constant true: the
// statements after it then sit in a block the loop header still dominates. Branching
// unconditionally left that block unreachable, and when it closed the body ("break" right
// before "endrep") its branch to the continue target lay outside the loop construct, which
// spirv-val rejects (generated vs_2_x, ps_2_x, vs_3_0 and ps_3_0 cases; CodegenEval.
// BreakRightBeforeTheLoopsEndLeavesAfterOneIteration).
bool Emitter::leave_loop(const ir::Instruction& ins, Id cond) {
  FlowFrame* loop = innermost_loop();
  if (!loop) {
    // fmt::format, not "'" + std::string(…): GCC 12 -O3 reports a false -Wrestrict in the
    // inlined concatenation (GCC bug 105651), which fails a Release build under -Werror.
    error(ins.loc, fmt::format("'{}' outside a loop", ir::op_info(ins.op).mnemonic));
    return false;
  }
  const Id out = loop->merge;
  if (!cond) cond = b.const_bool(true);
  const Id leave = b.fresh_id(), stay = b.fresh_id();
  b.op_void(Op::OpSelectionMerge,
            {stay, static_cast<uint32_t>(spv::SelectionControlMask::MaskNone)});
  b.op_void(Op::OpBranchConditional, {cond, leave, stay});
  b.begin_block(leave);
  b.op_void(Op::OpBranch, {out});
  b.begin_block(stay);
  return true;
}

namespace {

const ir::SrcOperand* predicate_operand(const ir::Instruction& ins) {
  for (const ir::SrcOperand& s : ins.src)
    if (s.file == ir::RegFile::Predicate) return &s;
  return nullptr;
}

} // namespace

void Emitter::call_if(const ir::Instruction& ins) {
  const ir::SrcOperand* p = predicate_operand(ins);
  const Id c = p ? predicate_component(*p) : bool_operand(ins.src[1]);
  const Id then = b.fresh_id(), merge = b.fresh_id();
  b.op_void(Op::OpSelectionMerge,
            {merge, static_cast<uint32_t>(spv::SelectionControlMask::MaskNone)});
  b.op_void(Op::OpBranchConditional, {c, then, merge});
  b.begin_block(then);
  b.op(Op::OpFunctionCall, t_void, {label_fn(ins.src[0].index)});
  b.op_void(Op::OpBranch, {merge});
  b.begin_block(merge);
}

// ps_1_4 phase: the alpha of every r# is lost across the marker; tierlift defines it as 0 (the
// interpreter's exec_phase, NUMERICS.md "phase alpha").
void Emitter::clear_phase_alpha() {
  for (uint32_t r = 0; r < 6; ++r) {
    if (!regs_.count({ir::RegFile::Temp, r})) continue; // never written: already 0
    PendingStore st;
    st.dst.file = ir::RegFile::Temp;
    st.dst.index = r;
    st.mask = 0x8;
    st.value = vec4_const(0, 0, 0, 0);
    store(st, false);
  }
}

void Emitter::end_routine_or_block() {
  if (b.block_open()) b.op_void(Op::OpReturn, {});
  if (flow_.empty()) {
    routine_ended_ = true; // the first top-level ret ends the routine
  } else {
    b.begin_block(b.fresh_id()); // the rest of the construct is unreachable
  }
}

bool Emitter::begin_subroutine(const ir::Instruction& ins) {
  if (!flow_.empty()) {
    error(ins.loc, "'label' inside an open flow-control block");
    return false;
  }
  if (b.block_open()) b.op_void(Op::OpReturn, {});
  b.end_function();
  const uint32_t l = ins.src[0].index;
  if (!labels_defined_.insert(l).second) {
    error(ins.loc, "label l" + std::to_string(l) + " is defined twice");
    return false;
  }
  b.begin_function(t_void, b.type_function(t_void), label_fn(l));
  b.begin_block(b.fresh_id());
  routine_ended_ = false;
  return true;
}

bool Emitter::emit_flow(const ir::Instruction& ins, size_t) {
  const ir::OpInfo& info = ir::op_info(ins.op);
  if (ins.src.size() < info.num_src) {
    error(ins.loc, "malformed instruction '" + std::string(info.mnemonic) + "'");
    return false;
  }
  if (const auto c = ir::flow::comparison_of(ins.op)) {
    const Id cond = compare(*c, first_component(ins.src[0]), first_component(ins.src[1]), 1);
    if (ins.op >= Opcode::IfGt && ins.op <= Opcode::IfLe) {
      open_if(cond);
      return true;
    }
    return leave_loop(ins, cond);
  }
  switch (ins.op) {
  case Opcode::Break: return leave_loop(ins, 0);
  case Opcode::BreakP: return leave_loop(ins, predicate_component(ins.src[0]));
  case Opcode::Phase: clear_phase_alpha(); return true;
  case Opcode::If: {
    const ir::SrcOperand* p = predicate_operand(ins);
    open_if(p ? predicate_component(*p) : bool_operand(ins.src[0]));
    return true;
  }
  case Opcode::Else: return else_branch(ins);
  case Opcode::EndIf: return end_if(ins);
  case Opcode::Loop: begin_loop(FlowFrame::Kind::Loop, ins.src[1].index); return true;
  case Opcode::Rep: begin_loop(FlowFrame::Kind::Rep, ins.src[0].index); return true;
  case Opcode::EndLoop: return end_loop(ins, FlowFrame::Kind::Loop);
  case Opcode::EndRep: return end_loop(ins, FlowFrame::Kind::Rep);
  case Opcode::Call: b.op(Op::OpFunctionCall, t_void, {label_fn(ins.src[0].index)}); return true;
  case Opcode::CallNz: call_if(ins); return true;
  case Opcode::Ret: end_routine_or_block(); return true;
  case Opcode::Label: return begin_subroutine(ins);
  default: break;
  }
  error(ins.loc, "code generation for '" + std::string(info.mnemonic) + "' is not implemented");
  return false;
}

} // namespace tierlift::codegen
