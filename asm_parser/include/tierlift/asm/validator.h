// The profile rules of d3d9-isa.md §6, checked on an ir::Program. Each message names the
// rule and the limit ("ps_1_3 allows 8 arithmetic slots; this instruction is the 9th").
#pragma once

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"

namespace tierlift::as {

struct ValidateOptions {
  bool warnings = true;  // legal-but-suspicious code (unread declared input, def twice, ...)
};

// Checks `program` against `target` (normally program.profile; --profile may name another).
// Returns true when no error was reported.
bool validate(const ir::Program& program, ir::Profile target, ir::DiagnosticSink& diags,
              const ValidateOptions& options = {});
inline bool validate(const ir::Program& program, ir::DiagnosticSink& diags) {
  return validate(program, program.profile, diags);
}

}  // namespace tierlift::as
