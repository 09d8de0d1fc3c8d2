#include "tierlift/effects/glow/blur_profile.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace tierlift::effects {
namespace {

constexpr double kMaxRadiusTexels = kMaxBlurRadius;

double gauss_value(int k, double s) {
  if (k == 0) return 1; // also when s² underflows: 0 / 0 must not make a NaN
  return std::exp(-double(k) * k / (2 * s * s));
}

double saw_value(int k, unsigned downsample, const Sawtooth& saw) {
  const double x = std::abs(double(k)) * downsample;
  if (x > saw.radius) return 0;
  double q = x / saw.period;
  // k·d / period may land a rounding error below a whole number (x = 3, period = 0.3·10):
  // that is the next peak, not the end of a ramp.
  const double n = std::round(q);
  if (std::abs(q - n) <= 1e-9 * std::max(1.0, q)) q = n;
  return 1 - (q - std::floor(q));
}

bool finite_non_negative(double v) {
  return std::isfinite(v) && v >= 0;
}

// One term sampled over −r..r and normalised to its weight, added into `taps`.
template <typename ValueAt>
void add_term(std::vector<BlurTap>& taps, int r, double weight, ValueAt value_at) {
  std::vector<double> v(size_t(2 * r + 1));
  double sum = 0;
  for (int k = -r; k <= r; ++k) sum += v[size_t(k + r)] = value_at(k);
  // sum ≥ 1: every term is 1 at k = 0.
  for (size_t i = 0; i < v.size(); ++i) taps[i].weight += weight * v[i] / sum;
}

} // namespace

BlurProfile default_blur_profile() {
  BlurProfile p;
  p.terms = {{16.0, 1.0}};
  return p;
}

double profile_weight_sum(const BlurProfile& profile) {
  double sum = 0;
  for (const Gaussian& g : profile.terms) sum += g.weight;
  if (profile.sawtooth) sum += profile.sawtooth->weight;
  return sum;
}

ir::Result<std::vector<BlurTap>> sample_blur_profile(const BlurProfile& profile,
                                                     unsigned downsample) {
  auto fail = [](std::string why) { return ir::fail("profile", "profile", std::move(why)); };
  if (downsample == 0) return fail("downsample factor 0");
  if (profile.terms.empty() && !profile.sawtooth) return fail("the blur profile has no terms");
  if (profile.max_taps % 2 == 0 && profile.max_taps != 0)
    return fail(fmt::format("taps {}: must be odd (the kernel is centred)", profile.max_taps));
  double radius = 0; // texels
  for (const Gaussian& g : profile.terms) {
    if (!std::isfinite(g.sigma) || !finite_non_negative(g.weight) || g.sigma <= 0)
      return fail(fmt::format("blur term sigma {} weight {}: need sigma > 0, weight >= 0", g.sigma,
                              g.weight));
    radius = std::max(radius, std::ceil(3.0 * g.sigma / downsample));
  }
  if (const auto& saw = profile.sawtooth) {
    if (!std::isfinite(saw->period) || saw->period <= 0 || !finite_non_negative(saw->radius) ||
        !finite_non_negative(saw->weight))
      return fail(fmt::format("sawtooth period {} radius {} weight {}: need period > 0, "
                              "radius >= 0, weight >= 0",
                              saw->period, saw->radius, saw->weight));
    radius = std::max(radius, std::floor(saw->radius / downsample + 1e-9));
  }
  if (profile.max_taps != 0) radius = std::min(radius, double((profile.max_taps - 1) / 2));
  if (radius > kMaxRadiusTexels)
    return fail(fmt::format("blur radius {} texels is beyond {} (a taps limit cuts it)", radius,
                            kMaxRadiusTexels));
  const double total = profile_weight_sum(profile);
  if (!(total > 0) || !std::isfinite(total))
    return fail(fmt::format("the blur profile's weights sum to {}", total));

  const int r = static_cast<int>(radius);
  std::vector<BlurTap> taps;
  for (int k = -r; k <= r; ++k) taps.push_back({k, 0.0});
  for (const Gaussian& g : profile.terms) {
    const double s = g.sigma / downsample;
    add_term(taps, r, g.weight, [&](int k) { return gauss_value(k, s); });
  }
  if (const auto& saw = profile.sawtooth)
    add_term(taps, r, saw->weight, [&](int k) { return saw_value(k, downsample, *saw); });
  return taps;
}

} // namespace tierlift::effects
