// Output-register rules (docs/d3d9-rules.md §3.1, §3.5, §6): vs writes oPos and each oT#'s masks
// together are .x/.xy/.xyz/.xyzw (which oT# are written is free: Direct3D pairs oTn with the
// pixel shader's t#/texcoord n by number, so oT1 without oT0 is legal, as fxc writes it);
// ps_2_0 writes oC# and oDepth with a plain mov, each at most once, oC0 always and
// oC0..oC(n-1) with oCn; ps_1_x's output is r0.
#include <map>

#include "context.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

ir::SourceLoc program_loc(const Ctx& c) {
  if (c.prog.version_loc.valid()) return c.prog.version_loc;
  return c.prog.code.empty() ? ir::SourceLoc{} : c.prog.code.front().loc;
}

void check_vertex(Ctx& c) {
  bool pos = false;
  std::map<uint32_t, std::pair<uint8_t, const ir::Instruction*>> tex; // oT# → mask, 1st write
  for (const ir::Instruction& ins : c.prog.code) {
    if (!ins.dst) continue;
    const ir::DstOperand& d = *ins.dst;
    if (d.file == RegFile::RastOut && d.index == ir::kRastPos) pos = true;
    if (d.file == RegFile::TexCrdOut) {
      auto& e = tex[d.index];
      e.first |= ir::written_mask(ins, c.target);
      if (!e.second) e.second = &ins;
    }
  }
  if (!pos)
    c.error(program_loc(c), "output-rule",
            fmt::format("oPos is never written; every {} shader must write it", c.pname()));
  for (auto& [index, e] : tex) {
    uint8_t m = e.first;
    if (m != 0x1 && m != 0x3 && m != 0x7 && m != 0xF)
      c.error(e.second->dst->loc, "output-rule",
              fmt::format("the components written to oT{} together must be .x, .xy, .xyz or "
                          ".xyzw; they are {}",
                          index, mask_name(m)));
  }
}

void check_pixel20(Ctx& c) {
  std::map<uint32_t, const ir::Instruction*> colour;
  const ir::Instruction* depth = nullptr;
  for (const ir::Instruction& ins : c.prog.code) {
    if (!ins.dst) continue;
    const ir::DstOperand& d = *ins.dst;
    if (d.file != RegFile::ColorOut && d.file != RegFile::DepthOut) continue;
    std::string name = reg_name(d.file, d.index);
    if (ins.op != Opcode::Mov) {
      c.error(ins.loc, "output-rule",
              fmt::format("{} can only be written by mov, not {}", name, mnemonic(ins)));
    } else if (!ins.src.empty()) {
      const ir::SrcOperand& s = ins.src[0];
      if (s.mod != ir::SrcMod::None)
        c.error(s.loc, "output-rule", fmt::format("a mov to {} takes no source modifier", name));
      if (d.file == RegFile::ColorOut && s.swizzle != ir::kIdentitySwizzle)
        c.error(s.loc, "output-rule", fmt::format("a mov to {} takes no swizzle", name));
      if (d.file == RegFile::DepthOut && !ir::is_replicate(s.swizzle))
        c.error(s.loc, "output-rule",
                "a mov to oDepth needs a replicate-swizzled source (.x, .y, .z or .w)");
    }
    if (ins.mods.sat)
      c.error(ins.loc, "output-rule", fmt::format("_sat is not allowed on a write to {}", name));
    if (d.file == RegFile::DepthOut) {
      if (depth)
        c.error(
            ins.loc, "output-rule",
            fmt::format("oDepth may be written once; it was written at line {}", depth->loc.line));
      else
        depth = &ins;
      continue;
    }
    auto [it, fresh] = colour.insert({d.index, &ins});
    if (!fresh)
      c.error(ins.loc, "output-rule",
              fmt::format("{} may be written once; it was written at line {}", name,
                          it->second->loc.line));
  }
  if (!colour.count(0))
    c.error(program_loc(c), "output-rule",
            fmt::format("oC0 is never written; every {} shader must write it", c.pname()));
  for (auto& [index, ins] : colour)
    for (uint32_t k = 0; k < index; ++k)
      if (!colour.count(k)) {
        c.error(ins->dst->loc, "output-rule",
                fmt::format("oC{} is written, so every oC below it must be written too; oC{} "
                            "is not",
                            index, k));
        break;
      }
}

// vs_3_0: no fixed outputs; what is written goes to declared o# (rules_decls.cpp). A
// position output is what the rasterizer needs: warn when none is declared or written.
void check_vertex30(Ctx& c) {
  const ir::Declaration* position = nullptr;
  for (const ir::Declaration& d : c.prog.decls)
    if (d.reg.file == RegFile::Output && d.usage == ir::DeclUsage::Position && d.usage_index == 0)
      position = &d;
  if (!position) {
    c.warning(program_loc(c), "output-rule",
              "no output is declared dcl_position: the vertex position is undefined");
    return;
  }
  for (const ir::Instruction& ins : c.prog.code)
    if (ins.dst && ins.dst->file == RegFile::Output &&
        (ins.dst->rel || ins.dst->index == position->reg.index))
      return;
  c.warning(
      position->loc, "output-rule",
      fmt::format("the position output o{} is declared but never written", position->reg.index));
}

// ps_3_0: oC# and oDepth are written by any instruction, any number of times, with any
// mask (the ps_2_0 "one mov" rule is gone); oC0..oC3 and oDepth only.
void check_pixel30(Ctx& c) {
  bool colour = false;
  for (const ir::Instruction& ins : c.prog.code)
    colour = colour || (ins.dst &&
                        (ins.dst->file == RegFile::ColorOut || ins.dst->file == RegFile::DepthOut));
  if (!colour)
    c.warning(program_loc(c), "output-rule",
              "ps_3_0 writes neither oC# nor oDepth: the pixel has no output");
}

void check_pixel1x(Ctx& c) {
  for (const ir::Instruction& ins : c.prog.code)
    if (ins.dst && ins.dst->file == RegFile::Temp && ins.dst->index == 0 &&
        ir::written_mask(ins, c.target) != 0)
      return;
  c.warning(program_loc(c), "output-rule",
            fmt::format("r0 is the output colour of {} but is never written", c.pname()));
}

} // namespace

void check_outputs(Ctx& c) {
  if (c.vs30())
    check_vertex30(c);
  else if (c.ps30())
    check_pixel30(c);
  else if (c.vs())
    check_vertex(c);
  else if (c.ps2up())
    check_pixel20(c);
  else
    check_pixel1x(c);
}

} // namespace tierlift::assembly::detail
