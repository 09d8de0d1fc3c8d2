// The texture coordinate a device interpolates at a pixel of the full-screen quad, in the
// devices' own fp32 arithmetic (ir::Rounding::Llvmpipe, the rasteriser of Mesa's lavapipe).
// Why the model needs it: a coordinate such as u = i/W is not a float; the devices round it
// in their own way, and a bilinear read or a point read on a texel edge turns that rounding
// into a different weight or a different texel. A model that takes u in double misses those
// by up to 1e-5 (σ ≤ 1 profiles, taps without the half texel); one that takes the devices'
// float u agrees with them to the last ulp and keeps only weights and sums in double.
//
// The arithmetic, from the rasteriser's definition (every step one fp32 rounding; fma where
// it multiplies and adds at once):
//   the quad is two triangles, (top-left, top-right, bottom-left) and (bottom-left,
//   top-right, bottom-right); a pixel whose sample point lies on the shared diagonal belongs
//   to the second (the diagonal is a top-left edge of the second only);
//   screen position of a corner at clip x = ±1: fma(x, W/2, W/2 + shift), shift ½ for D3D9
//   pixel centres (their pixel i samples at i, which the Vulkan frame puts at i + ½), 0 else;
//   y likewise with −y;
//   per triangle: dx01 = x0 − x1, dy01 = y0 − y1, dx20 = x2 − x0, dy20 = y2 − y0,
//   ooa = 1/(dx01·dy20 − dy01·dx20), each difference times ooa; per attribute with corner
//   values a0, a1, a2: dadx = da01·dy20o − da20·dy01o, dady = da20·dx01o − da01·dx20o,
//   a(0, 0) = a0 − (dadx·(x0 − ½) + dady·(y0 − ½)); at pixel (i, j):
//   fma(dady, j, fma(dadx, i, a(0, 0))), times 1/(the same plane of 1/w), here 1/1.
#pragma once

#include <array>
#include <cstdint>

#include "tierlift/ir/conventions.h"

namespace tierlift::analytic {

// oT#.xy at the quad corners: top-left, top-right, bottom-left, bottom-right.
using QuadCorners = std::array<std::array<float, 2>, 4>;

class QuadCoords {
public:
  QuadCoords(const QuadCorners& corners, uint32_t width, uint32_t height, ir::PixelCenter center);
  // (u, v) at pixel (i, j) of the width × height target.
  std::array<float, 2> at(uint32_t i, uint32_t j) const;

private:
  struct Plane {
    float a0 = 0, dadx = 0, dady = 0;
  };
  struct Triangle {
    std::array<Plane, 2> uv;
    Plane one_over_w;
  };
  std::array<Triangle, 2> tri_;
  uint64_t width_, height_;
  bool modern_;
};

} // namespace tierlift::analytic
