// The listings compiled into tierlift (listings/), parsed and validated for a pass.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "tierlift/ir/program.h"

namespace tierlift::effects {

// "gpugems21/listing2_blur8_weighted_sum.psh", "glow/downsample4.psh", …: the parsed and
// validated program, or nullptr and the rendered diagnostics (or "no such listing").
std::shared_ptr<const ir::Program> builtin_listing(std::string_view path, std::string* error);

} // namespace tierlift::effects
