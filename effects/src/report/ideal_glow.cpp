#include "tierlift/effects/report/ideal_glow.h"

#include <algorithm>
#include <cmath>

namespace tierlift::effects {
namespace {

double phi(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

double saw_at(double x, const Sawtooth& s) {
  x = std::abs(x);
  if (x > s.radius) return 0;
  const double q = x / s.period;
  return 1 - (q - std::floor(q));
}

// One axis: out(i) = Σ_d K(d) · in(i − d), outside the line 0.
void convolve_axis(const RgbImage& in, RgbImage& out, const std::vector<double>& k, bool vertical) {
  const int r = int(k.size() / 2);
  const int w = int(in.width), h = int(in.height);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double acc[3] = {0, 0, 0};
      for (int d = -r; d <= r; ++d) {
        const int sx = vertical ? x : x - d, sy = vertical ? y - d : y;
        if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
        const double kd = k[size_t(d + r)];
        const double* p = in.at(uint32_t(sx), uint32_t(sy));
        for (int c = 0; c < 3; ++c) acc[c] += kd * p[c];
      }
      double* o = out.at(uint32_t(x), uint32_t(y));
      for (int c = 0; c < 3; ++c) o[c] = acc[c];
    }
}

} // namespace

std::vector<double> ideal_kernel(const BlurProfile& profile) {
  if (profile.terms.empty() && !profile.sawtooth) return {};
  double radius = 0;
  for (const Gaussian& g : profile.terms) radius = std::max(radius, std::ceil(8 * g.sigma));
  if (profile.sawtooth) radius = std::max(radius, std::ceil(profile.sawtooth->radius + 0.5));
  const int r = int(std::min(radius, 1e5));
  std::vector<double> k(size_t(2 * r + 1), 0.0);
  for (const Gaussian& g : profile.terms)
    for (int d = -r; d <= r; ++d)
      k[size_t(d + r)] += g.weight * (phi((d + 0.5) / g.sigma) - phi((d - 0.5) / g.sigma));
  if (const auto& s = profile.sawtooth) {
    constexpr int kSub = 64;
    std::vector<double> cell(k.size(), 0.0);
    double total = 0;
    for (int d = -r; d <= r; ++d) {
      double sum = 0;
      for (int m = 0; m < kSub; ++m) sum += saw_at(d - 0.5 + (m + 0.5) / kSub, *s);
      total += cell[size_t(d + r)] = sum / kSub;
    }
    if (total > 0)
      for (size_t i = 0; i < k.size(); ++i) k[i] += s->weight * cell[i] / total;
  }
  return k;
}

RgbImage glow_sources(const img::Image& scene) {
  RgbImage out{scene.width, scene.height,
               std::vector<double>(size_t{scene.width} * scene.height * 3)};
  for (size_t i = 0; i < size_t{scene.width} * scene.height; ++i)
    for (size_t c = 0; c < 3; ++c)
      out.rgb[i * 3 + c] = double(scene.rgba[i * 4 + c]) * double(scene.rgba[i * 4 + 3]);
  return out;
}

RgbImage ideal_glow(const RgbImage& sources, const BlurProfile& profile) {
  const std::vector<double> k = ideal_kernel(profile);
  RgbImage tmp = sources, out = sources;
  if (k.empty()) {
    std::fill(out.rgb.begin(), out.rgb.end(), 0.0);
    return out;
  }
  convolve_axis(sources, tmp, k, false);
  convolve_axis(tmp, out, k, true);
  return out;
}

RgbImage upsample_glow(const img::Image& glow, uint32_t width, uint32_t height, unsigned n) {
  RgbImage out{width, height, std::vector<double>(size_t{width} * height * 3)};
  if (glow.width == 0 || glow.height == 0 || n == 0) return out;
  auto axis = [n](uint32_t i, uint32_t size, uint32_t* i0, uint32_t* i1, double* f) {
    double x = (i + 0.5) / n - 0.5;
    x = std::clamp(x, 0.0, double(size - 1));
    *i0 = uint32_t(std::floor(x));
    *i1 = std::min(*i0 + 1, size - 1);
    *f = x - *i0;
  };
  for (uint32_t y = 0; y < height; ++y) {
    uint32_t y0, y1;
    double fy;
    axis(y, glow.height, &y0, &y1, &fy);
    for (uint32_t x = 0; x < width; ++x) {
      uint32_t x0, x1;
      double fx;
      axis(x, glow.width, &x0, &x1, &fx);
      double* o = out.at(x, y);
      for (int c = 0; c < 3; ++c) {
        const double top = (1 - fx) * glow.at(x0, y0)[c] + fx * glow.at(x1, y0)[c];
        const double bottom = (1 - fx) * glow.at(x0, y1)[c] + fx * glow.at(x1, y1)[c];
        o[c] = (1 - fy) * top + fy * bottom;
      }
    }
  }
  return out;
}

RgbImage ideal_final(const img::Image& scene, const RgbImage& glow, double intensity) {
  RgbImage out = rgb_of(scene);
  for (size_t i = 0; i < out.rgb.size() && i < glow.rgb.size(); ++i)
    out.rgb[i] += intensity * glow.rgb[i];
  return out;
}

RgbImage displayed(RgbImage image) {
  for (double& v : image.rgb)
    if (!std::isnan(v)) v = std::clamp(v, 0.0, 1.0);
  return image;
}

RgbImage rgb_of(const img::Image& image) {
  RgbImage out{image.width, image.height,
               std::vector<double>(size_t{image.width} * image.height * 3)};
  for (size_t i = 0; i < size_t{image.width} * image.height; ++i)
    for (size_t c = 0; c < 3; ++c) out.rgb[i * 3 + c] = image.rgba[i * 4 + c];
  return out;
}

IdealError error_against(const RgbImage& ideal, const RgbImage& actual) {
  IdealError e;
  const size_t pixels = std::min(ideal.rgb.size(), actual.rgb.size()) / 3;
  if (pixels == 0) return e;
  double sq = 0;
  size_t off = 0;
  for (size_t i = 0; i < pixels; ++i) {
    double worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      double d = std::abs(ideal.rgb[i * 3 + c] - actual.rgb[i * 3 + c]);
      if (std::isnan(d)) d = INFINITY; // a NaN is as far off as it gets
      worst = std::max(worst, d);
      sq += d * d;
    }
    e.max_abs = std::max(e.max_abs, worst);
    if (worst > 1.0 / 255) ++off;
  }
  e.rmse = std::sqrt(sq / double(pixels * 3));
  e.share_off = double(off) / double(pixels);
  return e;
}

} // namespace tierlift::effects
