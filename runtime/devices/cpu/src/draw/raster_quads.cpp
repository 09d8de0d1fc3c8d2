// The pixel loop of programs that read their neighbours (dsx, dsy): 2x2 quads on even
// coordinates, as a GPU shades them. A quad runs when the triangle covers at least one of its
// pixels; the others are helper pixels (NUMERICS.md rule F9): inputs interpolated at their own
// centres (the triangle's planes extended past its edges), vPos their own coordinates, run to
// the end so that their values enter the covered pixels' gradients, and never stored.
#include <algorithm>
#include <array>

#include "raster.h"

namespace tierlift::cpu::detail {
namespace {

// Whether pixel (x, y) is inside t (the coverage test of raster_rows), its edge values into e.
bool inside(const Triangle& t, int64_t x, int64_t y, int64_t sample_offset, int64_t (&e)[3]) {
  const int64_t px = x * kSubPixelOne + sample_offset, py = y * kSubPixelOne + sample_offset;
  bool in = true;
  for (int k = 0; k < 3; ++k) {
    e[k] = edge(t.v[(k + 1) % 3], t.v[(k + 2) % 3], px, py);
    in = in && (e[k] > 0 || (e[k] == 0 && t.top_left[k]));
  }
  return in;
}

} // namespace

void raster_quads(const RasterJob& job, int64_t y0, int64_t y1, WorkerStats& stats) {
  PixelInput constant = job.pass.constant_inputs;
  for (auto& c : constant.color)
    for (auto& v : c) v = clamp01(v);
  std::array<PixelInput, 4> in;
  std::array<PixelOutput, 4> out;
  for (const Triangle& t : job.triangles) {
    // The rows and columns of pixels that may be covered (bounds lie inside the scissor).
    const int64_t ya = std::max(y0, t.bounds.y0), yb = std::min(y1, t.bounds.y1);
    const auto drawn = [&](int64_t x, int64_t y) {
      return x >= t.bounds.x0 && x < t.bounds.x1 && y >= ya && y < yb;
    };
    for (int64_t qy = ya & ~int64_t{1}; qy < yb; qy += 2) {
      for (int64_t qx = t.bounds.x0 & ~int64_t{1}; qx < t.bounds.x1; qx += 2) {
        std::array<bool, 4> covered{};
        int64_t e[4][3];
        for (int l = 0; l < 4; ++l)
          covered[l] = inside(t, qx + (l & 1), qy + (l >> 1), job.sample_offset, e[l]) &&
                       drawn(qx + (l & 1), qy + (l >> 1));
        if (std::none_of(covered.begin(), covered.end(), [](bool c) { return c; })) continue;
        for (int l = 0; l < 4; ++l) {
          const int64_t x = qx + (l & 1), y = qy + (l >> 1);
          in[l] = job.constant_inputs ? constant : interpolate(t, e[l], x, y);
          set_position_and_face(in[l], t, x, y);
        }
        job.ps->run_quad(in, job.pass.ps_constants, job.textures, out);
        for (size_t l = 0; l < 4; ++l) {
          if (!covered[l]) continue;
          ++stats.shaded;
          if (out[l].discarded) {
            ++stats.killed;
            continue;
          }
          store_shaded(job, out[l], in[l].depth, qx + static_cast<int64_t>(l & 1),
                       qy + static_cast<int64_t>(l >> 1));
        }
      }
    }
  }
}

} // namespace tierlift::cpu::detail
