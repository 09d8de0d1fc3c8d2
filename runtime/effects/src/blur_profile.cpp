#include "tierlift/effects/blur_profile.h"

#include <cmath>

#include <fmt/format.h>

namespace tierlift::effects {

BlurProfile default_blur_profile() {
  return BlurProfile{{{8.0, 0.7}, {1.5, 0.3}}};
}

std::vector<BlurTap> sample_blur_profile(const BlurProfile& profile, unsigned downsample,
                                         std::string* error) {
  auto fail = [&](std::string why) {
    if (error) *error = std::move(why);
    return std::vector<BlurTap>{};
  };
  if (downsample == 0) return fail("downsample factor 0");
  if (profile.terms.empty()) return fail("the blur profile has no terms");
  double max_sigma = 0;
  for (const Gaussian& g : profile.terms) {
    if (!std::isfinite(g.sigma) || !std::isfinite(g.weight) || g.sigma <= 0 || g.weight < 0)
      return fail(fmt::format("blur term sigma {} weight {}: need sigma > 0, weight >= 0", g.sigma,
                              g.weight));
    max_sigma = std::max(max_sigma, g.sigma / downsample);
  }
  const double radius = std::ceil(3.0 * max_sigma);
  if (radius > 1024) return fail(fmt::format("blur radius {} texels is beyond 1024", radius));
  const int r = static_cast<int>(radius);
  std::vector<BlurTap> taps;
  double sum = 0;
  for (int k = -r; k <= r; ++k) {
    double v = 0;
    for (const Gaussian& g : profile.terms) {
      const double s = g.sigma / downsample;
      v += g.weight * std::exp(-double(k) * k / (2 * s * s)) / s;
    }
    taps.push_back({k, v});
    sum += v;
  }
  if (!(sum > 0)) return fail("the blur profile sums to zero");
  for (BlurTap& t : taps) t.weight /= sum;
  return taps;
}

} // namespace tierlift::effects
