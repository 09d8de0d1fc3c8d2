// The devices' fp32 interpolation of a full-screen quad's texture coordinates
// (quad_coords.h), written from the rasteriser's arithmetic as that header states it.
#include "tierlift/analytic/quad_coords.h"

#include <cmath>

namespace tierlift::analytic {
namespace {

struct Corner {
  float x, y; // screen position (Vulkan frame, pixel i spans [i, i + 1))
  std::array<float, 2> uv;
};

} // namespace

QuadCoords::QuadCoords(const QuadCorners& corners, uint32_t width, uint32_t height,
                       ir::PixelCenter center)
    : width_(width), height_(height), modern_(center == ir::PixelCenter::Modern) {
  const float shift = modern_ ? 0.0f : 0.5f;
  const float half_w = 0.5f * static_cast<float>(width), half_h = 0.5f * static_cast<float>(height);
  // Clip-space corners (x, y) with w = 1: the quad the glow's vertex listings pass through.
  const float clip[4][2] = {{-1, 1}, {1, 1}, {-1, -1}, {1, -1}};
  std::array<Corner, 4> c;
  for (int k = 0; k < 4; ++k) {
    const float one_over_w = 1.0f / 1.0f;
    c[k].x = std::fma(clip[k][0] * one_over_w, half_w, half_w + shift);
    c[k].y = std::fma(-clip[k][1] * one_over_w, half_h, half_h + shift);
    c[k].uv = corners[k];
  }
  const int order[2][3] = {{0, 1, 2}, {2, 1, 3}};
  for (int t = 0; t < 2; ++t) {
    const Corner &v0 = c[order[t][0]], &v1 = c[order[t][1]], &v2 = c[order[t][2]];
    const float dx01 = v0.x - v1.x, dy01 = v0.y - v1.y;
    const float dx20 = v2.x - v0.x, dy20 = v2.y - v0.y;
    const float e = dx01 * dy20, f = dy01 * dx20;
    const float ooa = 1.0f / (e - f);
    const float dx01o = dx01 * ooa, dy01o = dy01 * ooa, dx20o = dx20 * ooa, dy20o = dy20 * ooa;
    const float x0c = v0.x - 0.5f, y0c = v0.y - 0.5f;
    auto plane = [&](float a0, float a1, float a2) {
      const float da01 = a0 - a1, da20 = a2 - a0;
      Plane p;
      const float gx1 = da01 * dy20o, gx2 = da20 * dy01o;
      p.dadx = gx1 - gx2;
      const float gy1 = da20 * dx01o, gy2 = da01 * dx20o;
      p.dady = gy1 - gy2;
      const float sx = p.dadx * x0c, sy = p.dady * y0c;
      p.a0 = a0 - (sx + sy);
      return p;
    };
    for (int a = 0; a < 2; ++a) tri_[t].uv[a] = plane(v0.uv[a], v1.uv[a], v2.uv[a]);
    tri_[t].one_over_w = plane(1.0f, 1.0f, 1.0f);
  }
}

std::array<float, 2> QuadCoords::at(uint32_t i, uint32_t j) const {
  // The diagonal runs from the top-right corner to the bottom-left one; the sample point
  // (px, py) in pixels from the top-left corner lies before it when px/W + py/H < 1, in
  // integers (doubled for the modern centre at i + ½): the first triangle's side.
  const uint64_t px2 = 2 * uint64_t{i} + (modern_ ? 1 : 0),
                 py2 = 2 * uint64_t{j} + (modern_ ? 1 : 0);
  const Triangle& t = tri_[px2 * height_ + py2 * width_ < 2 * width_ * height_ ? 0 : 1];
  const float x = static_cast<float>(i), y = static_cast<float>(j);
  auto eval = [x, y](const Plane& p) { return std::fma(p.dady, y, std::fma(p.dadx, x, p.a0)); };
  const float w = 1.0f / eval(t.one_over_w);
  return {eval(t.uv[0]) * w, eval(t.uv[1]) * w};
}

} // namespace tierlift::analytic
