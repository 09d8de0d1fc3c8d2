// NUMERICS.md rule 38: pixels the differential stage does not compare because Direct3D 9
// leaves their value undefined: the pixel program samples a texture at a coordinate that is
// not finite (±inf or NaN in a component the sampler addresses, after texldp's divide), or a
// dcl_cube sampler in direction (0, 0, 0) (NUMERICS.md rule T7).
#pragma once

#include <string>

#include "tierlift/pass/pass.h"

namespace tierlift::corpus {

// Whether the interpreter, running the pass's pixel program at its constant inputs (a pass
// with neither a vertex program nor transformed vertices: every pixel runs those inputs),
// samples a texture at a non-finite coordinate. Returns the first such read as text
// ("s2 at (inf, nan)"), or "" when there is none or the pass interpolates its inputs (the
// rule then excludes nothing). A pass of a vertex program alone (the corpus runner's) is
// checked the same way at each of its vertices: its texldl reads of the vertex samplers
// ("vertex s0 at (nan, 1)").
std::string non_finite_read(const pass::Pass& pass);

// The second case of the rule: `sincos` of an argument outside [−π, π] (Direct3D 9 defines it
// there only). The interpreter runs a copy of the pass's one program (a pixel program at its
// constant inputs, or a vertex program at each of its vertices) that also records the largest
// |argument| of every sincos it runs, in a temporary and an output the program leaves unused.
// Returns "sincos of 3.40282347e+38" (the largest, NaN shown as nan), or "" when every
// argument is in range or the copy cannot be made (no spare temporary or output, subroutines).
std::string sincos_out_of_range(const pass::Pass& pass);

} // namespace tierlift::corpus
