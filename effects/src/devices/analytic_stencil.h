// Internal to the analytic device: what an object pass covers, the constants its pixel
// listing writes to oC0..oC3, and the stencil test applied per covered pixel.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/graph.h"

namespace tierlift::effects::detail {

// One entry per pixel of a w×h target: 1 where the pass draws the pixel. The full-screen quad
// (no vertices) covers every pixel; otherwise each triangle of the pass's vertices (the
// position input, passed through by the vertex listing, clip space with w = 1) is tested at
// the pixel's sample point in double, the vertices snapped to 1/256 pixel as the rasteriser
// snaps them. A sample point exactly on an edge is where D3D9's
// fill rule decides; the model refuses such an object rather than restating the rasteriser.
std::string coverage(const PassDesc& pass, const ir::Conventions& conventions, uint32_t w,
                     uint32_t h, std::vector<uint8_t>& covered);

// The constant each oC# of the pixel listing receives: every instruction must be
// `mov oC#, c#` (no modifiers, identity swizzle, full mask), the constant from the listing's
// def or else from the pass's constants. Empty string on success.
std::string constant_outputs(const PassDesc& pass, std::array<pass::Vec4, 4>& out,
                             uint8_t& written);

// Applies the pass's stencil state to `stencil` (red channel = value) at the covered pixels
// and clears `covered` where the test fails (those pixels keep their colour).
void apply_stencil(const PassDesc& pass, img::Image& stencil, std::vector<uint8_t>& covered);

} // namespace tierlift::effects::detail
