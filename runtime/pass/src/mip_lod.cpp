// The LOD and mip-blend rules (mip_lod.h, NUMERICS.md M1-M3).
#include "tierlift/pass/mip_lod.h"

#include <algorithm>
#include <cmath>

namespace tierlift::pass {

float lod_from_gradients(float dudx, float dvdx, float dudy, float dvdy, uint32_t width,
                         uint32_t height) {
  const double w = width, h = height;
  const double x = std::hypot(double(dudx) * w, double(dvdx) * h);
  const double y = std::hypot(double(dudy) * w, double(dvdy) * h);
  if (std::isnan(x) || std::isnan(y) || std::isinf(x) || std::isinf(y))
    return std::nanf("");                               // a non-finite gradient has no footprint
  return static_cast<float>(std::log2(std::max(x, y))); // log2(0) = −inf
}

LevelChoice choose_levels(float lod, float texldb_bias, const MipState& state, uint32_t levels) {
  const uint32_t last = levels == 0 ? 0 : levels - 1;
  const uint32_t most_detailed = std::min(state.max_mip_level, last);
  // The biases add in float, as a device adds them to the lod it computed.
  const float biased = lod + state.lod_bias + texldb_bias;
  LevelChoice c;
  c.fine = c.coarse = most_detailed;
  c.magnified = !(biased > 0.0f); // NaN: the magnification filter, as at the finest level
  if (state.filter == MipFilter::None || std::isnan(biased)) return c;
  const double clamped = std::clamp(double(biased), double(most_detailed), double(last));
  if (state.filter == MipFilter::Point) {
    c.fine = c.coarse = static_cast<uint32_t>(std::floor(clamped + 0.5));
    return c;
  }
  const double floor = std::floor(clamped);
  c.fine = static_cast<uint32_t>(floor);
  c.coarse = std::min(c.fine + 1, last);
  c.fraction = c.coarse == c.fine ? 0.0f : static_cast<float>(clamped - floor);
  return c;
}

float mip_blend_exact(float fraction, float fine, float coarse) {
  const double f = fraction;
  return static_cast<float>((1.0 - f) * double(fine) + f * double(coarse));
}

} // namespace tierlift::pass
