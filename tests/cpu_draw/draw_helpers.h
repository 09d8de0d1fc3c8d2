// Shared by the draw tests: passes built from screen-space triangles, no shaders.
#pragma once

#include <vector>

#include "tierlift/cpu/draw.h"

namespace tierlift::cpu::test {

// Clip-space vertex whose D3D9 viewport transform lands at screen (sx, sy) on a W×H target
// (x = 2·sx/W − 1, y = 1 − 2·sy/H), scaled by w so that x/w, y/w are unchanged.
inline VertexOutput screen_vertex(double sx, double sy, uint32_t w, uint32_t h, float wclip = 1) {
  VertexOutput v;
  v.pos = {static_cast<float>((2.0 * sx / w - 1.0) * wclip),
           static_cast<float>((1.0 - 2.0 * sy / h) * wclip), 0.0f, wclip};
  return v;
}

// A pass that draws the given pre-transformed triangles with colour `c` and no shaders.
inline Pass flat_pass(std::vector<VertexOutput> verts, Vec4 c, BlendMode blend) {
  Pass p;
  for (auto& v : verts) v.color[0] = c;
  p.transformed = std::move(verts);
  p.blend = blend;
  return p;
}

} // namespace tierlift::cpu::test
