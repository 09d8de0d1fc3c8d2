// The differential stage: the case drawn by the interpreter and by Vulkan on K generated
// input sets, the two images held to the project's agreement targets (img::judge).
#pragma once

#include <optional>
#include <string>

#include "tierlift/corpus/result.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/ir/program.h"

namespace tierlift::corpus {

// `program` is valid. Its pairing follows `tierlift run`: a vertex listing draws the quad
// with no pixel listing (oD0 passes through), a pixel listing draws it with no vertex
// listing (its inputs constant over the quad). On disagreement `difference` says where.
StageResult differential_run(const ir::Program& program, const std::string& id,
                             const StageOptions& options, std::optional<Difference>& difference);

} // namespace tierlift::corpus
