// What changes from frame to frame in a glow (glow.h): ramped parameters (Keyframes) and the
// after-image's name.
#include <algorithm>

#include "glow_common.h"

namespace tierlift::effects {

double Keyframes::at(unsigned frame, double constant) const {
  if (points.empty()) return constant;
  if (frame <= points.front().first) return points.front().second;
  for (size_t i = 1; i < points.size(); ++i)
    if (frame <= points[i].first) {
      const auto [f0, v0] = points[i - 1];
      const auto [f1, v1] = points[i];
      const double t = double(frame - f0) / double(f1 - f0); // frames strictly increase
      return v0 + t * (v1 - v0);
    }
  return points.back().second;
}

double Keyframes::max(double constant) const {
  if (points.empty()) return constant;
  double m = points.front().second;
  // Linear between keyframes: the largest value is at a keyframe.
  for (const auto& p : points) m = std::max(m, p.second);
  return m;
}

std::string_view afterimage_name(Afterimage mode) {
  switch (mode) {
  case Afterimage::Sources: return "sources";
  case Afterimage::Glow: return "glow";
  case Afterimage::Off: break;
  }
  return "off";
}

namespace detail {

std::vector<double> ramp_values(const Keyframes& ramp) {
  std::vector<double> v;
  for (unsigned f = 1; f <= ramp.span(); ++f) v.push_back(ramp.at(f, 0));
  return v;
}

} // namespace detail
} // namespace tierlift::effects
