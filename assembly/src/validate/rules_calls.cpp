// Call nesting in the 2.x and 3.0 profiles (docs/d3d9-rules.md §14.4): a call made from main
// is at depth 1, a call made inside that subroutine at depth 2, and so on along every chain
// of calls. Microsoft's flow-control tables allow StaticFlowControlDepth levels in vs_2_x and
// ps_2_x (independently of the loop/rep limit) and 4 in vs_3_0 and ps_3_0 (the 3.0 caps'
// static depth). A chain that comes back to a subroutine already on it (recursion) has no
// bound at all. vs_2_0 (depth 1: no call inside a subroutine) is checked in rules_flow.cpp.
#include <map>
#include <set>
#include <vector>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

struct Routine {
  std::string name; // "main", "l3"
  std::vector<const ir::Instruction*> calls;
};

bool is_call(const ir::Instruction& ins) {
  return (ins.op == Opcode::Call || ins.op == Opcode::CallNz) && !ins.src.empty() &&
         ins.src[0].file == RegFile::Label;
}

class CallWalk {
public:
  explicit CallWalk(Ctx& c) : c_(c) { split(); }

  void run() {
    reached_.assign(routines_.size(), -1);
    on_chain_.assign(routines_.size(), false);
    chain_.push_back(0);
    on_chain_[0] = true;
    walk(0, 0);
  }

private:
  // Main is routine 0 (the code before the first label); every label starts another.
  void split() {
    routines_.push_back({"main", {}});
    for (const ir::Instruction& ins : c_.prog.code) {
      if (ins.op == Opcode::Label && !ins.src.empty() && ins.src[0].file == RegFile::Label) {
        // A label defined twice is reported by rules_flow.cpp; the first one is called.
        by_label_.emplace(ins.src[0].index, routines_.size());
        routines_.push_back({reg_name(RegFile::Label, ins.src[0].index), {}});
        continue;
      }
      if (is_call(ins)) routines_.back().calls.push_back(&ins);
    }
  }

  std::string chain_text(size_t last) const {
    std::string out;
    for (size_t r : chain_) out += routines_[r].name + " -> ";
    return out + routines_[last].name;
  }

  // Depth-first along the calls, walking a routine again only when it is reached deeper than
  // before: at most limit + 1 visits per routine, whatever the shape of the call graph.
  void walk(size_t routine, int depth) {
    const int limit = c_.caps.static_depth;
    for (const ir::Instruction* call : routines_[routine].calls) {
      auto target = by_label_.find(call->src[0].index);
      if (target == by_label_.end()) continue; // an undefined label: rules_flow.cpp
      const size_t callee = target->second;
      const int at = depth + 1;
      if (on_chain_[callee]) {
        report(call, fmt::format("{} calls {} again ({}): recursion has no bounded call "
                                 "nesting depth, and {} allows {}",
                                 routines_[routine].name, routines_[callee].name,
                                 chain_text(callee), c_.pname(), limit));
        continue;
      }
      if (at > limit) {
        report(call, fmt::format("{} allows call nesting depth {}; this call is at depth {} ({})",
                                 c_.pname(), limit, at, chain_text(callee)));
        continue;
      }
      if (at <= reached_[callee]) continue;
      reached_[callee] = at;
      chain_.push_back(callee);
      on_chain_[callee] = true;
      walk(callee, at);
      on_chain_[callee] = false;
      chain_.pop_back();
    }
  }

  void report(const ir::Instruction* call, std::string message) {
    if (reported_.insert(call).second) c_.error(call->loc, "call-nesting", std::move(message));
  }

  Ctx& c_;
  std::vector<Routine> routines_;
  std::map<uint32_t, size_t> by_label_;
  std::vector<int> reached_;
  std::vector<bool> on_chain_;
  std::vector<size_t> chain_;
  std::set<const ir::Instruction*> reported_;
};

} // namespace

void check_call_nesting(Ctx& c) {
  // No calls at all without static flow control: rules_flow.cpp says so at each call.
  if (!ir::has_predication(c.target) || c.caps.static_depth == 0) return;
  CallWalk(c).run();
}

} // namespace tierlift::assembly::detail
