// The glow graph both tiers build (glow_common.h, glow.h).
#include "glow_common.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "tierlift/effects/glow/builtin_listing.h"

namespace tierlift::effects::detail {
namespace {

using ProgramPtr = std::shared_ptr<const ir::Program>;

struct Listings {
  ProgramPtr helper_vs, extract, downsample, composite, blur_vs, blur_ps;
  ProgramPtr mix;    // the after-image's (only with one)
  ProgramPtr fogged; // the fogged extract (only with fog)
};

ir::Result<Listings> load_listings(const EffectParams& p, const TierListingPaths& paths) {
  Listings l;
  const std::pair<ProgramPtr*, std::string_view> wanted[] = {
      {&l.helper_vs, paths.helper_vs},      {&l.extract, paths.extract_ps},
      {&l.downsample, paths.downsample_ps}, {&l.composite, paths.composite_ps},
      {&l.blur_vs, paths.blur_vs},          {&l.blur_ps, paths.blur_ps}};
  for (const auto& [slot, path] : wanted) {
    if (path.empty()) continue; // tier dx7 draws its blur from stage states
    ListingResult r = glow_listing(path, p.listing_files, p.listing_options);
    if (!r) return std::move(r).failure();
    *slot = std::move(r).value();
  }
  if (p.afterimage != Afterimage::Off) {
    ListingResult r = glow_listing(paths.mix_ps, p.listing_files, p.listing_options);
    if (!r) return std::move(r).failure();
    l.mix = std::move(r).value();
  }
  if (p.context.fog.on) {
    ListingResult r = glow_listing(paths.fogged_ps, p.listing_files, p.listing_options);
    if (!r) return std::move(r).failure();
    l.fogged = std::move(r).value();
  }
  return l;
}

pass::SamplerState sampler(pass::Filter filter) {
  pass::SamplerState s;
  s.filter = filter;
  s.address_u = s.address_v = pass::AddressMode::Clamp;
  return s;
}

pass::Vec4 splat(double w) {
  const float f = static_cast<float>(w);
  return {f, f, f, f};
}

// One coordinate of a helper pass: offset (u, v) and scale (u, v) of the quad uv.
struct Coord {
  double du = 0, dv = 0, su = 1, sv = 1;
};

// The helper vertex listing's constants: offsets c0..c3, scales c4..c7 (unused ones read 0).
std::vector<pass::Vec4> helper_vs_constants(const std::vector<Coord>& coords) {
  std::vector<pass::Vec4> c(8, pass::Vec4{0, 0, 0, 0});
  for (size_t k = 0; k < coords.size() && k < 4; ++k) {
    c[k] = {float(coords[k].du), float(coords[k].dv), 0, 0};
    c[k + 4] = {float(coords[k].su), float(coords[k].sv), 0, 0};
  }
  return c;
}

// The constant tables of a ramped parameter: splat(value(f) · factor) for each frame, the
// rest of `base` (c1, …) as it is. Empty when the parameter does not ramp.
std::vector<std::vector<pass::Vec4>> ramp_table(const Keyframes& ramp, double factor,
                                                const std::vector<pass::Vec4>& base, float alpha) {
  std::vector<std::vector<pass::Vec4>> table;
  for (double v : ramp_values(ramp)) {
    std::vector<pass::Vec4> c = base;
    const auto f = static_cast<float>(v * factor);
    c.at(0) = {f, f, f, alpha};
    table.push_back(std::move(c));
  }
  return table;
}

class Builder {
public:
  Builder(const EffectParams& p, const TierRecipe& r, const Listings& l, uint32_t gw, uint32_t gh)
      : p_(p), r_(r), l_(l), gw_(gw), gh_(gh) {}

  // The glow sources: rgb × alpha of the scene, or of the glow render when the scene has one
  // (a rendering context, glow_context.h); with fog, fogged by the depth texture read at the
  // same texel.
  PassDesc extract() const {
    const GlowContext& c = p_.context;
    const bool fog = c.fog.on;
    PassDesc d =
        listing_pass("extract", l_.helper_vs, fog ? l_.fogged : l_.extract, kSourcesTexture);
    d.analytic = fog ? AnalyticForm::MaskByAlphaFogged : AnalyticForm::MaskByAlpha;
    // Point reads at texel centres: offset ½ texel, scale 1 (both reads: same size).
    const Coord centre{0.5 / p_.width, 0.5 / p_.height};
    d.draw.vs_constants.f = helper_vs_constants({centre, centre});
    bind(d, 0, c.glow_image ? kGlowImageTexture : kSceneTexture, pass::Filter::Point, 1);
    if (fog) {
      bind(d, 1, kDepthTexture, pass::Filter::Point, 1);
      // A ps.1.x listing scales its fog factor by 4 (_x4): its constants clamp to [-1, 1].
      for (const auto& k : fog_constants(c.fog, ir::is_ps1x(l_.fogged->profile) ? 4 : 1))
        d.draw.ps_constants.f.push_back(k);
    }
    return d;
  }

  // The box average of each N×N block, as point reads at texel centres, four a pass (the
  // helper listings have four coordinates), the passes summed by ONE/ONE blending (the first
  // replaces). Point reads, not bilinear reads between texels: a texture coordinate is an
  // fp32 value, about N·2^-24 texel off at N texels (6e-5 at 1280), and a bilinear read
  // meant for a midpoint turns that into a weight error of the same size, visible at the
  // sharp edges of the glow sources; a point read at a texel centre is 0.5 texel from any
  // other texel, so every device and the analytic model read the same texels.
  void downsample(std::vector<PassDesc>& out) const {
    const unsigned n = p_.downsample;
    // Pixel i of the small target reads source texels n·i … n·i + n − 1: scale the quad uv
    // so that u·W_src = n·i, then add the read position within the block.
    const double su = double(n) * gw_ / p_.width, sv = double(n) * gh_ / p_.height;
    std::vector<std::pair<Coord, double>> reads;
    for (const AxisRead& ry : downsample_reads(n))
      for (const AxisRead& rx : downsample_reads(n))
        reads.push_back(
            {{rx.position / p_.width, ry.position / p_.height, su, sv}, rx.weight * ry.weight});
    constexpr size_t kPerPass = 4;
    for (size_t first = 0; first < reads.size(); first += kPerPass) {
      PassDesc d = listing_pass(fmt::format("downsample.{}", first / kPerPass), l_.helper_vs,
                                l_.downsample, kSmallTexture);
      std::vector<Coord> coords;
      for (size_t k = first; k < std::min(reads.size(), first + kPerPass); ++k) {
        coords.push_back(reads[k].first);
        d.draw.ps_constants.f.push_back(splat(reads[k].second));
      }
      d.draw.vs_constants.f = helper_vs_constants(coords);
      // Reads beyond those needed have weight 0 and read texel (0, 0): they add exactly 0.
      d.draw.ps_constants.f.resize(kPerPass, pass::Vec4{0, 0, 0, 0});
      bind(d, 0, kSourcesTexture, pass::Filter::Point, kPerPass);
      d.draw.blend = first == 0 ? pass::BlendMode::Replace : pass::BlendMode::OneOne;
      out.push_back(std::move(d));
    }
  }

  // The blur passes of one axis: taps_per_blur_pass taps each, offsets (k + ½)/size in the
  // blur listing's c0.., weights in the pixel listing's c0.. (the article's rule).
  void blur(const std::vector<BlurTap>& taps, bool vertical, std::string_view source,
            std::string_view target, std::vector<PassDesc>& out) const {
    if (r_.stage_blur) return blur_stages(taps, vertical, source, target, out);
    if (r_.loop_blur) return blur_loop(taps, vertical, source, target, out);
    const double h = p_.half_texel ? 0.5 : 0.0;
    const unsigned per = r_.taps_per_blur_pass;
    const size_t count = (taps.size() + per - 1) / per;
    for (size_t i = 0; i < count; ++i) {
      PassDesc d = listing_pass(fmt::format("{}.{}", vertical ? "blur_v" : "blur_h", i), l_.blur_vs,
                                l_.blur_ps, target);
      for (size_t k = 0; k < per; ++k) {
        const size_t t = i * per + k;
        // Padding taps read the centre with weight 0 (adds exactly 0 for finite images).
        const double off = t < taps.size() ? taps[t].offset : 0.0;
        const double w = t < taps.size() ? taps[t].weight : 0.0;
        const double du = vertical ? h : off + h, dv = vertical ? off + h : h;
        d.draw.vs_constants.f.push_back({float(du / gw_), float(dv / gh_), 0, 0});
        d.draw.ps_constants.f.push_back(splat(w * p_.weight_scale));
      }
      // A ramped weight scale: every weight of the pass times the frame's scale.
      for (double scale : ramp_values(p_.weight_scale_ramp)) {
        std::vector<pass::Vec4> c;
        for (size_t k = 0; k < per; ++k) {
          const size_t t = i * per + k;
          c.push_back(splat(t < taps.size() ? taps[t].weight * scale : 0.0));
        }
        d.ps_constants_per_frame.push_back(std::move(c));
      }
      bind(d, 0, source, p_.half_texel ? pass::Filter::Point : pass::Filter::Linear, per);
      d.draw.blend = i == 0 ? pass::BlendMode::Replace : pass::BlendMode::OneOne;
      out.push_back(std::move(d));
    }
  }

  // Tier dx9c: pass i loops over taps i·per … (at most per of them, no padding): tap k of the
  // pass has its uv offset in ps c(2k+1) and its weight in c(2k+2), i0 = (n, 1, 2, 0). The
  // analytic model takes the same kernel as stated, with the offsets and weights the
  // devices see (the float constants), since it cannot read a loop.
  void blur_loop(const std::vector<BlurTap>& taps, bool vertical, std::string_view source,
                 std::string_view target, std::vector<PassDesc>& out) const {
    const double h = p_.half_texel ? 0.5 : 0.0;
    const size_t per = r_.taps_per_blur_pass;
    for (size_t first = 0, i = 0; first < taps.size(); first += per, ++i) {
      PassDesc d = listing_pass(fmt::format("{}.{}", vertical ? "blur_v" : "blur_h", i), l_.blur_vs,
                                l_.blur_ps, target);
      const size_t n = std::min(per, taps.size() - first);
      d.draw.ps_constants.f.push_back({0, 0, 0, 0}); // c0: the listing's def
      d.analytic = AnalyticForm::Kernel;
      for (size_t t = first; t < first + n; ++t) {
        const double du = vertical ? h : taps[t].offset + h, dv = vertical ? taps[t].offset + h : h;
        const pass::Vec4 offset{float(du / gw_), float(dv / gh_), 0, 0};
        const pass::Vec4 weight = splat(taps[t].weight * p_.weight_scale);
        d.draw.ps_constants.f.push_back(offset);
        d.draw.ps_constants.f.push_back(weight);
        KernelTap k;
        k.pixel_add = true;
        k.offset = {offset[0], offset[1]};
        k.weight = {weight[0], weight[1], weight[2], weight[3]};
        d.kernel.push_back(k);
      }
      d.draw.ps_constants.i[0] = {static_cast<int32_t>(n), 1, 2, 0};
      bind(d, 0, source, p_.half_texel ? pass::Filter::Point : pass::Filter::Linear, 1);
      d.draw.blend = i == 0 ? pass::BlendMode::Replace : pass::BlendMode::OneOne;
      out.push_back(std::move(d));
    }
  }

  // Tier dx7: quad i draws taps 2i and 2i + 1 through the lowered stage states; both weights
  // ride in one D3DCOLOR (rgb = byte of tap 2i, alpha = byte of tap 2i + 1, each byte/255 as
  // the device reads an 8-bit colour). An odd last quad pads with weight 0 at the centre.
  void blur_stages(const std::vector<BlurTap>& taps, bool vertical, std::string_view source,
                   std::string_view target, std::vector<PassDesc>& out) const {
    const double h = p_.half_texel ? 0.5 : 0.0;
    // The weight scale multiplies the weights before they are rounded to bytes, as an
    // application would scale them before writing the vertex colours; a ramped scale rounds
    // each frame's weights anew (per-frame diffuse constants).
    auto bytes_for = [&](double scale) {
      std::vector<double> weights;
      for (const BlurTap& t : taps) weights.push_back(t.weight * scale);
      return quantize_weights(weights, r_.rounding);
    };
    const std::vector<uint8_t> bytes = bytes_for(p_.weight_scale);
    std::vector<std::vector<uint8_t>> frame_bytes;
    for (double scale : ramp_values(p_.weight_scale_ramp)) frame_bytes.push_back(bytes_for(scale));
    auto diffuse = [&](const std::vector<uint8_t>& b, size_t i) {
      std::array<float, 2> w{};
      for (size_t k = 0; k < 2; ++k) {
        const size_t t = 2 * i + k;
        w[k] = t < taps.size() ? tss::d3dcolor_channel(b[t]) : 0.0f;
      }
      return pass::Vec4{w[0], w[0], w[0], w[1]};
    };
    const size_t count = (taps.size() + 1) / 2;
    for (size_t i = 0; i < count; ++i) {
      PassDesc d = listing_pass(fmt::format("{}.{}", vertical ? "blur_v" : "blur_h", i),
                                r_.stage_blur->vs, r_.stage_blur->ps, target);
      d.draw.vs_constants.f.assign(tss::kSpecularConstant + 1, pass::Vec4{0, 0, 0, 0});
      for (size_t k = 0; k < 2; ++k) {
        const size_t t = 2 * i + k;
        const double off = t < taps.size() ? taps[t].offset : 0.0;
        const double du = vertical ? h : off + h, dv = vertical ? off + h : h;
        d.draw.vs_constants.f[k] = {float(du / gw_), float(dv / gh_), 0, 0};
      }
      d.draw.vs_constants.f[tss::kDiffuseConstant] = diffuse(bytes, i);
      for (const std::vector<uint8_t>& b : frame_bytes) {
        d.vs_constants_per_frame.push_back(d.draw.vs_constants.f);
        d.vs_constants_per_frame.back()[tss::kDiffuseConstant] = diffuse(b, i);
      }
      bind(d, 0, source, p_.half_texel ? pass::Filter::Point : pass::Filter::Linear,
           r_.stage_blur->texture_stages);
      d.draw.blend = i == 0 ? pass::BlendMode::Replace : pass::BlendMode::OneOne;
      out.push_back(std::move(d));
    }
  }

  PassDesc composite() const {
    PassDesc d = listing_pass("composite", l_.helper_vs, l_.composite, kFinalTexture);
    // Full-resolution pixel i lies at (i + ½)/n glow texels: u = v·W/(n·gw) + ½/(n·gw).
    const double nw = double(p_.downsample) * gw_, nh = double(p_.downsample) * gh_;
    d.draw.vs_constants.f = helper_vs_constants(
        {{0.5 / p_.width, 0.5 / p_.height}, {0.5 / nw, 0.5 / nh, p_.width / nw, p_.height / nh}});
    // check_params keeps intensity finite and within the tier's limit (≤ FLT_MAX).
    const auto s = static_cast<float>(p_.intensity / r_.composite_divisor);
    d.draw.ps_constants.f = {pass::Vec4{s, s, s, 0}};
    d.ps_constants_per_frame =
        ramp_table(p_.intensity_ramp, 1 / r_.composite_divisor, d.draw.ps_constants.f, 0);
    // Scene on stage / sampler 0, glow on 1, in both tiers (t0/s0 and t1/s1).
    bind(d, 0, kSceneTexture, pass::Filter::Point, 1);
    bind(d, 1, kGlowTexture, pass::Filter::Linear, 1);
    return d;
  }

  // The after-image's mix: fed = x + g·previous (x: what the blur would read, previous: the
  // saved fed texture or last frame's glow), point reads at the glow's texel centres.
  PassDesc afterimage_mix(std::string_view x, std::string_view previous) const {
    PassDesc d = listing_pass("afterimage", l_.helper_vs, l_.mix, kFedTexture);
    d.draw.vs_constants.f = helper_vs_constants({{0.5 / gw_, 0.5 / gh_}, {0.5 / gw_, 0.5 / gh_}});
    const auto g = static_cast<float>(p_.afterimage_gain / r_.mix_divisor);
    d.draw.ps_constants.f = {pass::Vec4{g, g, g, 0}};
    d.ps_constants_per_frame =
        ramp_table(p_.afterimage_gain_ramp, 1 / r_.mix_divisor, d.draw.ps_constants.f, 0);
    bind(d, 0, x, pass::Filter::Point, 1);
    bind(d, 1, previous, pass::Filter::Point, 1);
    return d;
  }

  // Afterimage::Sources keeps this frame's fed texture for the next: the mix listing with
  // c0 = 0 (t0 + 0·t1 = t0 exactly), since a pass may not read its own target.
  PassDesc afterimage_save() const {
    PassDesc d = listing_pass("afterimage_save", l_.helper_vs, l_.mix, kSavedTexture);
    d.draw.vs_constants.f = helper_vs_constants({{0.5 / gw_, 0.5 / gh_}, {0.5 / gw_, 0.5 / gh_}});
    d.draw.ps_constants.f = {pass::Vec4{0, 0, 0, 0}};
    bind(d, 0, kFedTexture, pass::Filter::Point, 1);
    bind(d, 1, kFedTexture, pass::Filter::Point, 1);
    return d;
  }

private:
  // A texture the pixel listing reads `reads` times from `stage` on: once on that sampler
  // (ps_2_0), or on stages stage..stage + reads − 1 (ps_1_x, t# reads stage #).
  void bind(PassDesc& d, uint32_t stage, std::string_view texture, pass::Filter filter,
            unsigned reads) const {
    bind_reads(d, stage, texture, sampler(filter), reads, r_.one_stage_per_read);
  }

  const EffectParams& p_;
  const TierRecipe& r_;
  const Listings& l_;
  uint32_t gw_, gh_;
};

std::string check_params(const EffectParams& p, const TierRecipe& r) {
  if (p.downsample < 1 || p.downsample > 4)
    return fmt::format("downsample {}: expected 1..4", p.downsample);
  if (!img::valid_size(p.width, p.height))
    return fmt::format("scene size {}x{}: expected 1..{}", p.width, p.height, img::kMaxDimension);
  if (!std::isfinite(p.intensity) || p.intensity < 0)
    return fmt::format("intensity {}: expected a finite value >= 0", p.intensity);
  const double top = p.intensity_ramp.max(p.intensity);
  if (top > r.max_intensity)
    return fmt::format("intensity {}: tier {} reaches at most {} ({})", top, r.tier,
                       r.max_intensity, r.why_limit);
  const double gain = p.afterimage_gain_ramp.max(p.afterimage_gain);
  if (!std::isfinite(p.afterimage_gain) || p.afterimage_gain < 0 || gain > r.max_intensity)
    return fmt::format("after-image gain {}: expected 0..{} on tier {}", gain, r.max_intensity,
                       r.tier);
  if (!std::isfinite(p.weight_scale) || p.weight_scale < 0)
    return fmt::format("weight scale {}: expected a finite value >= 0", p.weight_scale);
  if (r.taps_per_blur_pass == 0) return fmt::format("tier {}: no taps per blur pass", r.tier);
  if (r.loop_blur && !p.weight_scale_ramp.empty())
    return fmt::format("weight scale ramp: tier {} states its blur kernel to the analytic model "
                       "once, so its weights cannot ramp; use tier dx9",
                       r.tier);
  const GlowFog& fog = p.context.fog;
  if (fog.on && !(std::isfinite(fog.start) && std::isfinite(fog.end) && fog.start < fog.end))
    return fmt::format("fog start {} and end {}: expected finite values, start < end", fog.start,
                       fog.end);
  const img::Image* glow = p.context.glow_image.get();
  if (glow && (glow->width != p.width || glow->height != p.height))
    return fmt::format("glow image {}x{}: expected the scene's size {}x{}", glow->width,
                       glow->height, p.width, p.height);
  return {};
}

} // namespace

TierRecipe ps1x_recipe(const EffectParams& params) {
  const bool above_one = params.intensity_ramp.max(params.intensity) > 1;
  const bool gain_above_one = params.afterimage_gain_ramp.max(params.afterimage_gain) > 1;
  const std::string_view plain = "glow/composite_add_ps13.psh",
                         x4 = "glow/composite_add_x4_ps13.psh";
  TierRecipe r;
  r.listings.helper_vs = "glow/quad4_coords_vs11.vsh";
  r.listings.extract_ps = "glow/extract_sources_ps11.psh";
  r.listings.downsample_ps = "glow/downsample4_ps13.psh";
  r.listings.composite_ps = above_one ? x4 : plain;
  r.listings.mix_ps = gain_above_one ? x4 : plain;
  r.listings.fogged_ps = "glow/extract_fogged_ps11.psh";
  r.one_stage_per_read = true; // tex t# reads texture stage #
  r.constants_clamp_to_one = true;
  r.composite_divisor = above_one ? 4 : 1;
  r.mix_divisor = gain_above_one ? 4 : 1;
  r.max_intensity = 4;
  return r;
}

PlanResult build_glow_graph(const EffectParams& p, const TierRecipe& r) {
  EffectPlan plan;
  if (std::string e = check_params(p, r); !e.empty()) return plan_failure(std::move(e));
  ir::Result<std::vector<BlurTap>> taps = sample_blur_profile(p.profile, p.downsample);
  if (!taps) return plan_failure(taps.message());
  plan.taps = std::move(taps).value();
  if (r.constants_clamp_to_one) {
    size_t above = 0;
    double top = 0;
    const double scale = p.weight_scale_ramp.max(p.weight_scale);
    for (const BlurTap& t : plan.taps)
      if (t.weight * scale > 1) ++above, top = std::max(top, t.weight * scale);
    if (above > 0)
      plan.warnings.push_back(
          fmt::format("profile: {} tap weight(s) above 1 (up to {}); tier {} uses 1 for them (a "
                      "ps.1.x constant clamps to [-1, 1])",
                      above, top, r.tier));
  }
  ir::Result<Listings> l = load_listings(p, r.listings);
  if (!l) return plan_failure(l.message());
  if (p.context.fog.on && ir::is_ps1x(l->fogged->profile))
    if (std::string why = fog_ps1x_limit(p.context.fog); !why.empty())
      return plan_failure(fmt::format("tier {}: {}", r.tier, why));

  const uint32_t gw = (p.width + p.downsample - 1) / p.downsample;
  const uint32_t gh = (p.height + p.downsample - 1) / p.downsample;
  plan.glow_width = gw;
  plan.glow_height = gh;
  plan.downsample = p.downsample;
  EffectGraph& g = plan.graph;
  g.conventions.subtexel_bits = p.subtexel_bits;
  g.conventions.ps1x_max_value = p.ps1x_max;
  auto tex = [&](std::string_view name, uint32_t w, uint32_t h, bool input = false) {
    g.textures.push_back({std::string(name), w, h, p.format, input});
  };
  tex(kSceneTexture, p.width, p.height, true);
  // The rendering context's inputs travel with the graph (TextureDesc::contents).
  if (p.context.glow_image) {
    tex(kGlowImageTexture, p.width, p.height, true);
    g.textures.back().contents = p.context.glow_image;
  }
  if (p.context.fog.on) {
    tex(kDepthTexture, p.width, p.height, true);
    g.textures.back().contents =
        std::make_shared<const img::Image>(fog_depth_texture(p.context.fog, p.width, p.height));
  }
  tex(kSourcesTexture, p.width, p.height);
  if (p.downsample > 1) tex(kSmallTexture, gw, gh);
  tex(kBlurHTexture, gw, gh);
  tex(kGlowTexture, gw, gh);
  tex(kFinalTexture, p.width, p.height);
  if (p.afterimage != Afterimage::Off) tex(kFedTexture, gw, gh);
  if (p.afterimage == Afterimage::Sources) tex(kSavedTexture, gw, gh);

  const Builder b(p, r, *l, gw, gh);
  g.passes.push_back(b.extract());
  if (p.downsample > 1) b.downsample(g.passes);
  std::string_view blur_src = p.downsample > 1 ? kSmallTexture : kSourcesTexture;
  if (p.afterimage != Afterimage::Off) {
    // Sources: last frame's fed texture (saved); Glow: last frame's glow, read before this
    // frame's blur writes it. Both start at zero in the first frame.
    g.passes.push_back(b.afterimage_mix(
        blur_src, p.afterimage == Afterimage::Sources ? kSavedTexture : kGlowTexture));
    if (p.afterimage == Afterimage::Sources) g.passes.push_back(b.afterimage_save());
    blur_src = kFedTexture;
  }
  b.blur(plan.taps, false, blur_src, kBlurHTexture, g.passes);
  b.blur(plan.taps, true, kBlurHTexture, kGlowTexture, g.passes);
  plan.blur_passes_per_axis =
      unsigned((plan.taps.size() + r.taps_per_blur_pass - 1) / r.taps_per_blur_pass);
  if (r.stage_blur) {
    std::vector<double> weights;
    for (const BlurTap& t : plan.taps) weights.push_back(t.weight * p.weight_scale);
    plan.weight_bytes = quantize_weights(weights, r.rounding);
    plan.quantization = quantization_summary(weights, r.rounding);
  }
  g.passes.push_back(b.composite());
  if (ir::Status checked = check_graph(g); !checked) return plan_failure(checked.message());
  return plan;
}

} // namespace tierlift::effects::detail

namespace tierlift::effects {

std::vector<AxisRead> downsample_reads(unsigned n) {
  std::vector<AxisRead> reads;
  for (unsigned k = 0; k < n && n <= 4; ++k) reads.push_back({k + 0.5, 1.0 / n});
  return reads;
}

} // namespace tierlift::effects
