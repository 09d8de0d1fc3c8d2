// The pixel loop for the block executor: the same coverage test, the same pixel order and the
// same store as raster_rows in draw.cpp, but covered pixels are gathered kBlockLanes at a time
// along a row, their inputs interpolated per block, the program run once per block and the
// results blended and stored pixel by pixel.
#include <algorithm>
#include <utility>
#include <vector>

#include "raster.h"

namespace tierlift::cpu::detail {
namespace {

void fill_constant_inputs(const PixelInput& constant, PixelBlockInput& in) {
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 4; ++c)
      std::fill(std::begin(in.color[r].c[c]), std::end(in.color[r].c[c]),
                clamp01(constant.color[r][c]));
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 4; ++c)
      std::fill(std::begin(in.tex[r].c[c]), std::end(in.tex[r].c[c]), constant.tex[r][c]);
}

void shade_block(const RasterJob& job, const Triangle& t, int64_t y, int n, BlockWorker& w,
                 WorkerStats& stats) {
  const PixelBlockVM& vm = *job.block;
  w.in.count = n;
  if (!job.constant_inputs)
    interpolate_block(t, w.e, w.x, y, n, vm.color_reads(), vm.tex_components(), w.in);
  vm.run(w.in, job.textures, w.out, *w.scratch);
  stats.block += static_cast<uint64_t>(n);
  stats.shaded += static_cast<uint64_t>(n);
  for (int l = 0; l < n; ++l) stats.killed += w.out.discarded[static_cast<size_t>(l)] ? 1 : 0;
  store_block(job.pass.blend, job.target.format, job.pass.conventions.rounding, *w.out.color,
              w.out.discarded, w.x[0], n, job.target.at(0, static_cast<uint32_t>(y)));
}

// Integer division rounded toward −∞ / +∞ (d > 0).
int64_t floor_div(int64_t a, int64_t d) {
  return a >= 0 ? a / d : -((-a + d - 1) / d);
}
int64_t ceil_div(int64_t a, int64_t d) {
  return -floor_div(-a, d);
}

} // namespace

BlockWorker::BlockWorker(const PixelBlockVM& vm, const RasterJob& job)
    : scratch(vm.make_scratch()) {
  if (job.constant_inputs) fill_constant_inputs(job.pass.constant_inputs, in);
}

RowSpan row_span(const Triangle& t, int64_t y, int64_t sample_offset) {
  RowSpan r;
  const int64_t py = y * kSubPixelOne + sample_offset;
  // Along the row each edge function is E + S·i at pixel x0 + i (exact integers), and a
  // pixel is inside when every one is ≥ 1, or ≥ 0 on a top-left edge: solved for i, that
  // is one span [lo, hi) — the pixels raster_rows tests one by one.
  const int64_t px0 = t.bounds.x0 * kSubPixelOne + sample_offset;
  r.hi = t.bounds.x1 - t.bounds.x0;
  for (int k = 0; k < 3; ++k) {
    const ScreenVertex &a = t.v[(k + 1) % 3], &b = t.v[(k + 2) % 3];
    r.e0[k] = edge(a, b, px0, py);
    r.step[k] = -(b.y - a.y) * kSubPixelOne;
    const int64_t need = t.top_left[k] ? 0 : 1;
    if (r.step[k] == 0) {
      if (r.e0[k] < need) r.hi = 0;
    } else if (r.step[k] > 0) {
      r.lo = std::max(r.lo, ceil_div(need - r.e0[k], r.step[k]));
    } else {
      r.hi = std::min(r.hi, floor_div(r.e0[k] - need, -r.step[k]) + 1);
    }
  }
  return r;
}

bool covers(const std::vector<Triangle>& triangles, const PixelRect& rect, int64_t sample_offset) {
  // Rows × triangles span computations: worth it for the few triangles of a full-screen
  // pass; a mesh is simply taken as not covering.
  if (triangles.empty() || triangles.size() > 16) return false;
  std::vector<std::pair<int64_t, int64_t>> spans;
  for (int64_t y = rect.y0; y < rect.y1; ++y) {
    spans.clear();
    for (const Triangle& t : triangles) {
      if (y < t.bounds.y0 || y >= t.bounds.y1) continue;
      const RowSpan r = row_span(t, y, sample_offset);
      if (r.lo < r.hi) spans.emplace_back(t.bounds.x0 + r.lo, t.bounds.x0 + r.hi);
    }
    std::sort(spans.begin(), spans.end());
    int64_t reached = rect.x0;
    for (const auto& [a, b] : spans)
      if (a <= reached) reached = std::max(reached, b);
    if (reached < rect.x1) return false;
  }
  return true;
}

void raster_rows_block(const RasterJob& job, int64_t y0, int64_t y1, BlockWorker& w,
                       WorkerStats& stats) {
  for (const Triangle& t : job.triangles) {
    const int64_t ya = std::max(y0, t.bounds.y0), yb = std::min(y1, t.bounds.y1);
    for (int64_t y = ya; y < yb; ++y) {
      const RowSpan r = row_span(t, y, job.sample_offset);
      // Blocks of kBlockLanes consecutive pixels from lo. The edge values are only read by
      // exact interpolation (llvmpipe's planes take x alone, constant inputs neither).
      const bool edges = !t.llvmpipe && !job.constant_inputs;
      for (int64_t i = r.lo; i < r.hi; i += kBlockLanes) {
        const int n = static_cast<int>(std::min<int64_t>(kBlockLanes, r.hi - i));
        for (int l = 0; l < n; ++l) w.x[l] = t.bounds.x0 + i + l;
        if (edges)
          for (int l = 0; l < n; ++l)
            for (int k = 0; k < 3; ++k) w.e[l][k] = r.e0[k] + r.step[k] * (i + l);
        shade_block(job, t, y, n, w, stats);
      }
    }
  }
}

} // namespace tierlift::cpu::detail
