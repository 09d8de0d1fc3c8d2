// The one registry of effects a scene may name (effect_kinds), and the dispatch on it:
// "effect" read with its own object ("radial", "outline", "glsl"; an object for another
// effect is an error at its key), and the graph each effect builds. Every dispatch is a
// switch on EffectKind, so an effect added to the enum without a case does not compile.
#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

constexpr std::array<EffectInfo, 4> kEffects{{
    {EffectKind::Glow, "glow", ""},
    {EffectKind::RadialBeams, "radial-beams", "radial"},
    {EffectKind::StencilOutline, "stencil-outline", "outline"},
    {EffectKind::GlslBlur, "glsl-blur", "glsl"},
}};

// The names alone, for scene_effects() (the schema's list).
constexpr std::array<std::string_view, kEffects.size()> kEffectNames = [] {
  std::array<std::string_view, kEffects.size()> names{};
  for (size_t i = 0; i < kEffects.size(); ++i) names[i] = kEffects[i].name;
  return names;
}();

std::string expected_effects() {
  std::string out;
  for (size_t i = 0; i < kEffects.size(); ++i)
    out += fmt::format("{}\"{}\"",
                       i == 0                     ? ""
                       : i + 1 == kEffects.size() ? " or "
                                                  : ", ",
                       kEffects[i].name);
  return out;
}

// The effect's own object: present only with that effect.
bool owned_by(EffectKind effect, FieldChecker& c, const Scene& s) {
  if (s.effect == effect) return true;
  const EffectInfo& info = effect_info(effect);
  c.error(fmt::format("/{}", info.object),
          fmt::format("\"{}\" configures \"effect\": \"{}\"; this scene's effect is \"{}\"",
                      info.object, info.name, effect_name(s.effect)),
          true);
  return false;
}

} // namespace

std::span<const EffectInfo> effect_kinds() {
  return kEffects;
}

const EffectInfo& effect_info(EffectKind kind) {
  for (const EffectInfo& e : kEffects)
    if (e.kind == kind) return e;
  return kEffects[0]; // unreachable: every kind is in the registry (a test checks it)
}

std::optional<EffectKind> parse_effect_kind(std::string_view name) {
  for (const EffectInfo& e : kEffects)
    if (e.name == name) return e.kind;
  return std::nullopt;
}

std::span<const std::string_view> scene_effects() {
  return kEffectNames;
}

void read_effect(const Json& j, FieldChecker& c, const std::string& base_dir, Scene& s) {
  if (const Json* v = member(j, "effect")) {
    std::optional<std::string> name = c.string(*v, "/effect");
    if (!name) return;
    std::optional<EffectKind> kind = parse_effect_kind(*name);
    if (!kind) {
      c.error("/effect",
              fmt::format("\"{}\" is not an effect; expected {}", *name, expected_effects()));
      return;
    }
    s.effect = *kind;
  }
  if (const Json* v = member(j, "radial"))
    if (owned_by(EffectKind::RadialBeams, c, s)) read_radial(*v, c, s.params, s.radial);
  if (const Json* v = member(j, "outline"))
    if (owned_by(EffectKind::StencilOutline, c, s)) read_outline(*v, c, s.outline);
  if (const Json* v = member(j, "glsl"))
    if (owned_by(EffectKind::GlslBlur, c, s)) read_glsl(*v, c, base_dir, s.glsl);
}

bool scene_animated(const Scene& scene) {
  switch (scene.effect) {
  case EffectKind::RadialBeams: return scene.radial.moves();
  case EffectKind::Glow:
  case EffectKind::StencilOutline:
  case EffectKind::GlslBlur: break;
  }
  return scene.params.animated();
}

PlanResult build_scene_effect(const Scene& scene) {
  switch (scene.effect) {
  case EffectKind::RadialBeams: return build_radial(scene.params, scene.radial);
  case EffectKind::StencilOutline: return build_outline(scene.params, scene.outline);
  case EffectKind::GlslBlur: return build_glsl_blur(scene.params, scene.glsl);
  case EffectKind::Glow: break;
  }
  return build_glow(scene.params);
}

std::vector<std::string> effect_warnings(const Scene& scene) {
  switch (scene.effect) {
  case EffectKind::GlslBlur: return glsl_blur_warnings(scene.glsl);
  case EffectKind::Glow:
  case EffectKind::RadialBeams:
  case EffectKind::StencilOutline: break;
  }
  return glow_warnings(scene.params);
}

} // namespace tierlift::effects
