// Public entry points: compile one program, or a VS/PS pair with link-time pruning
// (pruning.cpp decides what to leave out; the Emitter writes the module).
#include "tierlift/codegen/codegen.h"

#include "tierlift/codegen/emitter.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/result_diagnostics.h"
#include "tierlift/ir/sm3_interface.h"

namespace tierlift::codegen {

std::optional<ShaderModule> compile(const ir::Program& program, const CodegenOptions& options,
                                    ir::DiagnosticSink& diags) {
  // The structural checks every backend runs first (ir/passes.h): a program the emitter
  // could only misread is refused with positioned "ir" errors instead.
  if (ir::Status s = ir::validate_ir(program); !s) {
    ir::add_all(diags, s.diagnostics());
    return std::nullopt;
  }
  if (ir::Status s = ir::check_executable(program, "SPIR-V"); !s) {
    ir::add_all(diags, s.diagnostics());
    return std::nullopt;
  }
  EmitPlan plan;
  plan.relative_inputs = ir::relative_input_links(program);
  plan.relative_outputs = ir::relative_output_links(program);
  plan.saturate_color_outputs = ir::saturates_colors(program.profile);
  // Shader model 3's o#/v# become the 2.0 registers of their semantics (sm3_interface.h).
  const ir::Program linked = ir::link_by_semantic(program);
  Emitter emitter(linked, options, plan, diags);
  return emitter.run();
}

} // namespace tierlift::codegen
