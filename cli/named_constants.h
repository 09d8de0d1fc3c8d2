// `run --const NAME=…`: a constant named by the CTAB of a token-stream listing becomes the
// register settings it covers ("g_mWorld=16 numbers" → c4..c7).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tierlift/asm/constant_table.h"
#include "tierlift/ir/result.h"

namespace tierlift::cli {

// Rewrites every setting whose name is not a register (cN, iN, bN) through the constant
// tables of the vertex and pixel listings (either may be null); a "vs:"/"ps:" prefix picks
// the table. A matrix or array takes 4 numbers per register, in register order. Fails (rule
// "usage") when a name is in neither table or the value does not fit.
ir::Result<std::vector<std::string>>
resolve_named_constants(const std::vector<std::string>& settings, const as::ConstantTable* vs,
                        const as::ConstantTable* ps);

} // namespace tierlift::cli
