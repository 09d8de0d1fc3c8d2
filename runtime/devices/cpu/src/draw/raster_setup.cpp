// Clipping against D3D9's clip volume and a guard band, viewport transform, snapping to
// 8 sub-pixel bits, and the top-left classification of each edge.
#include <algorithm>
#include <cmath>

#include "raster.h"

namespace tierlift::cpu::detail {
namespace {

// |x|, |y| ≤ kGuard·w keeps snapped coordinates below 2^26 (1/256 px) for a 16384-wide
// viewport, so edge functions fit comfortably in int64. Pixels outside the viewport are
// never drawn, so this plane changes no coverage.
constexpr float kGuard = 8.0f;
// w ≥ kMinW keeps 1/w finite for vertices on the z = 0 plane at w = 0.
constexpr float kMinW = 1e-20f;

// Signed distance of a clip-space position to each clip plane (≥ 0 inside).
constexpr int kPlanes = 7;
double plane_distance(const Vec4& p, int plane) {
  double x = p[0], y = p[1], z = p[2], w = p[3];
  switch (plane) {
  case 0: return z;
  case 1: return w - z;
  case 2: return x + kGuard * w;
  case 3: return kGuard * w - x;
  case 4: return y + kGuard * w;
  case 5: return kGuard * w - y;
  default: return w - kMinW;
  }
}

Vec4 lerp4(const Vec4& a, const Vec4& b, float t) {
  Vec4 r;
  for (int i = 0; i < 4; ++i) r[i] = a[i] + (b[i] - a[i]) * t;
  return r;
}

// Attributes are linear in clip space, so clipping interpolates every output with t.
VertexOutput lerp_vertex(const VertexOutput& a, const VertexOutput& b, float t) {
  VertexOutput r = a;
  r.pos = lerp4(a.pos, b.pos, t);
  for (size_t i = 0; i < r.color.size(); ++i) r.color[i] = lerp4(a.color[i], b.color[i], t);
  for (size_t i = 0; i < r.tex.size(); ++i) r.tex[i] = lerp4(a.tex[i], b.tex[i], t);
  r.fog = a.fog + (b.fog - a.fog) * t;
  r.color_written |= b.color_written;
  r.tex_written |= b.tex_written;
  return r;
}

bool inside_all(const VertexOutput& v) {
  for (int p = 0; p < kPlanes; ++p)
    if (!(plane_distance(v.pos, p) >= 0)) return false; // NaN counts as outside
  return true;
}

// Sutherland–Hodgman against every plane.
std::vector<VertexOutput> clip_polygon(std::vector<VertexOutput> poly) {
  for (int p = 0; p < kPlanes && !poly.empty(); ++p) {
    std::vector<VertexOutput> next;
    for (size_t i = 0; i < poly.size(); ++i) {
      const VertexOutput& a = poly[i];
      const VertexOutput& b = poly[(i + 1) % poly.size()];
      double da = plane_distance(a.pos, p), db = plane_distance(b.pos, p);
      bool ina = da >= 0, inb = db >= 0;
      if (ina) next.push_back(a);
      if (ina != inb && std::isfinite(da) && std::isfinite(db)) {
        float t = static_cast<float>(da / (da - db));
        next.push_back(lerp_vertex(a, b, t));
      }
    }
    poly = std::move(next);
  }
  return poly;
}

float saturate(float v) {
  return v > 0 ? (v < 1 ? v : 1) : 0;
} // NaN → 0

int64_t snap(double screen) {
  return static_cast<int64_t>(std::nearbyint(screen * kSubPixelOne));
}

// Lavapipe's viewport transform, for Rounding::Llvmpipe: 1/w as a float division, the
// position times it, then one fused multiply-add with the viewport's half size and centre.
// The Vulkan device shifts D3D9 centres by +0.5 pixel through the viewport and flips y.
void lavapipe_position(const VertexOutput& v, const Viewport& vp, float shift, ScreenVertex& s) {
  const float half_w = 0.5f * static_cast<float>(vp.width);
  const float half_h = 0.5f * static_cast<float>(vp.height);
  s.oow = 1.0f / v.pos[3];
  s.fx = std::fma(v.pos[0] * s.oow, half_w, half_w + (static_cast<float>(vp.x) + shift));
  s.fy = std::fma(-v.pos[1] * s.oow, half_h, half_h + (static_cast<float>(vp.y) + shift));
  s.fz = std::fma(v.pos[2] * s.oow, vp.max_z - vp.min_z, vp.min_z);
}

ScreenVertex to_screen(const VertexOutput& v, const Viewport& vp, float shift,
                       bool saturate_colors) {
  ScreenVertex s;
  lavapipe_position(v, vp, shift, s);
  double w = v.pos[3];
  // Clipping leaves |x/w|, |y/w| ≤ kGuard up to rounding; the clamp only guards the
  // float→int conversion against vertices rounded across the w ≥ kMinW plane.
  auto ndc = [w](float c) { return std::fmin(std::fmax(c / w, -2.0 * kGuard), 2.0 * kGuard); };
  double nx = ndc(v.pos[0]), ny = ndc(v.pos[1]), nz = v.pos[2] / w;
  s.x = snap(vp.x + (nx + 1.0) * vp.width / 2.0);
  s.y = snap(vp.y + (1.0 - ny) * vp.height / 2.0);
  s.z = vp.min_z + nz * (static_cast<double>(vp.max_z) - vp.min_z);
  s.inv_w = 1.0 / w;
  s.out = v;
  if (saturate_colors) // oD# leave a vertex stage before 3.0 saturated
    for (auto& c : s.out.color)
      for (auto& x : c) x = saturate(x);
  return s;
}

// First pixel index whose sample point (i·256 + offset) is ≥ v, and last ≤ v.
int64_t ceil_pixel(int64_t v, int64_t offset) {
  int64_t d = v - offset;
  return d >= 0 ? (d + kSubPixelOne - 1) / kSubPixelOne : -((-d) / kSubPixelOne);
}
int64_t floor_pixel(int64_t v, int64_t offset) {
  int64_t d = v - offset;
  return d >= 0 ? d / kSubPixelOne : -((-d + kSubPixelOne - 1) / kSubPixelOne);
}

void emit(ScreenVertex a, ScreenVertex b, ScreenVertex c, const PixelRect& scissor, int64_t offset,
          bool llvmpipe, bool saturate_colors, std::vector<Triangle>& out) {
  Triangle t;
  t.saturate_colors = saturate_colors;
  t.v = {a, b, c};
  t.area = edge(a, b, c.x, c.y);
  if (t.area == 0) return; // degenerate after snapping: covers nothing
  t.front = t.area > 0;    // y points down: a positive area runs clockwise on screen
  if (t.area < 0) {        // no culling: both windings are drawn
    std::swap(t.v[1], t.v[2]);
    t.area = -t.area;
  }
  // With area > 0 and y pointing down, the inside lies to the right of a left edge
  // (dy < 0) and below a top edge (dy = 0, dx > 0).
  for (int k = 0; k < 3; ++k) {
    const ScreenVertex& p = t.v[(k + 1) % 3];
    const ScreenVertex& q = t.v[(k + 2) % 3];
    int64_t dx = q.x - p.x, dy = q.y - p.y;
    t.top_left[k] = dy < 0 || (dy == 0 && dx > 0);
  }
  int64_t minx = std::min({a.x, b.x, c.x}), maxx = std::max({a.x, b.x, c.x});
  int64_t miny = std::min({a.y, b.y, c.y}), maxy = std::max({a.y, b.y, c.y});
  t.bounds.x0 = std::max(scissor.x0, ceil_pixel(minx, offset));
  t.bounds.x1 = std::min(scissor.x1, floor_pixel(maxx, offset) + 1);
  t.bounds.y0 = std::max(scissor.y0, ceil_pixel(miny, offset));
  t.bounds.y1 = std::min(scissor.y1, floor_pixel(maxy, offset) + 1);
  if (t.bounds.x0 >= t.bounds.x1 || t.bounds.y0 >= t.bounds.y1) return;
  // The swap above keeps v[0]; lavapipe's setup also keeps its first vertex and its planes do
  // not depend on the order of the other two, so t.v is the order lavapipe uses.
  t.llvmpipe = llvmpipe;
  if (llvmpipe) setup_planes(t);
  out.push_back(std::move(t));
}

} // namespace

int64_t sample_offset(const ir::Conventions& conventions) {
  return conventions.pixel_center == ir::PixelCenter::Modern ? kSubPixelOne / 2 : 0;
}

void setup_triangle(const std::array<const VertexOutput*, 3>& tri, const Viewport& viewport,
                    const PixelRect& scissor, const ir::Conventions& conventions,
                    ColorClamps clamps, std::vector<Triangle>& out) {
  const int64_t offset = sample_offset(conventions);
  const float shift = conventions.pixel_center == ir::PixelCenter::D3D9 ? 0.5f : 0.0f;
  const bool llvmpipe = conventions.rounding == ir::Rounding::Llvmpipe;
  std::vector<VertexOutput> poly{*tri[0], *tri[1], *tri[2]};
  if (!(inside_all(poly[0]) && inside_all(poly[1]) && inside_all(poly[2])))
    poly = clip_polygon(std::move(poly));
  if (poly.size() < 3) return;
  std::vector<ScreenVertex> s;
  s.reserve(poly.size());
  for (const auto& v : poly) s.push_back(to_screen(v, viewport, shift, clamps.vertex_out));
  for (size_t i = 1; i + 1 < s.size(); ++i)
    emit(s[0], s[i], s[i + 1], scissor, offset, llvmpipe, clamps.pixel_in, out);
}

} // namespace tierlift::cpu::detail
