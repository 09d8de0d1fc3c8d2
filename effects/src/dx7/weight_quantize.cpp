// 8-bit blur weights, plain or with Tron 2.0's error carry (weight_quantize.h).
#include "tierlift/effects/glow/weight_quantize.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace tierlift::effects {

std::string_view weight_rounding_name(WeightRounding r) {
  return r == WeightRounding::Plain ? "plain" : "error-carry";
}

std::optional<WeightRounding> parse_weight_rounding(std::string_view name) {
  if (name == "plain") return WeightRounding::Plain;
  if (name == "error-carry") return WeightRounding::ErrorCarry;
  return std::nullopt;
}

std::vector<uint8_t> quantize_weights(const std::vector<double>& weights, WeightRounding rounding) {
  std::vector<uint8_t> out;
  out.reserve(weights.size());
  double carry = 0;
  for (double w : weights) {
    const double x = 255.0 * w + (rounding == WeightRounding::ErrorCarry ? carry : 0.0);
    // std::round: halves away from zero (a D3DCOLOR is built by the application, not the
    // hardware, so this is the CPU's rounding).
    const double q = std::clamp(std::round(std::isfinite(x) ? x : 0.0), 0.0, 255.0);
    carry = x - q;
    out.push_back(static_cast<uint8_t>(q));
  }
  return out;
}

std::string quantization_summary(const std::vector<double>& weights, WeightRounding rounding) {
  double ideal = 0;
  unsigned sum = 0;
  const std::vector<uint8_t> q = quantize_weights(weights, rounding);
  for (size_t i = 0; i < weights.size(); ++i) ideal += 255.0 * weights[i], sum += q[i];
  const double ratio = ideal > 0 ? sum / ideal : 1.0;
  const double both = ratio * ratio;
  const char* way = ratio < 1 ? "darker" : "brighter";
  if (std::abs(1 - ratio) < 5e-5) // below the 0.01 % the message shows
    return fmt::format("weight rounding {}: sum of 8-bit weights {}/255 per axis against "
                       "{:.2f}/255 unquantised: the glow keeps its brightness",
                       weight_rounding_name(rounding), sum, ideal);
  return fmt::format("weight rounding {}: sum of 8-bit weights {}/255 per axis against {:.2f}/255 "
                     "unquantised: the glow is {:.2f} % {} per axis ({:.2f} % after both axes)",
                     weight_rounding_name(rounding), sum, ideal, std::abs(1 - ratio) * 100, way,
                     std::abs(1 - both) * 100);
}

} // namespace tierlift::effects
