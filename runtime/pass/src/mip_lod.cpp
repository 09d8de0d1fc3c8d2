// The LOD and mip-blend rules (mip_lod.h, NUMERICS.md M1-M3).
#include "tierlift/pass/mip_lod.h"

#include <algorithm>
#include <cmath>

#include "tierlift/rounding/rounding.h"

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

namespace {

// lavapipe's steps (rounding.h). Its sampler gets minLod = m, maxLod = the last level (NONE:
// both m), and takes one of three routes: minLod = maxLod reads that level; POINT with no
// bias and minLod 0 reads the nearest level off ρ's exponent; otherwise λ is computed, the
// biases added (the shader's first), clamped from below by minLod, and rounded (POINT) or
// split into a level and a fraction (LINEAR).
LevelChoice select_llvmpipe(const LodInput& in, const MipState& state, uint32_t levels,
                            uint32_t width, uint32_t height) {
  const int32_t last = static_cast<int32_t>(levels == 0 ? 0 : levels - 1);
  const int32_t m = std::min(static_cast<int32_t>(std::min(state.max_mip_level, 31u)), last);
  LevelChoice c;
  c.fine = c.coarse = static_cast<uint32_t>(m);
  if (state.filter == MipFilter::None || m == last) return c;
  auto clamp_level = [&](int32_t k) { return static_cast<uint32_t>(std::clamp(k, 0, last)); };
  const float rho = in.explicit_lod ? 0.0f
                                    : rounding::mip_rho_llvmpipe(in.dudx, in.dvdx, in.dudy, in.dvdy,
                                                                 width, height);
  const bool plain = !in.explicit_lod && !in.has_bias && state.lod_bias == 0.0f && m == 0;
  if (state.filter == MipFilter::Point && plain) {
    c.fine = c.coarse = clamp_level(rounding::nearest_level_from_rho_llvmpipe(rho));
    return c;
  }
  float lod = in.explicit_lod ? in.lod : rounding::lod_from_rho_llvmpipe(rho);
  if (in.has_bias) lod = rounding::flush(lod + in.bias);
  if (state.lod_bias != 0.0f) lod = rounding::flush(lod + state.lod_bias);
  if (m > 0) lod = lod > float(m) ? lod : float(m);
  c.magnified = !(lod > 0.0f);
  if (state.filter == MipFilter::Point) {
    c.fine = c.coarse = clamp_level(rounding::nearest_level_llvmpipe(lod));
    return c;
  }
  if (std::isnan(lod)) return c;
  const float floor = std::floor(std::clamp(lod, -1073741824.0f, 1073741824.0f));
  const auto level0 = static_cast<int32_t>(floor);
  if (level0 < 0 || level0 >= last) { // the ends: one level, no fraction
    c.fine = c.coarse = clamp_level(level0);
    return c;
  }
  c.fine = static_cast<uint32_t>(level0);
  c.coarse = c.fine + 1;
  c.fraction = lod - floor; // exact
  return c;
}

} // namespace

LevelChoice select_levels(const LodInput& in, const MipState& state, uint32_t levels,
                          uint32_t width, uint32_t height, bool llvmpipe) {
  if (llvmpipe) return select_llvmpipe(in, state, levels, width, height);
  const float lod = in.explicit_lod
                        ? in.lod
                        : lod_from_gradients(in.dudx, in.dvdx, in.dudy, in.dvdy, width, height);
  return choose_levels(lod, in.has_bias ? in.bias : 0.0f, state, levels);
}

} // namespace tierlift::pass
