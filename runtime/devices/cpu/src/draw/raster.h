// Internal to the draw: clipping, viewport transform and triangle setup in fixed point.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tierlift/cpu/draw.h"
#include "tierlift/cpu/pixel_block.h"
#include "tierlift/ir/numerics.h"
#include "tierlift/rounding/rounding.h"

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
  // Rounding::Llvmpipe: the unsnapped float position in Vulkan's frame (pixel i spans
  // [i, i + 1)) and 1/w, rounded as lavapipe's vertex pipeline rounds them.
  float fx = 0, fy = 0, oow = 1;
  float fz = 0; // z_s as lavapipe's viewport transform makes it: fma(z·(1/w), maxZ − minZ, minZ)
  VertexOutput out; // colours already saturated
};

// One attribute channel as a plane over pixel indices: value(i, j) = a0 + dadx·i + dady·j.
struct Plane {
  float a0 = 0, dadx = 0, dady = 0;
};

// Rounding::Llvmpipe's planes of one triangle: each channel premultiplied by 1/w, and
// 1/w itself; z_s, linear in screen space (not premultiplied). `zero` marks registers that
// are +0 at all three vertices (they stay +0).
struct AttributePlanes {
  std::array<std::array<Plane, 4>, 2> color;
  std::array<std::array<Plane, 4>, 8> tex;
  Plane oow, z;
  std::array<bool, 2> color_zero{};
  std::array<bool, 8> tex_zero{};
};

// A triangle ready to rasterise: counter-clockwise-agnostic, normalised so that `area`
// (twice the signed area in 1/256² pixel units) is positive.
struct Triangle {
  std::array<ScreenVertex, 3> v;
  int64_t area = 0;
  std::array<bool, 3> top_left{}; // edge k runs from v[k+1] to v[k+2]
  PixelRect bounds;               // pixels whose sample point may be inside, ∩ scissor
  bool llvmpipe = false;          // interpolate with `planes` (else exact barycentrics)
  bool front = true;              // clockwise on screen as given (before the swap): vFace +1
  bool saturate_colors = true;    // the pixel stage reads its colours saturated (ColorClamps)
  AttributePlanes planes;
};

// Where a pass's colours are clamped to [0, 1] (NUMERICS.md rule 26, F6): as the vertex
// stage writes them (ir::saturates_vertex_colors: unless a vs_3_0 feeds a ps_3_0; a missing
// program is a 2.0 stage), and as the pixel stage reads them (a pixel program before ps_3_0,
// or none: ir::saturates_colors).
struct ColorClamps {
  bool vertex_out = true;
  bool pixel_in = true;
};

// Clips (0 ≤ z ≤ w, guard band) and transforms one triangle of vertex-stage outputs;
// appends 0..n triangles (a clipped polygon is fanned).
void setup_triangle(const std::array<const VertexOutput*, 3>& tri, const Viewport& viewport,
                    const PixelRect& scissor, const ir::Conventions& conventions,
                    ColorClamps clamps, std::vector<Triangle>& out);

// A pass's vertex stage and triangle setup (the first half of a draw): the triangles to
// rasterise in primitive order, the drawable rectangle, the sample offset, and whether the
// pixel inputs are the pass's constant ones (no vertex program, no transformed vertices).
struct PassSetup {
  std::vector<Triangle> triangles;
  PixelRect scissor;
  int64_t sample_offset = 0;
  bool constant_inputs = false;
};
// `vs`: the pass's vertex program's VM, nullptr without one; `vp` with its size filled in.
// Empty string on success, else why nothing can be drawn.
std::string setup_pass(const Pass& pass, const ShaderVM* vs, const Viewport& vp, uint32_t width,
                       uint32_t height, PassSetup& out);

// Sample offset of pixel (i, j) in 1/256 pixel: 0 for D3D9 centres, 128 for modern ones.
int64_t sample_offset(const ir::Conventions& conventions);

// Interpolation (interpolation.cpp). `e` are the edge functions at the pixel's sample
// point (all ≥ 0 inside), (x, y) its pixel index.
void setup_planes(Triangle& t);
PixelInput interpolate(const Triangle& t, const int64_t e[3], int64_t x, int64_t y);
// ps_3_0 vPos and vFace of pixel (x, y) of t: its integer coordinates and t's facing.
inline void set_position_and_face(PixelInput& in, const Triangle& t, int64_t x, int64_t y) {
  in.pos_x = static_cast<float>(x);
  in.pos_y = static_cast<float>(y);
  in.face = t.front ? 1.0f : -1.0f;
}

// Rounding::Llvmpipe's arithmetic (tierlift/rounding/rounding.h, measured in
// tests/vulkan/denormals_test.cpp): setup and interpolation flush denormals, planes are
// evaluated with FMAs. The per-pixel and the block interpolation both call these, so they
// agree bit for bit.
inline float ftz(float x) {
  return rounding::flush(x);
}
inline float eval(const Plane& p, float x, float y) {
  return rounding::plane_at(p.a0, p.dadx, p.dady, x, y);
}
inline float perspective(const Plane& p, float x, float y, float oow) {
  return rounding::perspective_at(p.a0, p.dadx, p.dady, x, y, oow);
}

inline float clamp01(float v) {
  return v > 0 ? (v < 1 ? v : 1) : 0;
} // NaN → 0
// An interpolated colour as the pixel stage receives it: clamped to [0, 1] before ps_3_0,
// as it is (a float register) in a ps_3_0 (NUMERICS.md rule 26, F6).
inline float color_in(const Triangle& t, float v) {
  return t.saturate_colors ? clamp01(v) : v;
}

// Everything the workers share, read-only except the target pixels they own.
struct RasterJob {
  const Pass& pass;
  const std::vector<Triangle>& triangles;
  const ShaderVM* ps;
  const PixelBlockVM* block; // set: the pixel stage runs on the block executor
  bool constant_inputs;
  int64_t sample_offset;
  PixelRect scissor;
  img::Image& target;
  BoundTextures textures;
  DrawTargets targets; // target is targets.color[0]
};

// One worker's counters, on a cache line of their own: the workers' counters lie side by
// side in one vector and are written once a block, and counters sharing a line made every
// block of one worker evict that line from the other's cache.
struct alignas(64) WorkerStats {
  uint64_t shaded = 0, killed = 0, block = 0;
};

// One worker's state for the block executor (raster_block.cpp).
struct BlockWorker {
  BlockWorker(const PixelBlockVM& vm, const RasterJob& job);
  std::unique_ptr<PixelBlockVM::Scratch, void (*)(PixelBlockVM::Scratch*)> scratch;
  PixelBlockInput in;
  PixelBlockOutput out;
  int64_t x[kBlockLanes]{};
  int64_t e[kBlockLanes][3]{};
};

// The pixels of row y a triangle covers: x = bounds.x0 + i for i in [lo, hi) (empty when
// lo ≥ hi), and its edge functions at pixel bounds.x0 + i: e0[k] + step[k]·i.
struct RowSpan {
  int64_t lo = 0, hi = 0;
  int64_t e0[3]{}, step[3]{};
};
RowSpan row_span(const Triangle& t, int64_t y, int64_t sample_offset);

// Whether every pixel of `rect` lies inside at least one of `triangles` (the same coverage
// test as the raster loops). False for more than a few triangles, without looking.
bool covers(const std::vector<Triangle>& triangles, const PixelRect& rect, int64_t sample_offset);

// Rows [y0, y1) of every triangle, in primitive order, kBlockLanes covered pixels of a row at a
// time through job.block; the same pixels and values as the per-pixel path.
void raster_rows_block(const RasterJob& job, int64_t y0, int64_t y1, BlockWorker& w,
                       WorkerStats& stats);

// A shaded pixel's stencil test and stores into every colour target (draw.cpp).
void store_shaded(const RasterJob& job, const PixelOutput& out, float interpolated_z, int64_t x,
                  int64_t y);

// Rows [y0, y1) (y0 even) of every triangle, in primitive order, by 2x2 quads aligned on even
// coordinates through job.ps->run_quad: the lanes outside the triangle (helper pixels) run
// with the inputs interpolated at their own centres and are never stored (raster_quads.cpp).
void raster_quads(const RasterJob& job, int64_t y0, int64_t y1, WorkerStats& stats);

// blend_and_store for lanes 0..n−1 of a block of n consecutive pixels on one row (`row`: the
// target's row, lane l's pixel x0 + l at row + 4·(x0 + l)), discarded lanes left alone;
// RGBA32F targets take an inlined loop.
void store_block(BlendMode mode, img::Format format, ir::Rounding rounding, const LaneVec4& src,
                 const std::array<bool, kBlockLanes>& discarded, int64_t x0, int n, float* row);

// The inputs `reads` names (bits 0–1 colours, 8–15 texture coordinates) of n consecutive
// pixels (x[l] = x[0] + l, y) into lanes 0..n−1, bit-identical to interpolate().
void interpolate_block(const Triangle& t, const int64_t (*e)[3], const int64_t* x, int64_t y, int n,
                       uint8_t color_reads, uint32_t tex_components, PixelBlockInput& in);

// Edge function of edge a→b at point (px, py), all in 1/256 pixel.
inline int64_t edge(const ScreenVertex& a, const ScreenVertex& b, int64_t px, int64_t py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

} // namespace tierlift::cpu::detail
