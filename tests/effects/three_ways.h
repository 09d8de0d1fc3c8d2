// The three ways a glow plan runs (interpreter, Vulkan, analytic model) for the tests that
// make them agree: the devices side by side, one run of a plan on each, and every pair of
// those runs compared pass by pass. The names ("cpu", "vulkan", "analytic") are the ones the
// failure messages print.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"

namespace tierlift::effects::test_ways {

struct ThreeDevices {
  explicit ThreeDevices(vulkan::Device& dev) : vk(make_vulkan_pass_device(dev)) {}
  CpuPassDevice cpu{2};
  AnalyticPassDevice analytic;
  std::unique_ptr<PassDevice> vk;
  std::array<PassDevice*, 3> all() { return {&cpu, vk.get(), &analytic}; }
};

using NamedRuns = std::vector<std::pair<std::string, EffectRun>>;

// The plan run once on each way, every pass's images kept for compare_pairs.
inline NamedRuns run_three_ways(const EffectPlan& plan, const img::Image& scene,
                                ThreeDevices& ways) {
  NamedRuns runs;
  runs.emplace_back("cpu", run_effect(plan, scene, ways.cpu, true));
  runs.emplace_back("vulkan", run_effect(plan, scene, *ways.vk, true));
  runs.emplace_back("analytic", run_effect(plan, scene, ways.analytic, true));
  return runs;
}

// Compares every pair of runs on the final texture and hands each agreement to check(a, b,
// agreement), a and b the ways' names.
template <class Check> void compare_pairs(const NamedRuns& runs, Check check) {
  for (size_t a = 0; a < runs.size(); ++a)
    for (size_t b = a + 1; b < runs.size(); ++b) {
      ir::Result<RunAgreement> agree =
          compare_runs(*runs[a].second.run, runs[a].second.images, *runs[b].second.run,
                       runs[b].second.images, std::string(kFinalTexture));
      ASSERT_TRUE(agree.ok()) << agree.message();
      check(runs[a].first, runs[b].first, *agree);
    }
}

} // namespace tierlift::effects::test_ways
