// Sample positions and filtered reads of the analytic model, in double.
#include <cmath>

#include "tierlift/analytic/blur_model.h"

namespace tierlift::analytic {

std::array<double, 2> pixel_uv(uint32_t i, uint32_t j, uint32_t width, uint32_t height,
                               const PassModel& model) {
  const double shift = model.conventions.pixel_center == ir::PixelCenter::D3D9 ? 0.0 : 0.5;
  double x = (i + shift) / width, y = (j + shift) / height;
  return {model.u0 + (model.u1 - model.u0) * x, model.v0 + (model.v1 - model.v0) * y};
}

namespace {

// The texel index after addressing (pass::address_texel), −1 for the border colour.
int64_t addressed_index(int64_t i, int64_t n, AddressMode mode) {
  return pass::address_texel(mode, i, n).value_or(-1);
}

// Far outside any texture, yet safe to convert to int64 and to add small offsets to.
constexpr double kPositionLimit = 1e12;

double limit_position(double p) {
  if (std::isnan(p)) return 0.0;
  return std::fmin(std::fmax(p, -kPositionLimit), kPositionLimit);
}

std::array<double, 4> texel(const img::Image& t, int64_t x, int64_t y, const SamplerModel& s) {
  int64_t ax = addressed_index(x, t.width, s.address_u);
  int64_t ay = addressed_index(y, t.height, s.address_v);
  if (ax < 0 || ay < 0) return s.border;
  const auto px = static_cast<uint32_t>(ax), py = static_cast<uint32_t>(ay);
  return {texel_value(t, px, py, 0), texel_value(t, px, py, 1), texel_value(t, px, py, 2),
          texel_value(t, px, py, 3)};
}

// Texel-space position p = u·N − 0.5 split into the lower texel and the fraction.
struct Split {
  int64_t i0;
  double frac;
};
Split split(double p, int subtexel_bits, double snap) {
  p = limit_position(p);
  // On a texel centre (integer) or half-way between two (integer + ½), within `snap`: read
  // exactly there (see blur_model.h).
  const double nearest = std::nearbyint(2.0 * p) / 2.0;
  if (std::fabs(p - nearest) <= snap) p = nearest;
  double f0 = std::floor(p);
  double frac = p - f0;
  auto i0 = static_cast<int64_t>(f0);
  if (subtexel_bits > 0) {
    double steps = std::ldexp(1.0, subtexel_bits);
    frac = std::nearbyint(frac * steps) / steps;
    if (frac >= 1.0) {
      ++i0;
      frac = 0.0;
    }
  }
  return {i0, frac};
}

// A bilinear read whose 2×2 footprint holds a non-finite texel in channel c, as the
// devices' filter unit computes it (NUMERICS.md rule 36): a + α·(b − a) along u, then along
// v, in IEEE fp32. Unlike a weighted sum it turns an infinite texel into NaN wherever the
// texel sits in the lower slot (inf − inf, or −inf + inf) or has weight 0 (0·inf), so a
// weight of 0 does not keep the texel out. The finite texels cannot change the result
// (it is ±inf or NaN whatever they hold), so their float is enough.
double filter_unit_lerp(const std::array<std::array<double, 4>, 4>& tx, int c, double alpha,
                        double beta) {
  auto lerp = [](float a, float v0, float v1) { return std::fma(a, v1 - v0, v0); };
  const auto a = static_cast<float>(alpha), b = static_cast<float>(beta);
  const float top = lerp(a, float(tx[0][c]), float(tx[1][c]));
  const float bottom = lerp(a, float(tx[2][c]), float(tx[3][c]));
  return lerp(b, top, bottom);
}

// The bilinear read of texels (i0, j0)…(i0 + 1, j0 + 1) with fractions fx, fy: weights in
// double, each texel of weight 0 left out (an exact read stays exact); a channel whose
// footprint holds ±inf or NaN as the filter unit computes it (filter_unit_lerp).
template <class Note>
std::array<double, 4> bilinear(const img::Image& t, int64_t i0, int64_t j0, double fx, double fy,
                               const SamplerModel& s, const Note& note) {
  std::array<std::array<double, 4>, 4> tx{}; // t00, t10, t01, t11
  for (int b = 0; b < 2; ++b)
    for (int a = 0; a < 2; ++a) tx[2 * b + a] = texel(t, i0 + a, j0 + b, s);
  const double wx[2] = {1.0 - fx, fx}, wy[2] = {1.0 - fy, fy};
  std::array<double, 4> out{};
  for (int b = 0; b < 2; ++b)
    for (int a = 0; a < 2; ++a) {
      const double wgt = wx[a] * wy[b];
      if (wgt == 0.0) continue; // keeps exact reads exact
      note(tx[2 * b + a]);
      for (int c = 0; c < 4; ++c) out[c] += wgt * tx[2 * b + a][c];
    }
  for (int c = 0; c < 4; ++c)
    for (const auto& texel_c : tx)
      if (!std::isfinite(texel_c[c])) {
        out[c] = filter_unit_lerp(tx, c, fx, fy);
        break;
      }
  return out;
}

} // namespace

double snap_tolerance(uint32_t texels) {
  return std::fmax(1e-9, std::ldexp(double(texels), -21));
}

std::array<double, 4> sample(const img::Image& t, double u, double v, const SamplerModel& s,
                             int subtexel_bits) {
  if (t.width == 0 || t.height == 0) return {0, 0, 0, 1};
  const double w = t.width, h = t.height;
  if (s.filter == Filter::Point) {
    // floor(u·N): only a position within 1e-9 of a texel edge is moved onto it.
    Split sx = split(u * w, 0, 1e-9), sy = split(v * h, 0, 1e-9);
    return texel(t, sx.i0, sy.i0, s);
  }
  Split sx = split(u * w - 0.5, subtexel_bits, snap_tolerance(t.width)),
        sy = split(v * h - 0.5, subtexel_bits, snap_tolerance(t.height));
  return bilinear(t, sx.i0, sy.i0, sx.frac, sy.frac, s, [](const std::array<double, 4>&) {});
}

} // namespace tierlift::analytic

namespace tierlift::analytic {
namespace {

// One axis of a bilinear read at the devices' float coordinate: the position x = fl32(u·N)
// − ½ in fp32 (clamp addressing clamps the coordinate first: min(u·N, N), NaN → N, then
// max(x, 0), so the index stays in the texture), its lower texel and the fraction x − ⌊x⌋,
// which is exact in fp32; the fraction quantised to subtexel_bits by rounding to nearest.
struct FloatSplit {
  int64_t i0;
  double frac;
};
FloatSplit float_split(float u, uint32_t n, AddressMode mode, int subtexel_bits) {
  const float size = static_cast<float>(n);
  float x = u * size;
  if (mode == AddressMode::Clamp) {
    x = x < size ? x : size;
    x = x - 0.5f;
    x = x > 0.0f ? x : 0.0f;
  } else {
    x = x - 0.5f;
    constexpr float kLimit = 1099511627776.0f; // 2^40, far outside any address period
    if (std::isnan(x)) x = 0.0f;
    x = std::fmin(std::fmax(x, -kLimit), kLimit);
  }
  const float f = std::floor(x);
  double frac = double(x) - double(f);
  if (subtexel_bits > 0) {
    const double steps = std::ldexp(1.0, subtexel_bits > 30 ? 30 : subtexel_bits);
    frac = std::nearbyint(frac * steps) / steps; // may reach 1: all weight on texel i0 + 1
  }
  return {static_cast<int64_t>(f), frac};
}

// Point reads: texel ⌊fl32(u·N)⌋ (NaN → 0, far positions limited as above).
int64_t float_point(float u, uint32_t n) {
  float x = u * static_cast<float>(n);
  constexpr float kLimit = 1099511627776.0f;
  if (std::isnan(x)) x = 0.0f;
  x = std::fmin(std::fmax(x, -kLimit), kLimit);
  return static_cast<int64_t>(std::floor(x));
}

} // namespace

std::array<double, 4> sample_at_float(const img::Image& t, float u, float v, const SamplerModel& s,
                                      int subtexel_bits, std::array<double, 4>* texel_max) {
  if (texel_max) *texel_max = {0, 0, 0, 0};
  auto note = [texel_max](const std::array<double, 4>& tx) {
    if (texel_max)
      for (int c = 0; c < 4; ++c) (*texel_max)[c] = std::fmax((*texel_max)[c], std::fabs(tx[c]));
  };
  if (t.width == 0 || t.height == 0) return {0, 0, 0, 1};
  if (s.filter == Filter::Point) {
    const auto tx = texel(t, float_point(u, t.width), float_point(v, t.height), s);
    note(tx);
    return tx;
  }
  const FloatSplit sx = float_split(u, t.width, s.address_u, subtexel_bits);
  const FloatSplit sy = float_split(v, t.height, s.address_v, subtexel_bits);
  return bilinear(t, sx.i0, sy.i0, sx.frac, sy.frac, s, note);
}

namespace {

// A texel as the devices hold it: the image's float (RGBA8: the float nearest k/255).
std::array<float, 4> texel_fp32(const img::Image& t, int64_t x, int64_t y, const SamplerModel& s) {
  const int64_t ax = addressed_index(x, t.width, s.address_u);
  const int64_t ay = addressed_index(y, t.height, s.address_v);
  if (ax < 0 || ay < 0)
    return {float(s.border[0]), float(s.border[1]), float(s.border[2]), float(s.border[3])};
  const float* p = t.at(static_cast<uint32_t>(ax), static_cast<uint32_t>(ay));
  return {p[0], p[1], p[2], p[3]};
}

// The filter unit's interpolation: a + α·(b − a) as one fused multiply-add.
float lerp_fp32(float alpha, float a, float b) {
  return std::fma(alpha, b - a, a);
}

} // namespace

std::array<float, 4> sample_fp32(const img::Image& t, float u, float v, const SamplerModel& s,
                                 int subtexel_bits) {
  if (t.width == 0 || t.height == 0) return {0, 0, 0, 1};
  if (s.filter == Filter::Point)
    return texel_fp32(t, float_point(u, t.width), float_point(v, t.height), s);
  const FloatSplit sx = float_split(u, t.width, s.address_u, subtexel_bits);
  const FloatSplit sy = float_split(v, t.height, s.address_v, subtexel_bits);
  const float a = static_cast<float>(sx.frac), b = static_cast<float>(sy.frac);
  const auto t00 = texel_fp32(t, sx.i0, sy.i0, s), t10 = texel_fp32(t, sx.i0 + 1, sy.i0, s);
  const auto t01 = texel_fp32(t, sx.i0, sy.i0 + 1, s), t11 = texel_fp32(t, sx.i0 + 1, sy.i0 + 1, s);
  std::array<float, 4> out{};
  for (int c = 0; c < 4; ++c)
    out[c] = lerp_fp32(b, lerp_fp32(a, t00[c], t10[c]), lerp_fp32(a, t01[c], t11[c]));
  return out;
}

} // namespace tierlift::analytic
