// The tier switch of the glow generators (glow.h).
#include <fmt/format.h>

#include "tierlift/effects/glow/glow.h"

namespace tierlift::effects {

std::string_view tier_name(Tier tier) {
  switch (tier) {
  case Tier::Dx8: return "dx8";
  case Tier::Dx7: return "dx7";
  case Tier::Dx9c: return "dx9c";
  case Tier::Dx9: break;
  }
  return "dx9";
}

std::optional<Tier> parse_tier(std::string_view name) {
  if (name == "dx9") return Tier::Dx9;
  if (name == "dx8") return Tier::Dx8;
  if (name == "dx7") return Tier::Dx7;
  if (name == "dx9c") return Tier::Dx9c;
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

PlanResult build_glow(const EffectParams& params) {
  switch (params.tier) {
  case Tier::Dx8: return build_glow_dx8(params);
  case Tier::Dx7: return build_glow_dx7(params);
  case Tier::Dx9c: return build_glow_dx9c(params);
  case Tier::Dx9: break;
  }
  return build_glow_dx9(params);
}

} // namespace tierlift::effects
