// Attribute interpolation of one pixel, two ways (ir::Rounding):
//   * Exact: perspective-correct barycentrics from the exact integer edge functions, in
//     double, rounded to float once.
//   * Llvmpipe: the arithmetic of Mesa's llvmpipe (lavapipe's rasteriser), reproduced so that
//     the CPU and Vulkan devices compute the same float texture coordinates. u = i/1920 is not
//     a float, so any two schemes round it differently, and with 8-bit bilinear weights a one-ulp
//     difference can move a weight by 1/256: matching the rounding is the only way to agree at
//     sizes that are not powers of two. Measured bit-exact against lavapipe (Mesa 22.3, x86-64
//     with FMA) on full-screen quads and on random triangles with w ≠ 1.
//
// llvmpipe's scheme, per triangle (its "setup" function, all in float, no fused operations):
//   positions (x_k, y_k) in the framebuffer with pixel i spanning [i, i + 1);
//   dx01 = x0 − x1, dy01 = y0 − y1, dx20 = x2 − x0, dy20 = y2 − y0;
//   ooa = 1 / (dx01·dy20 − dy01·dx20); each of the four differences is multiplied by ooa;
//   per channel, with a_k = value_k · (1/w_k):
//     da01 = a0 − a1, da20 = a2 − a0;
//     dadx = da01·dy20o − da20·dy01o;  dady = da20·dx01o − da01·dx20o;
//     a0' = a0 − (dadx·(x0 − ½) + dady·(y0 − ½))   (the plane's value at pixel (0, 0)'s centre)
//   and the same plane for 1/w. Per pixel (i, j) (its "interp" code, with llvm.fmuladd, which
//   is fused on FMA hardware): p = fma(dady, j, fma(dadx, i, a0')); value = p · (1 / w_ij)
//   where w_ij is the 1/w plane evaluated the same way.
// The planes are invariant under swapping vertices 1 and 2 (each product changes sign twice),
// so only the first vertex has to be lavapipe's first vertex.
#include <algorithm>
#include <cmath>

#include "raster.h"
#include "simd_rgba.h"
#include "tierlift/ir/numerics.h"

namespace tierlift::cpu::detail {
namespace {

// The triangle's shared terms of llvmpipe's setup.
struct SetupTerms {
  float x0c, y0c;                   // first vertex relative to pixel (0, 0)'s centre
  float dx01o, dy01o, dx20o, dy20o; // edge vectors divided by twice the signed area
};

SetupTerms setup_terms(const Triangle& t) {
  const ScreenVertex &v0 = t.v[0], &v1 = t.v[1], &v2 = t.v[2];
  SetupTerms s;
  s.x0c = v0.fx - 0.5f;
  s.y0c = v0.fy - 0.5f;
  const float dx01 = v0.fx - v1.fx, dy01 = v0.fy - v1.fy;
  const float dx20 = v2.fx - v0.fx, dy20 = v2.fy - v0.fy;
  const float e = dx01 * dy20, f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  s.dx01o = dx01 * ooa;
  s.dy01o = dy01 * ooa;
  s.dx20o = dx20 * ooa;
  s.dy20o = dy20 * ooa;
  return s;
}

Plane plane(const SetupTerms& s, float a0, float a1, float a2) {
  // The same infinity or NaN at all three vertices stays itself (as a flat varying would;
  // llvmpipe's differences inf − inf would make it NaN). Equal finite values come out of the
  // arithmetic below unchanged anyway when w is 1.
  if (!std::isfinite(a0) && (a0 == a1 || (std::isnan(a0) && std::isnan(a1))) &&
      (a0 == a2 || (std::isnan(a0) && std::isnan(a2))))
    return Plane{a0, 0, 0};
  a0 = ftz(a0);
  a1 = ftz(a1);
  a2 = ftz(a2);
  const float da01 = ftz(a0 - a1), da20 = ftz(a2 - a0);
  Plane p;
  p.dadx = ftz(ftz(da01 * s.dy20o) - ftz(da20 * s.dy01o));
  p.dady = ftz(ftz(da20 * s.dx01o) - ftz(da01 * s.dx20o));
  p.a0 = ftz(a0 - ftz(ftz(p.dadx * s.x0c) + ftz(p.dady * s.y0c)));
  return p;
}

bool all_positive_zero(const Vec4& a, const Vec4& b, const Vec4& c) {
  for (int i = 0; i < 4; ++i)
    for (float v : {a[i], b[i], c[i]})
      if (v != 0 || std::signbit(v)) return false;
  return true;
}

PixelInput interpolate_exact(const Triangle& t, const int64_t e[3]) {
  PixelInput in;
  const double area = static_cast<double>(t.area);
  double l[3], q[3], s = 0;
  for (int k = 0; k < 3; ++k) {
    l[k] = static_cast<double>(e[k]) / area;
    q[k] = l[k] * t.v[k].inv_w;
    s += q[k];
  }
  // Perspective-correct weights. When the three w are equal (every 2D pass) the screen
  // weights are already right, and skipping the division keeps u = i/W as exact as the
  // division E/area allows.
  if (t.v[0].inv_w != t.v[1].inv_w || t.v[0].inv_w != t.v[2].inv_w)
    for (int k = 0; k < 3; ++k) q[k] /= s;
  else
    for (int k = 0; k < 3; ++k) q[k] = l[k];
  for (size_t r = 0; r < in.color.size(); ++r)
    for (int c = 0; c < 4; ++c)
      in.color[r][c] = color_in(t, static_cast<float>(q[0] * t.v[0].out.color[r][c] +
                                                      q[1] * t.v[1].out.color[r][c] +
                                                      q[2] * t.v[2].out.color[r][c]));
  for (size_t r = 0; r < in.tex.size(); ++r)
    for (int c = 0; c < 4; ++c)
      in.tex[r][c] = static_cast<float>(q[0] * t.v[0].out.tex[r][c] + q[1] * t.v[1].out.tex[r][c] +
                                        q[2] * t.v[2].out.tex[r][c]);
  return in;
}

PixelInput interpolate_llvmpipe(const Triangle& t, int64_t x, int64_t y) {
  PixelInput in;
  const AttributePlanes& p = t.planes;
  // Pixel indices are below 2^15 (img::kMaxDimension), exact in float.
  const float fx = static_cast<float>(x), fy = static_cast<float>(y);
  const float oow = 1.0f / eval(p.oow, fx, fy);
  for (size_t r = 0; r < in.color.size(); ++r)
    if (!p.color_zero[r])
      for (int c = 0; c < 4; ++c)
        in.color[r][c] = color_in(t, perspective(p.color[r][c], fx, fy, oow));
  for (size_t r = 0; r < in.tex.size(); ++r)
    if (!p.tex_zero[r])
      for (int c = 0; c < 4; ++c) in.tex[r][c] = perspective(p.tex[r][c], fx, fy, oow);
  return in;
}

} // namespace

void setup_planes(Triangle& t) {
  const SetupTerms s = setup_terms(t);
  const ScreenVertex &v0 = t.v[0], &v1 = t.v[1], &v2 = t.v[2];
  AttributePlanes& p = t.planes;
  p.oow = plane(s, v0.oow, v1.oow, v2.oow);
  p.z = plane(s, v0.fz, v1.fz, v2.fz);
  for (size_t r = 0; r < p.color.size(); ++r) {
    p.color_zero[r] = all_positive_zero(v0.out.color[r], v1.out.color[r], v2.out.color[r]);
    for (int c = 0; c < 4; ++c)
      p.color[r][c] =
          plane(s, ftz(ftz(v0.out.color[r][c]) * v0.oow), ftz(ftz(v1.out.color[r][c]) * v1.oow),
                ftz(ftz(v2.out.color[r][c]) * v2.oow));
  }
  for (size_t r = 0; r < p.tex.size(); ++r) {
    p.tex_zero[r] = all_positive_zero(v0.out.tex[r], v1.out.tex[r], v2.out.tex[r]);
    for (int c = 0; c < 4; ++c)
      p.tex[r][c] = plane(s, ftz(ftz(v0.out.tex[r][c]) * v0.oow),
                          ftz(ftz(v1.out.tex[r][c]) * v1.oow), ftz(ftz(v2.out.tex[r][c]) * v2.oow));
  }
}

PixelInput interpolate(const Triangle& t, const int64_t e[3], int64_t x, int64_t y) {
  PixelInput in = t.llvmpipe ? interpolate_llvmpipe(t, x, y) : interpolate_exact(t, e);
  // Depth is linear in screen space under both schemes (NUMERICS.md D4). Llvmpipe: the z
  // plane evaluated as every other plane is, then min(z, 1) — lavapipe's fragment stage clamps
  // the interpolated z from above, since a plane referred to pixel (0, 0) can overshoot 1.
  // Exact: barycentric weights from the edge functions, in double, rounded once.
  if (t.llvmpipe) {
    const float z = eval(t.planes.z, static_cast<float>(x), static_cast<float>(y));
    in.depth = z > 1.0f ? 1.0f : z;
    return in;
  }
  const double area = static_cast<double>(t.area);
  double z = 0;
  for (int k = 0; k < 3; ++k) z += static_cast<double>(e[k]) / area * t.v[k].z;
  in.depth = static_cast<float>(z);
  return in;
}

namespace {

// interpolate_llvmpipe, one channel across all the lanes at a time (lanes past the block's
// count compute values nobody reads). Inlined into two functions: one built for AVX2 + FMA,
// where std::fma becomes one vector instruction, and the baseline one, where it is a call
// into libm; both round exactly once per fma, so they agree bit for bit.
[[gnu::always_inline]] inline void llvmpipe_lanes_body(const Triangle& t, int64_t x0, int64_t y,
                                                       uint8_t color_reads, uint32_t tex_components,
                                                       PixelBlockInput& in) {
  const AttributePlanes& p = t.planes;
  const float fy = static_cast<float>(y);
  float fx[kBlockLanes], oow[kBlockLanes];
  const Plane w = p.oow;
  // Lane l is pixel x0 + l. x0 + l < 16384 + 64 (draw() refuses wider targets), so the sum
  // of the two floats is that integer exactly. Computed rather than loaded: x[] was just
  // written lane by lane, and wide loads of it stalled on store forwarding.
  const float x0f = static_cast<float>(x0);
#pragma GCC unroll 1
  for (int l = 0; l < kBlockLanes; ++l) fx[l] = x0f + static_cast<float>(l);
  // With dadx = ±0 (1/w constant along the row: every 2D pass), dadx·x is the same signed zero
  // at every x ≥ 0, so every lane's 1/w is the one at x = 0: one division per block. When it
  // is exactly 1 the products by it are skipped too: v·1 = v, and v is already flushed. The
  // same holds for a texture coordinate plane with dadx = ±0 (x ≥ 0 at every pixel): one
  // evaluation per block.
  bool unit = false;
  if (w.dadx == 0.0f) {
    const float o = 1.0f / eval(w, 0.0f, fy);
    std::fill(oow, oow + kBlockLanes, o);
    unit = o == 1.0f;
  } else {
#pragma GCC unroll 1
    for (int l = 0; l < kBlockLanes; ++l) oow[l] = 1.0f / eval(w, fx[l], fy);
  }
  for (size_t r = 0; r < 2; ++r) {
    if (!(color_reads & (1u << r))) continue;
    for (int c = 0; c < 4; ++c) {
      float* out = in.color[r].c[c];
      if (p.color_zero[r]) {
        std::fill(out, out + kBlockLanes, 0.0f);
        continue;
      }
      const Plane pl = p.color[r][c]; // a copy: no store to `out` can change it
      if (unit) {
#pragma GCC unroll 1
        for (int l = 0; l < kBlockLanes; ++l) out[l] = color_in(t, eval(pl, fx[l], fy));
        continue;
      }
#pragma GCC unroll 1
      for (int l = 0; l < kBlockLanes; ++l)
        out[l] = color_in(t, perspective(pl, fx[l], fy, oow[l]));
    }
  }
  for (size_t r = 0; r < 8; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (!(tex_components & (1u << (4 * r + c)))) continue;
      float* out = in.tex[r].c[c];
      if (p.tex_zero[r]) {
        std::fill(out, out + kBlockLanes, 0.0f);
        continue;
      }
      const Plane pl = p.tex[r][c];
      if (pl.dadx == 0.0f && w.dadx == 0.0f) {
        // Constant along the row (the v of a 2D pass): every lane's value is lane 0's.
        const float v = unit ? eval(pl, fx[0], fy) : perspective(pl, fx[0], fy, oow[0]);
        std::fill(out, out + kBlockLanes, v);
        continue;
      }
      if (unit) {
#pragma GCC unroll 1
        for (int l = 0; l < kBlockLanes; ++l) out[l] = eval(pl, fx[l], fy);
        continue;
      }
#pragma GCC unroll 1
      for (int l = 0; l < kBlockLanes; ++l) out[l] = perspective(pl, fx[l], fy, oow[l]);
    }
  }
}

void llvmpipe_lanes(const Triangle& t, int64_t x0, int64_t y, uint8_t color_reads,
                    uint32_t tex_components, PixelBlockInput& in) {
  llvmpipe_lanes_body(t, x0, y, color_reads, tex_components, in);
}

#if TIERLIFT_CPU_AVX2
[[gnu::target("avx2,fma")]] void llvmpipe_lanes_fma(const Triangle& t, int64_t x0, int64_t y,
                                                    uint8_t color_reads, uint32_t tex_components,
                                                    PixelBlockInput& in) {
  llvmpipe_lanes_body(t, x0, y, color_reads, tex_components, in);
}
#else
void llvmpipe_lanes_fma(const Triangle& t, int64_t x0, int64_t y, uint8_t color_reads,
                        uint32_t tex_components, PixelBlockInput& in) {
  llvmpipe_lanes_body(t, x0, y, color_reads, tex_components, in);
}
#endif

} // namespace

void interpolate_block(const Triangle& t, const int64_t (*e)[3], const int64_t* x, int64_t y, int n,
                       uint8_t color_reads, uint32_t tex_components, PixelBlockInput& in) {
  if (!t.llvmpipe) {
    for (int l = 0; l < n; ++l) {
      const PixelInput p = interpolate(t, e[l], x[l], y);
      for (int r = 0; r < 2; ++r)
        if (color_reads & (1u << r))
          for (int c = 0; c < 4; ++c) in.color[r].c[c][l] = p.color[r][c];
      for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 4; ++c)
          if (tex_components & (1u << (4 * r + c))) in.tex[r].c[c][l] = p.tex[r][c];
    }
    return;
  }
  if (cpu_runs_avx2_fma())
    llvmpipe_lanes_fma(t, x[0], y, color_reads, tex_components, in);
  else
    llvmpipe_lanes(t, x[0], y, color_reads, tex_components, in);
}

} // namespace tierlift::cpu::detail
