#include "tierlift/effects/scenes/default_scene.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/vec2.hpp>

namespace tierlift::effects {
namespace {

using Rgb = std::array<int, 3>; // 0..255

void put(img::Image& im, int64_t x, int64_t y, const Rgb& c, float alpha) {
  if (x < 0 || y < 0 || x >= int64_t(im.width) || y >= int64_t(im.height)) return;
  float* p = im.at(uint32_t(x), uint32_t(y));
  for (int k = 0; k < 3; ++k) p[k] = float(c[k]) / 255.0f;
  p[3] = alpha;
}

// Rectangle given in fractions of the image: [fx0, fx1) × [fy0, fy1).
void rect(img::Image& im, double fx0, double fx1, double fy0, double fy1, const Rgb& c,
          float alpha) {
  const auto x0 = int64_t(fx0 * im.width), x1 = std::max(x0 + 1, int64_t(fx1 * im.width));
  const auto y0 = int64_t(fy0 * im.height), y1 = std::max(y0 + 1, int64_t(fy1 * im.height));
  for (int64_t y = y0; y < y1; ++y)
    for (int64_t x = x0; x < x1; ++x) put(im, x, y, c, alpha);
}

void strip_h(img::Image& im, double fx0, double fx1, double fy, int64_t t, const Rgb& c) {
  const auto y0 = int64_t(fy * im.height);
  const auto x0 = int64_t(fx0 * im.width), x1 = int64_t(fx1 * im.width);
  for (int64_t y = y0; y < y0 + t; ++y)
    for (int64_t x = x0; x < std::max(x1, x0 + 1); ++x) put(im, x, y, c, 1.0f);
}

void strip_v(img::Image& im, double fx, double fy0, double fy1, int64_t t, const Rgb& c) {
  const auto x0 = int64_t(fx * im.width);
  const auto y0 = int64_t(fy0 * im.height), y1 = int64_t(fy1 * im.height);
  for (int64_t y = y0; y < std::max(y1, y0 + 1); ++y)
    for (int64_t x = x0; x < x0 + t; ++x) put(im, x, y, c, 1.0f);
}

void light(img::Image& im, double fx, double fy, int64_t r, const Rgb& c) {
  const auto cx = int64_t(std::floor(fx * im.width)), cy = int64_t(std::floor(fy * im.height));
  for (int64_t y = cy - r; y <= cy + r; ++y)
    for (int64_t x = cx - r; x <= cx + r; ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) put(im, x, y, c, 1.0f);
}

} // namespace

img::Image make_default_scene(uint32_t width, uint32_t height, img::Format format,
                              double light_orbit, double angle) {
  img::Image im(width, height, format);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) put(im, x, y, {10, 10, 16}, 0.0f);
  rect(im, 0.08, 0.30, 0.50, 0.90, {90, 90, 100}, 0.0f); // lit panel, no glow
  const int64_t t = std::max<int64_t>(1, height / 60);
  const int64_t r = std::max<int64_t>(1, height / 90);
  strip_h(im, 0.10, 0.60, 0.30, t, {255, 40, 200}); // magenta
  strip_v(im, 0.75, 0.15, 0.85, t, {40, 230, 255}); // cyan
  strip_h(im, 0.35, 0.90, 0.70, t, {255, 190, 20}); // amber
  // Each light's centre moved along its circle (in fractions of the image, as light() takes).
  auto at = [&](double fx, double fy, int k) {
    const double a = angle + k * glm::two_pi<double>() / 3;
    const glm::dvec2 shift = light_orbit * glm::dvec2(std::cos(a), std::sin(a));
    return glm::dvec2(fx, fy) + shift / glm::dvec2(width, height);
  };
  const glm::dvec2 l0 = at(0.20, 0.15, 0), l1 = at(0.50, 0.55, 1), l2 = at(0.88, 0.20, 2);
  light(im, l0.x, l0.y, r, {255, 255, 255});
  light(im, l1.x, l1.y, r, {255, 255, 200});
  light(im, l2.x, l2.y, r, {200, 255, 255});
  return im;
}

} // namespace tierlift::effects
