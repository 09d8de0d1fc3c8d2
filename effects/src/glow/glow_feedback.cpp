// The after-image's regimes (glow.h): the loop gain, runaway and the RGBA8 stall, told to
// the user before a run.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "tierlift/effects/glow/glow.h"

namespace tierlift::effects {

double afterimage_loop_gain(const EffectParams& p, const std::vector<BlurTap>& taps) {
  if (p.afterimage == Afterimage::Off) return 0;
  const double g = p.afterimage_gain_ramp.max(p.afterimage_gain);
  if (p.afterimage == Afterimage::Sources) return g;
  // The blur runs on x, then on y: a flat region is scaled by the tap sum twice.
  double sum = 0;
  for (const BlurTap& t : taps) sum += t.weight;
  const double s = sum * p.weight_scale_ramp.max(p.weight_scale);
  return g * s * s;
}

int rgba8_stall_level(double k) {
  if (!(k > 0) || k >= 1) return 0;
  // L·(1 − k) < ½ ⇔ k·L lies within half a step of L: it rounds back to L. The largest such
  // L is the first integer below ½ / (1 − k) (at equality k·L is a tie; not counted).
  // ½ / (1 − k) is itself rounded (k = 0.9: 5.000000000000001), so the estimate is moved
  // to where the test L − k·L < ½ itself says.
  auto l = static_cast<int>(std::min(256.0, std::ceil(0.5 / (1 - k))));
  while (l > 0 && !(l - k * l < 0.5)) --l;
  return l > 255 ? 255 : l;
}

std::vector<std::string> afterimage_warnings(const EffectParams& p,
                                             const std::vector<BlurTap>& taps) {
  std::vector<std::string> out;
  if (p.afterimage == Afterimage::Off) return out;
  const double k = afterimage_loop_gain(p, taps);
  const double g = p.afterimage_gain_ramp.max(p.afterimage_gain);
  if (k >= 1) {
    const double per_gain = g > 0 ? k / g : 1; // the loop gain per unit of g
    out.push_back(
        fmt::format("after-image ({}): loop gain {:.4g} >= 1, the feedback runs away ({}); keep "
                    "afterimage.gain below {:.4g}",
                    afterimage_name(p.afterimage), k,
                    p.format == img::Format::RGBA8 ? "to a white screen" : "without bound",
                    per_gain > 0 ? 1 / per_gain : 1.0));
  } else if (p.format == img::Format::RGBA8) {
    if (int l = rgba8_stall_level(k); l > 0)
      out.push_back(fmt::format(
          "after-image ({}): loop gain {:.4g} in rgba8 stalls: a trail at or below {}/255 "
          "never fades (round({:.4g}·L) = L), and a steady state ends up to {} step(s) short "
          "of x/(1 − g); use format rgba16f, or a loop gain of at most 0.5",
          afterimage_name(p.afterimage), k, l, k, l));
  }
  return out;
}

} // namespace tierlift::effects
