// The listings compiled into tierlift (listings/), parsed and validated for a pass.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "tierlift/ir/program.h"

namespace tierlift::effects {

// "gpugems21/listing2_blur8_weighted_sum.psh", "glow/downsample4.psh", …: the parsed and
// validated program, or nullptr and the rendered diagnostics (or "no such listing").
std::shared_ptr<const ir::Program> builtin_listing(std::string_view path, std::string* error);

// The listing a glow pass uses: `files`' entry for `path` when there is one (read from
// disk, parsed and validated; errors carry file:line:col and the caret), else the built-in.
std::shared_ptr<const ir::Program>
glow_listing(std::string_view path, const std::map<std::string, std::string, std::less<>>& files,
             std::string* error);

} // namespace tierlift::effects
