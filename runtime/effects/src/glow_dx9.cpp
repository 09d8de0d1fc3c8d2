// Builds the dx9 glow graph (see glow.h).
#include <algorithm>

#include <fmt/format.h>

#include "tierlift/effects/builtin_listing.h"
#include "tierlift/effects/glow.h"

namespace tierlift::effects {
namespace {

struct Listings {
  std::shared_ptr<const ir::Program> quad4, extract, downsample, composite, blur_vs, blur_ps;
};

std::optional<Listings> load_listings(const GlowParams& p, std::string* error) {
  Listings l;
  const std::pair<std::shared_ptr<const ir::Program>*, const char*> wanted[] = {
      {&l.quad4, "glow/quad4_coords.vsh"},
      {&l.extract, "glow/extract_sources.psh"},
      {&l.downsample, "glow/downsample4.psh"},
      {&l.composite, "glow/composite_add.psh"},
      {&l.blur_vs, "gpugems21/listing1_blur8_coords.vsh"},
      {&l.blur_ps, "gpugems21/listing2_blur8_weighted_sum.psh"}};
  for (const auto& [slot, path] : wanted) {
    *slot = glow_listing(path, p.listing_files, error);
    if (!*slot) return std::nullopt;
  }
  return l;
}

cpu::SamplerState sampler(cpu::Filter filter) {
  cpu::SamplerState s;
  s.filter = filter;
  s.address_u = s.address_v = cpu::AddressMode::Clamp;
  return s;
}

cpu::Vec4 splat(double w) {
  const float f = static_cast<float>(w);
  return {f, f, f, f};
}

// glow/quad4_coords.vsh constants: offsets c0..c3, scales c4..c7 (unused ones read 0).
std::vector<cpu::Vec4> quad4_constants(const std::vector<std::array<double, 4>>& coords) {
  std::vector<cpu::Vec4> c(8, cpu::Vec4{0, 0, 0, 0});
  for (size_t k = 0; k < coords.size() && k < 4; ++k) {
    c[k] = {float(coords[k][0]), float(coords[k][1]), 0, 0};
    c[k + 4] = {float(coords[k][2]), float(coords[k][3]), 0, 0};
  }
  return c;
}

PassDesc pass(std::string name, std::shared_ptr<const ir::Program> vs,
              std::shared_ptr<const ir::Program> ps, std::string_view target) {
  PassDesc d;
  d.name = std::move(name);
  d.vs = std::move(vs);
  d.ps = std::move(ps);
  d.target = std::string(target);
  return d;
}

PassDesc extract_pass(const Listings& l, const GlowParams& p) {
  PassDesc d = pass("extract", l.quad4, l.extract, kSourcesTexture);
  d.analytic = AnalyticForm::MaskByAlpha;
  // Point reads at texel centres: offset ½ texel, scale 1.
  d.vs_constants = quad4_constants({{0.5 / p.width, 0.5 / p.height, 1, 1}});
  d.textures.push_back({0, std::string(kSceneTexture), sampler(cpu::Filter::Point)});
  return d;
}

PassDesc downsample_pass(const Listings& l, const GlowParams& p, uint32_t gw, uint32_t gh) {
  PassDesc d = pass("downsample", l.quad4, l.downsample, kSmallTexture);
  const unsigned n = p.downsample;
  // Pixel i of the small target reads source texels n·i … n·i + n − 1: scale the quad uv
  // so that u·W_src = n·i, then add the read position within the block.
  const double su = double(n) * gw / p.width, sv = double(n) * gh / p.height;
  std::vector<std::array<double, 4>> coords;
  for (const AxisRead& ry : downsample_reads(n))
    for (const AxisRead& rx : downsample_reads(n)) {
      coords.push_back({rx.position / p.width, ry.position / p.height, su, sv});
      d.ps_constants.push_back(splat(rx.weight * ry.weight));
    }
  d.vs_constants = quad4_constants(coords);
  d.ps_constants.resize(4, cpu::Vec4{0, 0, 0, 0});
  d.textures.push_back({0, std::string(kSourcesTexture), sampler(cpu::Filter::Linear)});
  return d;
}

// The blur passes of one axis: 8 taps each, Listing 1 offsets and Listing 2 weights.
void blur_passes(const Listings& l, const GlowParams& p, const std::vector<BlurTap>& taps,
                 bool vertical, const std::string& source, const std::string& target, uint32_t gw,
                 uint32_t gh, std::vector<PassDesc>& out) {
  const double h = p.half_texel ? 0.5 : 0.0;
  const size_t count = (taps.size() + kTapsPerBlurPassDx9 - 1) / kTapsPerBlurPassDx9;
  for (size_t i = 0; i < count; ++i) {
    PassDesc d =
        pass(fmt::format("{}.{}", vertical ? "blur_v" : "blur_h", i), l.blur_vs, l.blur_ps, target);
    for (size_t k = 0; k < kTapsPerBlurPassDx9; ++k) {
      const size_t t = i * kTapsPerBlurPassDx9 + k;
      // Padding taps read the centre with weight 0 (adds exactly 0 for finite images).
      const double off = t < taps.size() ? taps[t].offset : 0.0;
      const double w = t < taps.size() ? taps[t].weight : 0.0;
      const double du = vertical ? h : off + h, dv = vertical ? off + h : h;
      d.vs_constants.push_back({float(du / gw), float(dv / gh), 0, 0});
      d.ps_constants.push_back(splat(w));
    }
    d.textures.push_back({0, source, sampler(cpu::Filter::Linear)});
    d.blend = i == 0 ? cpu::BlendMode::Replace : cpu::BlendMode::OneOne;
    out.push_back(std::move(d));
  }
}

PassDesc composite_pass(const Listings& l, const GlowParams& p, uint32_t gw, uint32_t gh) {
  PassDesc d = pass("composite", l.quad4, l.composite, kFinalTexture);
  // Full-resolution pixel i lies at (i + ½)/n glow texels: u = v·W/(n·gw) + ½/(n·gw).
  const double nw = double(p.downsample) * gw, nh = double(p.downsample) * gh;
  d.vs_constants = quad4_constants(
      {{0.5 / p.width, 0.5 / p.height, 1, 1}, {0.5 / nw, 0.5 / nh, p.width / nw, p.height / nh}});
  d.textures.push_back({0, std::string(kSceneTexture), sampler(cpu::Filter::Point)});
  d.textures.push_back({1, std::string(kGlowTexture), sampler(cpu::Filter::Linear)});
  return d;
}

} // namespace

std::vector<AxisRead> downsample_reads(unsigned n) {
  switch (n) {
  case 1: return {{0.5, 1.0}};                         // texel centre
  case 2: return {{1.0, 1.0}};                         // midpoint of texels 0, 1
  case 3: return {{1.0, 2.0 / 3.0}, {2.5, 1.0 / 3.0}}; // mid of 0, 1; centre of 2
  case 4: return {{1.0, 0.5}, {3.0, 0.5}};             // mid of 0, 1; mid of 2, 3
  default: return {};
  }
}

GlowPlan build_glow_dx9(const GlowParams& p) {
  GlowPlan plan;
  if (p.downsample < 1 || p.downsample > 4) {
    plan.error = fmt::format("downsample {}: expected 1..4", p.downsample);
    return plan;
  }
  if (p.width == 0 || p.height == 0 || p.width > img::kMaxDimension ||
      p.height > img::kMaxDimension) {
    plan.error =
        fmt::format("scene size {}x{}: expected 1..{}", p.width, p.height, img::kMaxDimension);
    return plan;
  }
  plan.taps = sample_blur_profile(p.profile, p.downsample, &plan.error);
  if (plan.taps.empty()) return plan;
  std::optional<Listings> l = load_listings(p, &plan.error);
  if (!l) return plan;

  const uint32_t gw = (p.width + p.downsample - 1) / p.downsample;
  const uint32_t gh = (p.height + p.downsample - 1) / p.downsample;
  plan.glow_width = gw;
  plan.glow_height = gh;
  EffectGraph& g = plan.graph;
  g.conventions.subtexel_bits = p.subtexel_bits;
  auto tex = [&](std::string_view name, uint32_t w, uint32_t h, bool input = false) {
    g.textures.push_back({std::string(name), w, h, p.format, input});
  };
  tex(kSceneTexture, p.width, p.height, true);
  tex(kSourcesTexture, p.width, p.height);
  if (p.downsample > 1) tex(kSmallTexture, gw, gh);
  tex(kBlurHTexture, gw, gh);
  tex(kGlowTexture, gw, gh);
  tex(kFinalTexture, p.width, p.height);

  g.passes.push_back(extract_pass(*l, p));
  if (p.downsample > 1) g.passes.push_back(downsample_pass(*l, p, gw, gh));
  const std::string blur_src(p.downsample > 1 ? kSmallTexture : kSourcesTexture);
  blur_passes(*l, p, plan.taps, false, blur_src, std::string(kBlurHTexture), gw, gh, g.passes);
  blur_passes(*l, p, plan.taps, true, std::string(kBlurHTexture), std::string(kGlowTexture), gw, gh,
              g.passes);
  plan.blur_passes_per_axis =
      unsigned((plan.taps.size() + kTapsPerBlurPassDx9 - 1) / kTapsPerBlurPassDx9);
  g.passes.push_back(composite_pass(*l, p, gw, gh));
  plan.error = check_graph(g);
  return plan;
}

} // namespace tierlift::effects
