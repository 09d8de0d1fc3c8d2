// NUMERICS.md rule 38: pixels the differential stage does not compare because Direct3D 9
// leaves their value undefined: the pixel program samples a texture at a coordinate that is
// not finite (±inf or NaN in a component the sampler addresses, after texldp's divide).
#pragma once

#include <string>

#include "tierlift/pass/pass.h"

namespace tierlift::corpus {

// Whether the interpreter, running the pass's pixel program at its constant inputs (a pass
// with neither a vertex program nor transformed vertices: every pixel runs those inputs),
// samples a texture at a non-finite coordinate. Returns the first such read as text
// ("s2 at (inf, nan)"), or "" when there is none or the pass interpolates its inputs (the
// rule then excludes nothing).
std::string non_finite_read(const pass::Pass& pass);

} // namespace tierlift::corpus
