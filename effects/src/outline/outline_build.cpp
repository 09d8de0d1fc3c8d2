// The stencil outline's graph (outline.h): the dx9 glow's graph rewired around an object
// pass. The glow builds the blur exactly as it does for the glow effect; this file adds the
// object pass in front, points the glow's extract at the object's mask, and splits the
// composite into a full-screen base and a stencil-tested outline pass.
#include "tierlift/effects/glow/outline.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace tierlift::effects {
namespace {

std::string check_outline(const EffectParams& g, const OutlineParams& o) {
  if (g.tier != Tier::Dx9)
    return fmt::format("tier {}: the stencil outline needs tier dx9 (two render targets are a "
                       "ps_2_0 feature)",
                       tier_name(g.tier));
  if (o.sides < 3 || o.sides > 64) return fmt::format("sides {}: expected 3..64", o.sides);
  for (double v : {o.center_x, o.center_y, o.radius, o.rotation})
    if (!std::isfinite(v)) return "polygon: centre, radius and rotation must be finite";
  if (o.stencil_ref < 1 || o.stencil_ref > 255)
    return fmt::format("stencil_ref {}: expected 1..255 (8 stencil bits; 0 marks outside)",
                       o.stencil_ref);
  if (o.radius <= 0) return fmt::format("radius {}: expected > 0", o.radius);
  // Clip space stays within the rasteriser's guard band (|x|, |y| ≤ 8·w).
  const double limit = 3.0 * std::max(g.width, g.height);
  if (std::abs(o.center_x) + o.radius > limit || std::abs(o.center_y) + o.radius > limit)
    return fmt::format("polygon reaches {} pixels from the scene: keep it within {}",
                       std::abs(o.center_x) + o.radius, limit);
  return {};
}

pass::Vec4 vec(const std::array<float, 4>& a) {
  return {a[0], a[1], a[2], a[3]};
}

void rename_reads(PassDesc& d, std::string_view from, std::string_view to) {
  for (TextureBind& b : d.textures)
    if (b.texture == from) b.texture = std::string(to);
}

} // namespace

std::vector<std::array<double, 2>> outline_polygon(const OutlineParams& o) {
  std::vector<std::array<double, 2>> corners;
  for (uint32_t k = 0; k < o.sides; ++k) {
    const double a = (o.rotation + 360.0 * k / o.sides) * std::numbers::pi / 180.0;
    corners.push_back({o.center_x + o.radius * std::cos(a), o.center_y + o.radius * std::sin(a)});
  }
  return corners;
}

PlanResult build_outline(const EffectParams& glow, const OutlineParams& o) {
  if (std::string e = check_outline(glow, o); !e.empty()) return plan_failure(std::move(e));
  PlanResult built = build_glow(glow);
  if (!built) return built;
  EffectPlan plan = std::move(*built);
  EffectGraph& g = plan.graph;
  std::shared_ptr<const ir::Program> object_vs, object_ps, add_ps;
  const std::pair<std::shared_ptr<const ir::Program>*, std::string_view> wanted[] = {
      {&object_vs, "outline/object.vsh"},
      {&object_ps, "outline/object_mrt.psh"},
      {&add_ps, "outline/add_glow.psh"}};
  for (const auto& [slot, path] : wanted) {
    ListingResult l = glow_listing(path, glow.listing_files, glow.listing_options);
    if (!l) return plan_failure(l.message());
    *slot = std::move(l).value();
  }

  // Textures: the glow's, plus the object's two targets and the stencil buffer.
  const uint32_t w = glow.width, h = glow.height;
  g.textures.push_back({std::string(kColorTexture), w, h, glow.format, false});
  g.textures.push_back({std::string(kMaskTexture), w, h, glow.format, false});
  TextureDesc stencil{std::string(kStencilTexture), w, h, img::Format::RGBA32F, false};
  stencil.stencil = true;
  g.textures.push_back(stencil);

  // The object: a fan around the centre, clip-space positions in v0.
  PassDesc object;
  object.name = "object";
  object.analytic = AnalyticForm::Coverage;
  object.draw.vertex_program = object_vs;
  object.draw.pixel_program = object_ps;
  object.draw.ps_constants.f = {vec(o.color), vec(o.glow_color)};
  object.target = std::string(kColorTexture);
  object.more_targets = {std::string(kMaskTexture)};
  object.stencil = std::string(kStencilTexture);
  object.draw.depth_stencil.stencil_test = true;
  object.draw.depth_stencil.stencil_func = pass::CompareFunc::Always;
  object.draw.depth_stencil.stencil_pass = pass::StencilOp::Replace;
  object.draw.depth_stencil.stencil_ref = o.stencil_ref;
  auto clip = [&](double x, double y) {
    pass::VertexInput v;
    v.v[0] = {static_cast<float>(2.0 * x / w - 1.0), static_cast<float>(1.0 - 2.0 * y / h), 0.0f,
              1.0f};
    return v;
  };
  object.draw.vertices.push_back(clip(o.center_x, o.center_y));
  for (const auto& c : outline_polygon(o)) object.draw.vertices.push_back(clip(c[0], c[1]));
  for (uint32_t k = 0; k < o.sides; ++k)
    object.draw.triangles.push_back({0, 1 + k, 1 + (k + 1) % o.sides});

  // The glow's passes read the mask where they read the scene; its composite becomes the
  // base (scene + colour) and a stencil-tested pass adds the glow.
  std::vector<PassDesc> passes{object};
  for (PassDesc& d : g.passes) {
    if (d.name == "composite") continue;
    rename_reads(d, kSceneTexture, kMaskTexture);
    passes.push_back(std::move(d));
  }
  const PassDesc* composite = nullptr;
  for (const PassDesc& d : g.passes)
    if (d.name == "composite") composite = &d;
  if (!composite) return plan_failure("the glow graph has no composite pass");
  PassDesc base = *composite;
  base.name = "base";
  base.draw.ps_constants.f = {pass::Vec4{1, 1, 1, 0}};
  // t1 reads the full-size colour texture at pixel centres: offset ½ texel, scale 1.
  base.draw.vs_constants.f[1] = {static_cast<float>(0.5 / w), static_cast<float>(0.5 / h), 0, 0};
  base.draw.vs_constants.f[5] = {1, 1, 0, 0};
  for (TextureBind& b : base.textures)
    if (b.stage == 1) {
      b.texture = std::string(kColorTexture);
      base.draw.textures[1].sampler.filter = pass::Filter::Point;
    }
  PassDesc outline = *composite;
  outline.name = "outline";
  outline.draw.pixel_program = add_ps;
  const auto s = static_cast<float>(glow.intensity);
  outline.draw.ps_constants.f = {pass::Vec4{s, s, s, 0}};
  std::erase_if(outline.textures, [](const TextureBind& b) { return b.stage != 1; });
  outline.draw.blend = pass::BlendMode::OneOne;
  outline.stencil = std::string(kStencilTexture);
  outline.draw.depth_stencil.stencil_test = true;
  outline.draw.depth_stencil.stencil_func = pass::CompareFunc::Equal;
  outline.draw.depth_stencil.stencil_ref = 0;
  passes.push_back(std::move(base));
  passes.push_back(std::move(outline));
  g.passes = std::move(passes);
  if (ir::Status checked = check_graph(g); !checked) return plan_failure(checked.message());
  return plan;
}

} // namespace tierlift::effects
