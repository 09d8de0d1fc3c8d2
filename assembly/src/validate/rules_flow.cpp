// Flow control (docs/d3d9-rules.md §5.3, §14): if/else/endif, loop/endloop and rep/endrep
// nest properly; a label directly follows a ret; aL only inside a loop; loop/rep counters
// within their ranges. vs_2_0: loop/rep nest one deep, calls go forward and do not nest.
// vs_2_0 and vs_2_x: at most 16 static flow-control instructions. 2.x and 3.0: loop/rep nest as
// deep as the caps' static depth, if_comp / if p0 as deep as the dynamic depth, break* only inside
// loop/rep.
#include <map>
#include <vector>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

constexpr int kMaxStaticFlow = 16;

struct Block {
  Opcode op; // If, Loop or Rep (if_comp opens an If block too)
  const ir::Instruction* open;
  bool has_else = false;
  bool dynamic = false; // if_comp, if p0: counts against the dynamic depth
};

bool is_if_comp(Opcode op) {
  return op == Opcode::IfGt || op == Opcode::IfEq || op == Opcode::IfGe || op == Opcode::IfLt ||
         op == Opcode::IfNe || op == Opcode::IfLe;
}
bool is_break(Opcode op) {
  return op == Opcode::Break || op == Opcode::BreakGt || op == Opcode::BreakEq ||
         op == Opcode::BreakGe || op == Opcode::BreakLt || op == Opcode::BreakNe ||
         op == Opcode::BreakLe || op == Opcode::BreakP;
}

const ir::ConstDef* find_int_def(const ir::Program& p, uint32_t index) {
  const ir::ConstDef* last = nullptr; // the last definition wins
  for (const ir::ConstDef& d : p.defs)
    if (d.file == RegFile::ConstInt && d.index == index) last = &d;
  return last;
}

void check_counter(Ctx& c, const ir::Instruction& ins) {
  const ir::SrcOperand* ireg = nullptr;
  for (const ir::SrcOperand& s : ins.src)
    if (s.file == RegFile::ConstInt) ireg = &s;
  if (!ireg) return;
  const ir::ConstDef* d = find_int_def(c.prog, ireg->index);
  if (!d) return; // set by the application: checked at run time
  auto bad = [&](int k, int lo, int hi, const char* what) {
    if (d->i(k) < lo || d->i(k) > hi)
      c.error(ireg->loc, "flow",
              fmt::format("{}.{} = {} is the {} and must be in {}..{}",
                          reg_name(RegFile::ConstInt, ireg->index), "xyzw"[k], d -> i(k), what, lo,
                          hi));
  };
  bad(0, 0, 255, "iteration count");
  if (ins.op == Opcode::Loop) {
    bad(1, 0, 255, "start value of aL");
    bad(2, -128, 127, "step of aL");
    bad(3, 0, 0, "unused w component");
  }
}

bool uses_loop_reg(const ir::Instruction& ins) {
  if (ins.op == Opcode::Loop) return false; // its own aL operand
  for (const ir::SrcOperand& s : ins.src)
    if (s.file == RegFile::Loop || (s.rel && s.rel->file == RegFile::Loop)) return true;
  return false;
}

// What counts against the static flow count (16) of vs_2_0 and vs_2_x, per Microsoft's
// vertex nesting tables: if b# and an else of one, loop, rep, call, callnz b#. The dynamic
// forms (if p0, if_comp, callnz p0) do not count.
bool counts_static_flow(const ir::Instruction& ins, const std::vector<Block>& stack) {
  switch (ins.op) {
  case Opcode::If: return ins.src.empty() || ins.src[0].file != RegFile::Predicate;
  case Opcode::Else:
    return !stack.empty() && stack.back().op == Opcode::If && !stack.back().dynamic;
  case Opcode::Loop:
  case Opcode::Rep:
  case Opcode::Call: return true;
  case Opcode::CallNz: return ins.src.size() < 2 || ins.src[1].file != RegFile::Predicate;
  default: return false;
  }
}

// if b#, if p0.x, if_comp: one more if block. Dynamic ones (p0, comparisons) nest as deep
// as DynamicFlowControlDepth; a device without dynamic flow control has none.
void open_if(Ctx& c, std::vector<Block>& stack, const ir::Instruction& ins, bool dynamic) {
  if (dynamic) {
    int depth = 1;
    for (const Block& b : stack) depth += b.dynamic;
    if (depth > c.caps.dynamic_depth)
      c.error(ins.loc, "flow",
              c.caps.dynamic_depth == 0
                  ? fmt::format("{} is dynamic flow control, which these {} caps do not have "
                                "(DynamicFlowControlDepth 0)",
                                mnemonic(ins), c.pname())
                  : fmt::format("{} allows dynamic flow control nesting depth {}; this {} is at "
                                "depth {}",
                                c.pname(), c.caps.dynamic_depth, mnemonic(ins), depth));
  }
  stack.push_back({Opcode::If, &ins, false, dynamic});
}

// loop / rep: its nesting depth (1 in vs_2_0, the caps' static depth later) and counter.
void open_loop(Ctx& c, std::vector<Block>& stack, const ir::Instruction& ins, bool later) {
  int depth = 1;
  for (const Block& b : stack) depth += b.op != Opcode::If;
  const int allowed = later ? c.caps.static_depth : 1;
  if (depth > allowed)
    c.error(ins.loc, "flow",
            fmt::format("{} allows loop/rep nesting depth {}; this {} is at depth {}", c.pname(),
                        allowed, mnemonic(ins), depth));
  check_counter(c, ins);
  stack.push_back({ins.op, &ins});
}

// endif / endloop / endrep closes the innermost block, which must be of its kind.
void close_block(Ctx& c, std::vector<Block>& stack, const ir::Instruction& ins) {
  const Opcode want = ins.op == Opcode::EndIf     ? Opcode::If
                      : ins.op == Opcode::EndLoop ? Opcode::Loop
                                                  : Opcode::Rep;
  if (!stack.empty() && stack.back().op == want) {
    stack.pop_back();
    return;
  }
  const std::string open =
      stack.empty() ? std::string("no block is open")
                    : fmt::format("the innermost open block is {} at line {}",
                                  mnemonic(*stack.back().open), stack.back().open->loc.line);
  c.error(ins.loc, "flow", fmt::format("{} does not match: {}", mnemonic(ins), open));
}

// A label starts a subroutine: right after a ret, outside every block, defined once.
void check_label(Ctx& c, size_t i, const std::vector<Block>& stack,
                 std::map<uint32_t, size_t>& labels) {
  const auto& code = c.prog.code;
  const ir::Instruction& ins = code[i];
  if (i == 0 || code[i - 1].op != Opcode::Ret)
    c.error(ins.loc, "flow", "label must directly follow a ret");
  if (!stack.empty()) c.error(ins.loc, "flow", "label inside an open if/loop/rep block");
  if (!ins.src.empty() && ins.src[0].file == RegFile::Label &&
      !labels.insert({ins.src[0].index, i}).second)
    c.error(ins.src[0].loc, "flow", fmt::format("label l{} is defined twice", ins.src[0].index));
}

// Every call names a defined label; vs_2_0 calls forward only.
void check_call_targets(Ctx& c, const std::vector<size_t>& calls,
                        const std::map<uint32_t, size_t>& labels, bool later) {
  const auto& code = c.prog.code;
  for (size_t i : calls) {
    const ir::Instruction& call = code[i];
    if (call.src.empty() || call.src[0].file != RegFile::Label) continue;
    auto it = labels.find(call.src[0].index);
    if (it == labels.end())
      c.error(call.src[0].loc, "flow", fmt::format("label l{} is not defined", call.src[0].index));
    else if (it->second < i && !later)
      c.error(call.src[0].loc, "flow",
              fmt::format("vs_2_0 only allows forward calls: label l{} is at line {}, before "
                          "this call",
                          call.src[0].index, code[it->second].loc.line));
  }
}

} // namespace

void check_flow(Ctx& c) {
  const bool later = ir::has_predication(c.target); // 2.x, 3.0
  if (!c.vs20() && !later) return;
  const auto& code = c.prog.code;
  std::vector<Block> stack;
  std::map<uint32_t, size_t> labels; // label index → position
  std::vector<size_t> calls;
  bool in_sub = false;
  int flow_count = 0;
  // The static flow count of Microsoft's vertex nesting tables: vs_2_0 and vs_2_x only.
  const bool counted_flow = c.vs20() || c.target == ir::Profile::vs_2_x;
  auto loops_open = [&]() {
    for (const Block& b : stack)
      if (b.op != Opcode::If) return true;
    return false;
  };
  for (size_t i = 0; i < code.size(); ++i) {
    const ir::Instruction& ins = code[i];
    if (counted_flow && counts_static_flow(ins, stack) && ++flow_count == kMaxStaticFlow + 1)
      c.error(ins.loc, "flow",
              fmt::format("{} allows {} static flow-control instructions (if b#, its else, "
                          "loop, rep, call, callnz b#); this is the {}",
                          c.pname(), kMaxStaticFlow, ordinal(kMaxStaticFlow + 1)));
    if (uses_loop_reg(ins) && !in_sub) {
      bool in_loop = false;
      for (const Block& b : stack) in_loop = in_loop || b.op == Opcode::Loop;
      if (!in_loop) c.error(ins.loc, "flow", "aL is only valid inside a loop ... endloop block");
    }
    if (is_if_comp(ins.op)) {
      open_if(c, stack, ins, true);
      continue;
    }
    if (is_break(ins.op)) {
      if (!loops_open())
        c.error(ins.loc, "flow", fmt::format("{} outside loop/rep", mnemonic(ins)));
      if (ins.op != Opcode::Break && c.caps.dynamic_depth == 0)
        c.error(ins.loc, "flow",
                fmt::format("{} is dynamic flow control, which these {} caps do not have "
                            "(DynamicFlowControlDepth 0)",
                            mnemonic(ins), c.pname()));
      continue;
    }
    switch (ins.op) {
    case Opcode::If:
      open_if(c, stack, ins, !ins.src.empty() && ins.src[0].file == RegFile::Predicate);
      break;
    case Opcode::Loop:
    case Opcode::Rep: open_loop(c, stack, ins, later); break;
    case Opcode::Else:
      if (stack.empty() || stack.back().op != Opcode::If || stack.back().has_else)
        c.error(ins.loc, "flow", "else without a matching if");
      else
        stack.back().has_else = true;
      break;
    case Opcode::EndIf:
    case Opcode::EndLoop:
    case Opcode::EndRep: close_block(c, stack, ins); break;
    case Opcode::Call:
    case Opcode::CallNz:
      if (later && c.caps.static_depth == 0)
        c.error(ins.loc, "flow",
                fmt::format("{} is static flow control, which these {} caps do not have "
                            "(StaticFlowControlDepth 0)",
                            mnemonic(ins), c.pname()));
      if (in_sub && !later)
        c.error(ins.loc, "flow", "vs_2_0 allows call nesting depth 1: no call inside a subroutine");
      calls.push_back(i);
      break;
    case Opcode::Label:
      check_label(c, i, stack, labels);
      in_sub = true;
      break;
    case Opcode::Ret:
      if (stack.empty() && i + 1 < code.size() && code[i + 1].op != Opcode::Label)
        c.error(code[i + 1].loc, "flow",
                "code after ret is unreachable: it must start a subroutine with label");
      break;
    default: break;
    }
  }
  for (const Block& b : stack)
    c.error(b.open->loc, "flow",
            fmt::format("{} is never closed by {}", mnemonic(*b.open),
                        b.op == Opcode::If     ? "endif"
                        : b.op == Opcode::Loop ? "endloop"
                                               : "endrep"));
  if (in_sub && code.back().op != Opcode::Ret)
    c.error(code.back().loc, "flow", "a subroutine must end with ret");
  check_call_targets(c, calls, labels, later);
}

} // namespace tierlift::assembly::detail
