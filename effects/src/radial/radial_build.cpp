// The radial-beams graph (radial.h): star, zoom passes, composite, in the tier's listings.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "tierlift/effects/glow/builtin_listing.h"
#include "tierlift/effects/glow/radial.h"

namespace tierlift::effects {
namespace {

using ProgramPtr = std::shared_ptr<const ir::Program>;

struct TierListings {
  std::string_view star_vs, star_ps, zoom_vs, zoom_ps, composite_ps;
  unsigned per_pass = 0;           // zoomed copies a pass: the texture coordinates there are
  bool one_stage_per_read = false; // ps.1.x: t# reads stage #, so a texture takes 4 stages
  double max_strength = 0;         // ps.1.x constants clamp to [-1, 1]
};

TierListings tier_listings(Tier tier) {
  if (tier == Tier::Dx8)
    return {"radial/star4_vs11.vsh",
            "radial/star_average_ps11.psh",
            "radial/zoom4_vs11.vsh",
            "radial/zoom4_ps13.psh",
            "radial/composite_ps13.psh",
            4,
            true,
            1.0};
  return {"radial/star4.vsh",
          "radial/star_average.psh",
          "radial/zoom8.vsh",
          "radial/zoom8.psh",
          "radial/composite.psh",
          8,
          false,
          3.0e38};
}

pass::SamplerState sampler(pass::Filter filter, pass::AddressMode address) {
  pass::SamplerState s;
  s.filter = filter;
  s.address_u = s.address_v = address;
  return s;
}

pass::Vec4 splat(double w) {
  const float f = static_cast<float>(w);
  return {f, f, f, f};
}

std::string check(const EffectParams& g, const RadialParams& r, const TierListings& t) {
  if (!img::valid_size(g.width, g.height))
    return fmt::format("scene size {}x{}: expected 1..{}", g.width, g.height, img::kMaxDimension);
  for (double c : r.centre)
    if (!std::isfinite(c) || c < 0 || c > 1)
      return fmt::format("radial centre {}: expected 0..1", c);
  if (r.steps < 1 || r.steps > 256) return fmt::format("radial steps {}: expected 1..256", r.steps);
  // The last copy must still face the right way: scale 1 − 2·N·step > 0.
  if (!std::isfinite(r.step) || r.step <= 0 || 2.0 * r.steps * r.step >= 1)
    return fmt::format("radial step {}: expected > 0 and 2·steps·step < 1 (steps {})", r.step,
                       r.steps);
  if (!std::isfinite(r.strength) || r.strength < 0 || r.strength > t.max_strength)
    return fmt::format("radial strength {}: expected 0..{}", r.strength, t.max_strength);
  if (!std::isfinite(r.amplitude) || r.amplitude < 0 || r.amplitude > 4096)
    return fmt::format("radial amplitude {}: expected 0..4096 texels", r.amplitude);
  if (!std::isfinite(r.rate) || r.rate <= 0)
    return fmt::format("radial rate {}: expected a finite value > 0", r.rate);
  if (r.frames > 100000) return fmt::format("radial frames {}: expected 1..100000", r.frames);
  return {};
}

} // namespace

std::vector<RadialCopy> radial_copies(const RadialParams& r, uint32_t width, uint32_t height) {
  std::vector<RadialCopy> out;
  const double size[2] = {double(width), double(height)};
  for (unsigned i = 1; i <= r.steps; ++i) {
    RadialCopy c;
    c.scale = 1 - 2.0 * i * r.step;
    // u' = c + ((x + ½)/W − c)·s = s·(x/W) + [s·½/W + c·(1 − s)]
    for (int a = 0; a < 2; ++a) c.offset[a] = c.scale * 0.5 / size[a] + r.centre[a] * (1 - c.scale);
    c.weight = (1.0 / 8.0) * double(r.steps - i) / double(r.steps);
    out.push_back(c);
  }
  return out;
}

std::array<std::array<double, 2>, 4> star_offsets(const RadialParams& r, unsigned frame,
                                                  uint32_t width, uint32_t height) {
  // Four functions of time that never coincide: different frequencies and phases per set.
  constexpr double kFreq[4][2] = {{0.70, 0.45}, {-0.55, 0.80}, {0.35, -0.65}, {-0.90, -0.30}};
  constexpr double kPhase[4] = {0.0, 1.3, 2.6, 4.1};
  const double t = double(frame) / r.rate;
  std::array<std::array<double, 2>, 4> out{};
  for (int k = 0; k < 4; ++k) {
    const double dx = r.amplitude * std::sin(kFreq[k][0] * t + kPhase[k]) -
                      r.amplitude * std::sin(kPhase[k]); // 0 at time 0
    const double dy =
        r.amplitude * std::cos(kFreq[k][1] * t + kPhase[k]) - r.amplitude * std::cos(kPhase[k]);
    out[k] = {(dx + 0.5) / width, (dy + 0.5) / height};
  }
  return out;
}

PlanResult build_radial(const EffectParams& g, const RadialParams& r) {
  EffectPlan plan;
  const TierListings t = tier_listings(g.tier);
  if (std::string e = check(g, r, t); !e.empty()) return plan_failure(std::move(e));
  ProgramPtr star_vs, star_ps, zoom_vs, zoom_ps, composite_ps;
  const std::pair<ProgramPtr*, std::string_view> wanted[] = {{&star_vs, t.star_vs},
                                                             {&star_ps, t.star_ps},
                                                             {&zoom_vs, t.zoom_vs},
                                                             {&zoom_ps, t.zoom_ps},
                                                             {&composite_ps, t.composite_ps}};
  for (const auto& [slot, path] : wanted) {
    ListingResult l = glow_listing(path, g.listing_files, g.listing_options);
    if (!l) return plan_failure(l.message());
    *slot = std::move(l).value();
  }
  EffectGraph& graph = plan.graph;
  graph.conventions.subtexel_bits = g.subtexel_bits;
  graph.conventions.ps1x_max_value = g.ps1x_max;
  for (std::string_view name : {kSceneTexture, kStarTexture, kGlowTexture, kFinalTexture})
    graph.textures.push_back(
        {std::string(name), g.width, g.height, g.format, name == kSceneTexture});
  plan.glow_width = g.width;
  plan.glow_height = g.height;

  // The star: the scene image tiled (wrap), four moving reads averaged.
  PassDesc star = listing_pass("star", star_vs, star_ps, kStarTexture);
  const unsigned frames = r.moves() ? std::max(1u, r.frames) : 1u;
  for (unsigned f = 0; f < frames; ++f) {
    std::vector<pass::Vec4> offsets;
    for (const auto& o : star_offsets(r, r.frame + f, g.width, g.height))
      offsets.push_back({float(o[0]), float(o[1]), 0, 0});
    if (f == 0) star.draw.vs_constants.f = offsets;
    if (frames > 1) star.vs_constants_per_frame.push_back(std::move(offsets));
  }
  star.draw.ps_constants.f = {splat(0.25)};
  bind_reads(star, 0, kSceneTexture, sampler(pass::Filter::Linear, pass::AddressMode::Wrap), 4,
             t.one_stage_per_read);
  graph.passes.push_back(std::move(star));

  // The beams: per_pass copies a pass, offsets c0.., scales c(per_pass)..; padding copies
  // have scale 0, offset 0 and weight 0 (a read of texel (0, 0) times 0 adds exactly 0).
  const std::vector<RadialCopy> copies = radial_copies(r, g.width, g.height);
  const size_t passes = (copies.size() + t.per_pass - 1) / t.per_pass;
  for (size_t p = 0; p < passes; ++p) {
    PassDesc d = listing_pass(fmt::format("zoom.{}", p), zoom_vs, zoom_ps, kGlowTexture);
    std::vector<pass::Vec4> offsets, scales;
    for (size_t k = 0; k < t.per_pass; ++k) {
      const size_t i = p * t.per_pass + k;
      const RadialCopy c = i < copies.size() ? copies[i] : RadialCopy{0, {0, 0}, 0};
      offsets.push_back({float(c.offset[0]), float(c.offset[1]), 0, 0});
      scales.push_back({float(c.scale), float(c.scale), 0, 0});
      d.draw.ps_constants.f.push_back(splat(c.weight));
    }
    d.draw.vs_constants.f = offsets;
    d.draw.vs_constants.f.insert(d.draw.vs_constants.f.end(), scales.begin(), scales.end());
    bind_reads(d, 0, kStarTexture, sampler(pass::Filter::Linear, pass::AddressMode::Clamp),
               t.per_pass, t.one_stage_per_read);
    d.draw.blend = p == 0 ? pass::BlendMode::Replace : pass::BlendMode::OneOne;
    graph.passes.push_back(std::move(d));
  }
  plan.blur_passes_per_axis = unsigned(passes);

  // The composite: star on stage 0, beams on 1, both read at texel centres.
  PassDesc comp = listing_pass("composite", zoom_vs, composite_ps, kFinalTexture);
  std::vector<pass::Vec4> c(2 * t.per_pass, pass::Vec4{0, 0, 0, 0});
  for (size_t k = 0; k < 2; ++k) {
    c[k] = {float(0.5 / g.width), float(0.5 / g.height), 0, 0};
    c[t.per_pass + k] = {1, 1, 0, 0};
  }
  comp.draw.vs_constants.f = c;
  const auto s = static_cast<float>(r.strength);
  comp.draw.ps_constants.f = {pass::Vec4{s, s, s, 0}};
  bind_reads(comp, 0, kStarTexture, sampler(pass::Filter::Point, pass::AddressMode::Clamp), 1,
             false);
  bind_reads(comp, 1, kGlowTexture, sampler(pass::Filter::Point, pass::AddressMode::Clamp), 1,
             false);
  graph.passes.push_back(std::move(comp));
  if (ir::Status checked = check_graph(graph); !checked) return plan_failure(checked.message());
  return plan;
}

} // namespace tierlift::effects
