// The profile rules of docs/d3d9-rules.md §6, checked on an ir::Program. Each message names the
// rule and the limit ("ps_1_3 allows 8 arithmetic slots; this instruction is the 9th").
//
// Every problem is reported in one run through the sink, with the offending operand's
// position (or the instruction's), and a short rule id:
//   not-in-profile    the instruction (table row) does not exist in the target profile
//   operand-kind      wrong register file for an operand position (s#, b#, i#, l#, aL, c#, r#)
//   register-file     the register file does not exist in the profile (oC0 in vs_1_1)
//   register-range    index out of range (r2 in ps_1_1); warning for vertex c# past the
//                     guaranteed count (a device cap)
//   register-access   read of a write-only or write of a read-only register
//   read-port         too many distinct registers of one file per instruction / co-issued pair
//   relative-address  c[a0.x + n] / c[aL + n] where it is not allowed
//   read-before-write a register component read before anything wrote it
//   dependent-read    ps_2_0 texture-read chain deeper than 4
//   slot-limit        instruction, texture or arithmetic slots (and cmp/dp4 counts)
//   order             dcl/def after code; texture instructions after arithmetic (ps_1_x)
//   phase             ps_1_4 phase rules
//   declaration       missing, duplicate or ill-formed dcl; reads outside a dcl mask
//   definition        (warning) a constant defined twice, or outside ps_1_x's [-1, 1]
//   unused-input      (warning) a declared input never read
//   modifier          instruction and source modifiers
//   swizzle           source swizzles and selectors
//   write-mask        destination masks
//   instruction-rule  operand rules of one instruction (cnd r0.a, cmp/crs/nrm aliasing, ...)
//   macro-alias       matrix-macro destination overlapping a source
//   coissue           "+" pairing rules (ps_1_x)
//   texture-op        ps_1_1–1_3 texture-address rules (m > n, pad rows, texbem reuse)
//   flow              vs_2_0 static flow control
//   output-rule       oPos, oT#, oC#, oDepth rules; (warning) ps_1_x r0 never written
#pragma once

#include <optional>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"

namespace tierlift::assembly {

// What the Direct3D 8/9 runtimes accepted beyond the documented rules, rewritten to what
// Windows executed, each with a warning that names the rule (NUMERICS.md, "Windows
// leniency"). Run it before validate() unless the user asked for --strict:
//   swizzle     a scalar source (rcp, rsq, exp, log, expp, logp, pow) with the identity
//               swizzle, as D3D8-era token streams carry it: read as .w
//   write-mask  ps_1_4 texcrd with no write mask: kept full, as D3DAssemble writes it;
//               it defines .xyz (.xy with _dw)
// Returns the number of rewrites (= warnings added).
size_t apply_windows_leniency(ir::Program& program, ir::Profile target, ir::DiagnosticSink& diags);

struct ValidateOptions {
  bool warnings = true; // legal-but-suspicious code (unread declared input, def twice, ...)
  // The 2.x features of the device (temps, slots, flow-control depths, predication,
  // gradients, arbitrary swizzles, dependent reads); unset: ir::default_caps(target).
  std::optional<ir::Caps2x> caps;
  // apply_windows_leniency ran: take the forms it reports but keeps as written (ps_1_4
  // texcrd with the full mask), and a def after the first instruction (a warning, rule
  // "order", as shipped listings have it).
  bool windows_leniency = false;
};

// Checks `program` against `target` (normally program.profile; --profile may name another).
// Returns true when no error was reported.
bool validate(const ir::Program& program, ir::Profile target, ir::DiagnosticSink& diags,
              const ValidateOptions& options = {});
inline bool validate(const ir::Program& program, ir::DiagnosticSink& diags) {
  return validate(program, program.profile, diags);
}

} // namespace tierlift::assembly
