// Small helpers the glow-plan tests share: parameters for a target size and downsample
// factor, a plan that must build, and the names of a plan's passes in order.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tierlift/effects/glow/glow.h"

namespace tierlift::effects::plan_test {

// The profile the plan tests' hand-counted taps and passes assume: σ 8 px (weight 0.7) +
// σ 1.5 px (0.3), the glow's default before the default became the visible σ 16 px.
inline BlurProfile two_gaussians() {
  BlurProfile p;
  p.terms = {{8.0, 0.7}, {1.5, 0.3}};
  return p;
}

inline EffectParams sized(unsigned downsample, uint32_t w, uint32_t h) {
  EffectParams p;
  p.width = w;
  p.height = h;
  p.downsample = downsample;
  p.profile = two_gaussians();
  return p;
}

// The plan, or (a failure recorded) an empty one.
inline EffectPlan expect_built(PlanResult plan) {
  if (!plan) {
    ADD_FAILURE() << plan.message();
    return {};
  }
  return std::move(*plan);
}

inline std::vector<std::string> pass_names(const EffectPlan& plan) {
  std::vector<std::string> v;
  for (const PassDesc& d : plan.graph.passes) v.push_back(d.name);
  return v;
}

} // namespace tierlift::effects::plan_test
