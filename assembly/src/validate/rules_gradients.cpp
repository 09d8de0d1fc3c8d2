// Gradients in flow control that may differ between the four pixels of a 2x2 quad (rule
// `gradient-in-divergent-flow`, a warning, as fxc warns). dsx and dsy read the neighbouring
// pixels' values; where a branch or a loop exit can go one way in one pixel and another way in
// its neighbour, those values are undefined in Direct3D 9 and in Vulkan (NUMERICS.md rule F8).
// Flow that differs per pixel: if_comp and if p0 blocks, and loops or reps that a pixel can
// leave by itself (break_comp, breakp, or a break inside such an if). Flow on constants (if b#,
// loop i#, rep i#, call, callnz b#) is the same for every pixel of a draw. texld, texldp and
// texldb take gradients too: their implicit level of detail comes from the coordinate's
// differences across the quad (NUMERICS.md M5), so they warn alike; texldl and texldd, whose
// lod or gradients are given, do not.
#include <vector>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;

bool dynamic_if(const ir::Instruction& ins) {
  if (ins.op >= Opcode::IfGt && ins.op <= Opcode::IfLe) return true;
  return ins.op == Opcode::If && !ins.src.empty() && ins.src[0].file == ir::RegFile::Predicate;
}
bool dynamic_break(Opcode op) {
  return op == Opcode::BreakP || (op >= Opcode::BreakGt && op <= Opcode::BreakLe);
}
bool opens_loop(Opcode op) {
  return op == Opcode::Loop || op == Opcode::Rep;
}
bool closes_loop(Opcode op) {
  return op == Opcode::EndLoop || op == Opcode::EndRep;
}
bool opens_if(const ir::Instruction& ins) {
  return ins.op == Opcode::If || dynamic_if(ins);
}
// A read whose level of detail comes from its coordinate's gradients.
bool implicit_lod(Opcode op) {
  return op == Opcode::TexLd || op == Opcode::TexLdP || op == Opcode::TexLdB;
}

// For every loop or rep (by its index in code): whether a pixel can leave it by itself.
std::vector<bool> divergent_loops(const std::vector<ir::Instruction>& code) {
  std::vector<bool> divergent(code.size(), false);
  std::vector<size_t> loops;     // open loops
  std::vector<size_t> dyn_depth; // per open loop: dynamic ifs opened inside it and still open
  std::vector<bool> if_dynamic;  // open ifs: dynamic or not
  for (size_t i = 0; i < code.size(); ++i) {
    const ir::Instruction& ins = code[i];
    if (opens_loop(ins.op)) {
      loops.push_back(i);
      dyn_depth.push_back(0);
    } else if (closes_loop(ins.op) && !loops.empty()) {
      loops.pop_back();
      dyn_depth.pop_back();
    } else if (opens_if(ins)) {
      if_dynamic.push_back(dynamic_if(ins));
      if (!loops.empty() && if_dynamic.back()) ++dyn_depth.back();
    } else if (ins.op == Opcode::EndIf && !if_dynamic.empty()) {
      if (!loops.empty() && if_dynamic.back() && dyn_depth.back() > 0) --dyn_depth.back();
      if_dynamic.pop_back();
    } else if (!loops.empty() &&
               (dynamic_break(ins.op) || (ins.op == Opcode::Break && dyn_depth.back() > 0))) {
      divergent[loops.back()] = true;
    }
  }
  return divergent;
}

} // namespace

void check_gradients(Ctx& c) {
  if (c.vs()) return;
  const std::vector<ir::Instruction>& code = c.prog.code;
  const std::vector<bool> divergent = divergent_loops(code);
  std::vector<size_t> open; // ifs and loops, innermost last
  for (size_t i = 0; i < code.size(); ++i) {
    const ir::Instruction& ins = code[i];
    if (opens_if(ins) || opens_loop(ins.op)) {
      open.push_back(i);
    } else if ((ins.op == Opcode::EndIf || closes_loop(ins.op)) && !open.empty()) {
      open.pop_back();
    } else if (ins.op == Opcode::Dsx || ins.op == Opcode::Dsy || implicit_lod(ins.op)) {
      for (auto it = open.rbegin(); it != open.rend(); ++it) {
        const ir::Instruction& block = code[*it];
        if (!(opens_loop(block.op) ? divergent[*it] : dynamic_if(block))) continue;
        const char* where = opens_loop(block.op) ? "loop" : "branch";
        const std::string advice =
            implicit_lod(ins.op)
                ? fmt::format("its level of detail (a mip chain's level) is then undefined on a "
                              "GPU; sample before the {}, or give the lod (texldl) or the "
                              "gradients (texldd)",
                              where)
                : fmt::format("the neighbours' values it takes are then undefined on a GPU; take "
                              "the gradient before the {}",
                              where);
        c.warning(ins.loc, "gradient-in-divergent-flow",
                  fmt::format("{} inside the {} of line {}, whose flow may differ between the "
                              "pixels of a 2x2 quad: {}",
                              mnemonic(ins), mnemonic(block), block.loc.line, advice));
        break;
      }
    }
  }
}

} // namespace tierlift::assembly::detail
