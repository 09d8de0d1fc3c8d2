// What the Direct3D 8/9 runtimes accepted beyond the documented rules, applied to the IR
// before validation (validator.h, apply_windows_leniency). Each rewrite makes the program
// say what Windows executed, so that the validator, the interpreter, the SPIR-V codegen and
// the printer all see one meaning; each is reported as a warning that names the rule.
// Sources (NUMERICS.md, "Windows leniency"): the D3D8-era token streams of Wine's d3d8/d3d9
// tests, wined3d's scalar-operation loads, the ps_1_4 texcrd/texld pages.
#include <fmt/format.h>

#include "context.h"

namespace tierlift::assembly {
namespace {

using ir::Opcode;
using ir::OperandKind;

// A scalar source (rcp, rsq, exp, log, expp, logp, pow) with the identity swizzle: the
// runtime took the stream, and the operation read the swizzle's 4th slot, .w — the rule the
// interpreter and codegen already apply to every scalar source. The IR gets the .w
// replicate, so that printing and re-reading keeps the meaning (a bare "rcp r0, c0" in text
// would read .x, the assembler's rule for text).
void scalar_sources(ir::Instruction& ins, ir::DiagnosticSink& diags) {
  const ir::OpInfo& info = ir::op_info(ins.op);
  for (size_t k = 0; k < ins.src.size() && k < info.num_src; ++k) {
    ir::SrcOperand& s = ins.src[k];
    if (info.src[k] != OperandKind::Scalar || s.swizzle != ir::kIdentitySwizzle) continue;
    s.swizzle = ir::replicate_swizzle(ir::swizzle_component(s.swizzle, 3));
    diags.warning(s.loc, "swizzle",
                  fmt::format("source {} of {} is a scalar and has no replicate swizzle; read "
                              "as {}.w, the component Direct3D used (--strict rejects it)",
                              k + 1, info.mnemonic, ir::register_name(s.file, s.index)));
  }
}

// ps_1_4 texcrd with no write mask: Microsoft's assembler took it and wrote the full mask
// into the stream (0x800F0000 for "texcrd r0, t0", as Wine's d3dcompiler tests record it),
// and the runtime ran it. The mask stays as written, so the bytes are D3DAssemble's; what
// the instruction defines is .rgb (.rg with _dw), which ir::written_mask already says, and
// the validator takes the full mask once this leniency applies (ValidateOptions).
void texcrd_mask(const ir::Instruction& ins, ir::DiagnosticSink& diags) {
  if (ins.op != Opcode::TexCrd || !ins.dst || ins.dst->mask != ir::kFullMask) return;
  bool dw = !ins.src.empty() && ins.src[0].mod == ir::SrcMod::Dw;
  diags.warning(ins.dst->loc, "write-mask",
                fmt::format("texcrd with the full write mask defines {} only; the 4th channel{} "
                            "is left undefined (Microsoft's assembler writes it when no mask is "
                            "given, and tierlift keeps the full mask; --strict rejects it)",
                            dw ? ".rg (.xy)" : ".rgb (.xyz)", dw ? " and the 3rd" : ""));
}

} // namespace

size_t apply_windows_leniency(ir::Program& program, ir::Profile target, ir::DiagnosticSink& diags) {
  size_t before = diags.warning_count();
  for (ir::Instruction& ins : program.code) {
    scalar_sources(ins, diags);
    if (target == ir::Profile::ps_1_4) texcrd_mask(ins, diags);
  }
  return diags.warning_count() - before;
}

} // namespace tierlift::assembly
