// The tier switch of the glow generators (glow.h).
#include <fmt/format.h>

#include "tierlift/effects/glow.h"

namespace tierlift::effects {

std::string_view tier_name(Tier tier) {
  return tier == Tier::Dx8 ? "dx8" : "dx9";
}

std::optional<Tier> parse_tier(std::string_view name) {
  if (name == "dx9") return Tier::Dx9;
  if (name == "dx8") return Tier::Dx8;
  return std::nullopt;
}

std::vector<Tier> all_tiers() {
  std::vector<Tier> tiers;
  // A scoped enum's underlying type is int, so every int converts to a Tier value.
  for (int i = 0; i < 64; ++i) {
    const auto t = static_cast<Tier>(i);
    if (parse_tier(tier_name(t)) != t) break;
    tiers.push_back(t);
  }
  return tiers;
}

GlowPlan build_glow(const GlowParams& params) {
  return params.tier == Tier::Dx8 ? build_glow_dx8(params) : build_glow_dx9(params);
}

} // namespace tierlift::effects
