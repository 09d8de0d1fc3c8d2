// Public entry points: compile one program, or a VS/PS pair with link-time pruning
// (pruning.cpp decides what to leave out; the Emitter writes the module).
#include "tierlift/codegen/codegen.h"

#include "tierlift/codegen/emitter.h"

namespace tierlift::codegen {

std::optional<ShaderModule> compile(const ir::Program& program, const CodegenOptions& options,
                                    ir::DiagnosticSink& diags) {
  EmitPlan plan;
  Emitter emitter(program, options, plan, diags);
  return emitter.run();
}

} // namespace tierlift::codegen
