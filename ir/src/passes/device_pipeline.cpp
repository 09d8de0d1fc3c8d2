#include "tierlift/ir/device_pipeline.h"

#include "tierlift/ir/liveness.h"
#include "tierlift/ir/passes.h"

namespace tierlift::ir {
namespace {

// Step 2: every instruction whose result no output reads becomes nop.
void drop_dead_instructions(Program& program) {
  const std::vector<bool> dead = dead_instructions(program, pixel_live_out(program));
  for (size_t i = 0; i < program.code.size(); ++i)
    if (dead[i]) {
      Instruction& ins = program.code[i];
      ins.op = Opcode::Nop;
      ins.dst.reset();
      ins.src.clear();
      ins.mods = {};
      ins.coissue = false;
    }
}

} // namespace

Result<DeviceProgram> prepare_for_device(const Program& pixel_program,
                                         std::span<const std::array<float, 4>> bound_constants,
                                         const DevicePipelineOptions& options) {
  Program copy = pixel_program;
  // Step 1. Nothing rewritten: the loader's validated program is run as it is.
  if (zero_constant_products(copy, bound_constants) == 0) return DeviceProgram{};
  // Steps 2 and 3.
  Result<Program> out =
      run_pass(std::move(copy), "specialising for the bound constants", [&](Program& p) {
        if (options.drop_dead) drop_dead_instructions(p);
      });
  if (!out) return out.failure();
  return DeviceProgram{std::move(*out)};
}

} // namespace tierlift::ir
