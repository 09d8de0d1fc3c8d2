// RGBA8 rounding midpoints, interpreter against the analytic device (three_way_test.cpp
// runs all three ways). First the downsample's midpoints, found by independent math: the
// model settles them in the devices' fp32 arithmetic, so it stores the interpreter's bytes
// there too, and its slack mask may flag only such midpoints. Then every replacing pass of
// the glow run on the SAME inputs by the two devices: each pass alone stores the same bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "three_way_scenes.h"
#include "tierlift/effects/glow/glow_run.h"
#include "tierlift/effects/graph/agreement.h"
#include "tierlift/effects/graph/analytic_device.h"

namespace tierlift::effects {
namespace {

// rgb and alpha random multiples of 1/255 (the glow sources then hold many midpoints).
img::Image random_scene(uint32_t w, uint32_t h, uint32_t seed) {
  return test_scenes::random_bytes(w, h, seed);
}

// The RGBA8 downsample, checked against independent math: the passes point-read the
// sources (8-bit texels, s steps of 1/255) at the texel centres of each N×N block, four
// reads a pass in row order (x fastest), weight 1/N², summed by ONE/ONE on the 8-bit target.
// Each pass stores (stored so far) + S/N² steps, S the sum of its reads' steps: a rounding
// midpoint exactly where S/N² has the fraction ½. The interpreter and the model must store
// the same byte everywhere, midpoints included (the model decides them in fp32 as the devices
// do), and the analytic device's slack mask (its proven fp32 ties, kept over the ONE/ONE
// passes) may flag only pixels with such a midpoint in some pass so far.
TEST(ThreeWayRgba8, DownsampleStoresTheInterpretersBytesAtExactMidpoints) {
  for (unsigned n : {2u, 3u, 4u}) {
    SCOPED_TRACE(n);
    EffectParams p;
    p.downsample = n;
    p.format = img::Format::RGBA8;
    p.width = 50;
    p.height = 31;
    const img::Image scene = random_scene(p.width, p.height, 1122);
    PlanResult plan_built = build_glow(p);
    ASSERT_TRUE(plan_built) << plan_built.message();
    EffectPlan& plan = *plan_built;
    CpuPassDevice cpu_dev(2);
    AnalyticPassDevice analytic;
    EffectRun a = run_effect(plan, scene, cpu_dev, true),
              b = run_effect(plan, scene, analytic, true);
    ASSERT_TRUE(a.run.ok() && b.run.ok()) << a.run.message() << b.run.message();
    ASSERT_EQ(a.run->passes[0].result.rgba, b.run->passes[0].result.rgba) << "extract";
    const img::Image& src = b.run->passes[0].result; // the glow sources, 8-bit
    const uint32_t gw = plan.glow_width, gh = plan.glow_height;
    auto steps_at = [&](uint32_t x, uint32_t y, int c) { // clamp addressing
      return std::lround(
          double(src.at(std::min(x, src.width - 1), std::min(y, src.height - 1))[c]) * 255.0);
    };
    const unsigned reads = n * n, passes = (reads + 3) / 4;
    size_t midpoint_values = 0, differ = 0, flagged = 0;
    std::vector<uint8_t> any_so_far(size_t(gw) * gh, 0); // a midpoint in some pass so far
    for (unsigned i = 0; i < passes; ++i) {
      // Per value: a midpoint in this pass (the store of its own reads, before ONE/ONE).
      std::vector<uint8_t> midpoint(size_t(gw) * gh * 4, 0);
      const size_t index = 1 + i;
      ASSERT_EQ(plan.graph.passes[index].name, "downsample." + std::to_string(i));
      for (uint32_t y = 0; y < gh; ++y)
        for (uint32_t x = 0; x < gw; ++x)
          for (int c = 0; c < 4; ++c) {
            long sum = 0;
            for (unsigned r = 4 * i; r < std::min(reads, 4 * i + 4); ++r)
              sum += steps_at(n * x + r % n, n * y + r / n, c);
            // sum / N² has the fraction ½: 2·sum ≡ N² (mod 2N²).
            if ((2 * sum) % (2 * long(reads)) == long(reads))
              midpoint[(size_t(y) * gw + x) * 4 + size_t(c)] = 1;
          }
      const PassRecord &ra = a.run->passes[index], &rb = b.run->passes[index];
      ASSERT_EQ(rb.midpoints.size(), size_t(gw) * gh) << "the analytic device keeps a mask";
      for (size_t px = 0; px < rb.midpoints.size(); ++px) {
        if (midpoint[4 * px] || midpoint[4 * px + 1] || midpoint[4 * px + 2] ||
            midpoint[4 * px + 3])
          any_so_far[px] = 1;
        if (rb.midpoints[px] != 0) {
          flagged += i + 1 == passes;
          EXPECT_TRUE(any_so_far[px])
              << ra.pass << " pixel " << px << " is flagged but met no midpoint";
          EXPECT_LE(rb.midpoints[px], 1) << ra.pass << " pixel " << px;
        }
        for (size_t c = 0; c < 4; ++c) {
          const size_t v = 4 * px + c;
          midpoint_values += midpoint[v];
          if (ra.result.rgba[v] != rb.result.rgba[v]) ++differ;
        }
      }
    }
    EXPECT_EQ(differ, 0u) << "values the interpreter and the model store differently";
    // N = 2 and 4 average 8-bit texels with power-of-two weights: midpoints are common (so the
    // equality above is tested where it is hardest). N = 3 cannot meet one (S/9 never has
    // the fraction ½).
    if (n == 3)
      EXPECT_EQ(midpoint_values, 0u);
    else
      EXPECT_GT(midpoint_values, 0u);
    std::printf("[three-way] rgba8 downsample %u: %zu values at exact midpoints over %u passes, "
                "%zu stored differently by the interpreter and the model, %zu pixels flagged as "
                "fp32 ties\n",
                n, midpoint_values, passes, differ, flagged);
  }
}

// The one-pass graph of `pass`, every texture it binds an input holding `images`' copy.
EffectGraph one_pass_graph(const EffectGraph& g, const PassDesc& pass) {
  EffectGraph one;
  one.conventions = g.conventions;
  for (const TextureBind& b : pass.textures) {
    if (one.find_texture(b.texture)) continue;
    TextureDesc t = *g.find_texture(b.texture);
    t.input = true;
    one.textures.push_back(t);
  }
  TextureDesc target = *g.find_texture(pass.target);
  target.input = false;
  one.textures.push_back(target);
  one.passes.push_back(pass);
  return one;
}

TEST(ThreeWaySameInputs, Rgba8ReplacingPassesAgreeAlone) {
  for (Tier tier : {Tier::Dx9, Tier::Dx8})
    for (unsigned n : {2u, 4u})
      for (uint32_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(std::string(tier_name(tier)) + " N " + std::to_string(n) + " seed " +
                     std::to_string(seed));
        EffectParams p;
        p.tier = tier;
        p.downsample = n;
        p.format = img::Format::RGBA8;
        p.width = 50;
        p.height = 31;
        PlanResult plan_built = build_glow(p);
        ASSERT_TRUE(plan_built) << plan_built.message();
        EffectPlan& plan = *plan_built;
        CpuPassDevice cpu_dev(2);
        // The interpreter's images after every pass: the inputs each pass gets.
        EffectRun whole = run_effect(plan, random_scene(p.width, p.height, seed), cpu_dev, true);
        ASSERT_TRUE(whole.run.ok()) << whole.run.message();
        ImageMap state{{std::string(kSceneTexture), whole.images.at(std::string(kSceneTexture))}};
        uint64_t midpoint_pixels = 0, differing = 0;
        for (size_t i = 0; i < plan.graph.passes.size(); ++i) {
          const PassDesc& d = plan.graph.passes[i];
          if (d.draw.blend == cpu::BlendMode::Replace) {
            const EffectGraph one = one_pass_graph(plan.graph, d);
            ImageMap ia = state, ib = state;
            CpuPassDevice c1(2);
            AnalyticPassDevice an;
            ir::Result<GraphRun> ra = run_graph(one, c1, ia, true),
                                 rb = run_graph(one, an, ib, true);
            ASSERT_TRUE(ra.ok() && rb.ok()) << ra.message() << rb.message();
            ir::Result<RunAgreement> agree_compared = compare_runs(*ra, ia, *rb, ib, d.target);
            ASSERT_TRUE(agree_compared.ok()) << agree_compared.message();
            const RunAgreement& agree = *agree_compared;
            for (const PassAgreement& row : agree.passes)
              EXPECT_TRUE(row.verdict.pass) << d.name << ": " << row.verdict.summary;
            midpoint_pixels += agree.passes[0].midpoint_pixels;
            differing +=
                agree.passes[0].comparison.pixels - agree.passes[0].comparison.identical_pixels;
          }
          state[d.target] = whole.run->passes[i].result;
        }
        // Fed the same inputs, every pass stores the interpreter's bytes: no pixel differs,
        // so none needs the slack either.
        EXPECT_EQ(differing, 0u);
        EXPECT_EQ(midpoint_pixels, 0u);
        std::printf("[same-inputs] %s N %u seed %u: %llu pixels differ\n",
                    std::string(tier_name(tier)).c_str(), n, seed,
                    static_cast<unsigned long long>(differing));
      }
}

} // namespace
} // namespace tierlift::effects
