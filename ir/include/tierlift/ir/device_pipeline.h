// The IR pipeline a device runs on a pixel program before it draws it, in one place: every
// device calls prepare_for_device, so what is done to a program between the loader and a
// device reads here, in order, the way a pass manager lists its passes.
//
//   1. specialise for the bound constants: products with a ±0 constant factor
//      (zero_constant_products, passes.h);
//   2. drop dead instructions (dead_instructions on pixel_live_out, liveness.h): what fed
//      only those products becomes nop — for a device that does not prune on its own (the
//      code generator prunes the same instructions while it emits, codegen/pruning.cpp);
//   3. validate the result (validate_ir), a failure naming the step (run_pass).
// A program step 1 leaves alone is not copied (specialised = nullopt).
#pragma once

#include <array>
#include <optional>
#include <span>

#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::ir {

struct DevicePipelineOptions {
  bool drop_dead = true; // step 2 (false: the device's own pruning does it)
};

struct DeviceProgram {
  std::optional<Program> specialised; // nullopt: nothing rewritten, run the input as it is
};

Result<DeviceProgram> prepare_for_device(const Program& pixel_program,
                                         std::span<const std::array<float, 4>> bound_constants,
                                         const DevicePipelineOptions& options = {});

} // namespace tierlift::ir
