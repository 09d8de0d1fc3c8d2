// Blur weights as 8-bit vertex colours (tier dx7): a D3DCOLOR channel holds byte/255, so each
// tap weight w becomes a byte. Two ways to choose the bytes (selected by a scene's
// "weight_rounding"):
//   plain        q_k = round(255 w_k): each tap within ½ step, but the errors add up, and the
//                glow comes out darker or brighter than the unquantised kernel;
//   error-carry  Tron 2.0's fix: round, then add what rounding left over to the next weight
//                (x_k = 255 w_k + carry, q_k = round(x_k), carry = x_k − q_k). The running sum
//                Σ_{j≤k} q_j stays within ½ step of Σ_{j≤k} 255 w_j, so the kernel's total is
//                kept to within ½ step (0.13 · 255 = 33.15 → 33, carry 0.15).
// Weights above 1 are clamped to 255 (the colour's range) and negative ones to 0; a message
// then says so.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tierlift::effects {

enum class WeightRounding { Plain, ErrorCarry };
std::string_view weight_rounding_name(WeightRounding r); // "plain", "error-carry"
std::optional<WeightRounding> parse_weight_rounding(std::string_view name);

// The bytes (0..255), in the order of `weights` (the order the quads are drawn).
std::vector<uint8_t> quantize_weights(const std::vector<double>& weights, WeightRounding rounding);

// "weight rounding error-carry: sum of 8-bit weights 255/255 per axis against 255.00/255
// unquantised: the glow is 0.000 % darker (0.000 % after both axes)" — the brightness of the
// quantised kernel against the unquantised one; both axes use the same bytes, so the glow is
// scaled by the square of the per-axis ratio.
std::string quantization_summary(const std::vector<double>& weights, WeightRounding rounding);

} // namespace tierlift::effects
