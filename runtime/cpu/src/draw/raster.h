// Internal to the draw: clipping, viewport transform and triangle setup in fixed point.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tierlift/cpu/draw.h"

namespace tierlift::cpu::detail {

inline constexpr int kSubPixelBits = 8;
inline constexpr int64_t kSubPixelOne = int64_t{1} << kSubPixelBits;

// The drawable rectangle: viewport ∩ render target, in whole pixels, [x0, x1) × [y0, y1).
struct PixelRect {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// A vertex after the viewport transform: snapped position and what interpolation needs.
struct ScreenVertex {
  int64_t x = 0, y = 0; // screen position in 1/256 pixel
  double inv_w = 1.0;   // 1/w for perspective correction
  double z = 0.0;       // z_s, interpolated linearly in screen space
  VertexOutput out;     // colours already saturated
};

// A triangle ready to rasterise: counter-clockwise-agnostic, normalised so that `area`
// (twice the signed area in 1/256² pixel units) is positive.
struct Triangle {
  std::array<ScreenVertex, 3> v;
  int64_t area = 0;
  std::array<bool, 3> top_left{}; // edge k runs from v[k+1] to v[k+2]
  PixelRect bounds;               // pixels whose sample point may be inside, ∩ scissor
};

// Clips (0 ≤ z ≤ w, guard band) and transforms one triangle of vertex-stage outputs;
// appends 0..n triangles (a clipped polygon is fanned).
void setup_triangle(const std::array<const VertexOutput*, 3>& tri, const Viewport& viewport,
                    const PixelRect& scissor, int64_t sample_offset, std::vector<Triangle>& out);

// Edge function of edge a→b at point (px, py), all in 1/256 pixel.
inline int64_t edge(const ScreenVertex& a, const ScreenVertex& b, int64_t px, int64_t py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

} // namespace tierlift::cpu::detail
