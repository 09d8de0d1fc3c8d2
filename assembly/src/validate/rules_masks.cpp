// Destination write masks: which masks a profile allows, and the masks particular
// instructions require (docs/d3d9-rules.md §4.4, §3.1, §3.5).
#include "context.h"
#include "registers_util.h"

namespace tierlift::assembly::detail {
namespace {

using ir::Opcode;
using ir::RegFile;

constexpr uint8_t X = 1, Y = 2, Z = 4, W = 8, XY = 3, XYZ = 7, FULL = 0xF;

bool one_component(uint8_t m) {
  return m == X || m == Y || m == Z || m == W;
}

// The instruction-specific mask rule, or "" when the mask is fine.
std::string instruction_rule(const Ctx& c, const ir::Instruction& ins, uint8_t m) {
  std::string_view mn = mnemonic(ins);
  std::string got = mask_name(m);
  switch (ins.op) {
  // m3x2/m3x3/m4x3: the pages require .xy / .xyz; a bare destination is accepted too
  // because D3DX assembled it (Irrlicht ships `m3x3 r5, v4, c0`) and the macro then writes
  // only its own components (DXVK and wined3d clip the same way).
  case Opcode::M3x2:
    return (m == XY || m == FULL)
               ? ""
               : fmt::format("m3x2 writes .xy; its mask must be .xy, not {}", got);
  case Opcode::M3x3:
  case Opcode::M4x3:
    return (m == XYZ || m == FULL)
               ? ""
               : fmt::format("{} writes .xyz; its mask must be .xyz, not {}", mn, got);
  // m3x4/m4x4: the instruction pages' full mask (the VS masking page's .xyz is a doc
  // conflict; the instruction pages win).
  case Opcode::M3x4:
  case Opcode::M4x4:
    return m == FULL
               ? ""
               : fmt::format("{} writes all four components; it takes no mask, not {}", mn, got);
  // sincos: .x, .y or .xy (instruction pages; the masking page's .xyz is a doc conflict).
  case Opcode::SinCos:
  case Opcode::SinCos3:
    return (m == X || m == Y || m == XY) ? ""
                                         : fmt::format("sincos writes .x, .y or .xy, not {}", got);
  // frc in vs_1_1: .y or .xy (instruction page and MojoShader; doc conflict with the masking
  // page's .x/.y/.xy).
  case Opcode::Frc:
    if (c.vs11() && m != Y && m != XY)
      return fmt::format("frc in vs_1_1 writes .y or .xy only, not {}", got);
    return {};
  case Opcode::Crs:
    return (m & W) == 0 ? "" : fmt::format("crs writes a subset of .xyz, not {}", got);
  case Opcode::Dp3:
    if (c.ps11_13() && m != XYZ && m != FULL)
      return fmt::format("dp3 in {} writes .rgb or .rgba, not {}", c.pname(), got);
    return {};
  case Opcode::Bem: return m == XY ? "" : fmt::format("bem writes .rg (.xy) only, not {}", got);
  // texcrd forms (docs/d3d9-rules.md §4.5): rM.rgb from tN[.xyz|.xyw], rM.rg from tN_dw.xyw.
  case Opcode::TexCrd: {
    bool dw = !ins.src.empty() && ins.src[0].mod == ir::SrcMod::Dw;
    if (m == FULL && c.opt.windows_leniency) return {}; // D3DAssemble's spelling, warned about
    if (dw) return m == XY ? "" : fmt::format("texcrd with _dw writes .rg (.xy), not {}", got);
    return m == XYZ ? "" : fmt::format("texcrd writes .rgb (.xyz), not {}", got);
  }
  // Scalar operations (rcp, rsq, exp, log, expp, logp, pow): the VS masking page asks for one
  // component, other pages replicate into every written one (doc conflict); like the
  // translators, any mask is accepted.
  default: break;
  }
  // 3.0 texture instructions write through any mask (fxc writes texld r0.xyz).
  if (is_texture_op(ins) && m != FULL && !c.sm3())
    return fmt::format("{} takes no destination mask, not {}", mn, got);
  return {};
}

// The register-specific rule (outputs, a0), or "".
std::string register_rule(const Ctx& c, const ir::DstOperand& d) {
  std::string got = mask_name(d.mask);
  switch (d.file) {
  case RegFile::Addr:
    if (c.vs11() && d.mask != X)
      return fmt::format("vs_1_1's a0 has only .x; write a0.x, not a0{}", got);
    return {};
  // oFog/oPts are scalars: the masking page asks for one component, the PS page for none
  // (doc conflict); like MojoShader, any single component or none is taken.
  case RegFile::RastOut:
    if (d.index != ir::kRastPos && d.mask != FULL && !one_component(d.mask))
      return fmt::format("{} is a scalar: write one component or none, not {}",
                         reg_name(d.file, d.index), got);
    return {};
  case RegFile::ColorOut:
    if (c.ps30()) return {}; // ps_3_0 writes oC# component by component
    [[fallthrough]];
  case RegFile::DepthOut:
    return d.mask == FULL
               ? ""
               : fmt::format("{} takes no write mask, not {}", reg_name(d.file, d.index), got);
  default: return {};
  }
}

} // namespace

void check_masks(Ctx& c) {
  for (const ir::Instruction& ins : c.prog.code) {
    if (!ins.dst) continue;
    const ir::DstOperand& d = *ins.dst;
    const uint8_t m = d.mask;
    if (m == 0 || m > FULL) {
      c.error(d.loc, "write-mask", "the write mask is empty");
      continue;
    }
    // ps_1_1–1_3 arithmetic: the vector pipe (.rgb), the scalar pipe (.a) or both.
    if (c.ps11_13() && is_arith_op(ins) && m != FULL && m != XYZ && m != W) {
      c.error(d.loc, "write-mask",
              fmt::format("{} allows the masks .rgba, .rgb and .a only, not {}", c.pname(),
                          mask_name(m)));
      continue;
    }
    std::string p = instruction_rule(c, ins, m);
    if (p.empty()) p = register_rule(c, d);
    if (!p.empty()) c.error(d.loc, "write-mask", p);
  }
}

} // namespace tierlift::assembly::detail
