// The one list of effects a scene may name, and the dispatch on it: "effect" read with its
// own object ("radial", "outline", "glsl"; an object for another effect is an error at its
// key), and the graph each effect builds.
#include <algorithm>

#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/scene.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kEffects[] = {"glow", "radial-beams", "stencil-outline", "glsl-blur"};

std::string expected_effects() {
  std::string out;
  for (size_t i = 0; i < std::size(kEffects); ++i)
    out += fmt::format("{}\"{}\"",
                       i == 0                         ? ""
                       : i + 1 == std::size(kEffects) ? " or "
                                                      : ", ",
                       kEffects[i]);
  return out;
}

// The effect's own object: present only with that effect.
bool owned_by(std::string_view key, std::string_view effect, FieldChecker& c, const Scene& s) {
  if (s.effect == effect) return true;
  c.error(fmt::format("/{}", key),
          fmt::format("\"{}\" configures \"effect\": \"{}\"; this scene's effect is \"{}\"", key,
                      effect, s.effect),
          true);
  return false;
}

} // namespace

std::span<const std::string_view> scene_effects() {
  return kEffects;
}

void read_effect(const Json& j, FieldChecker& c, const std::string& base_dir, Scene& s) {
  if (const Json* v = member(j, "effect")) {
    std::optional<std::string> name = c.string(*v, "/effect");
    if (!name) return;
    if (std::find(std::begin(kEffects), std::end(kEffects), *name) == std::end(kEffects)) {
      c.error("/effect",
              fmt::format("\"{}\" is not an effect; expected {}", *name, expected_effects()));
      return;
    }
    s.effect = *name;
  }
  if (const Json* v = member(j, "radial"))
    if (owned_by("radial", "radial-beams", c, s)) read_radial(*v, c, s.params, s.radial);
  if (const Json* v = member(j, "outline"))
    if (owned_by("outline", "stencil-outline", c, s)) read_outline(*v, c, s.outline);
  if (const Json* v = member(j, "glsl"))
    if (owned_by("glsl", "glsl-blur", c, s)) read_glsl(*v, c, base_dir, s.glsl);
}

bool scene_animated(const Scene& scene) {
  if (scene.effect == "radial-beams") return scene.radial.moves();
  return scene.params.animated();
}

PlanResult build_scene_effect(const Scene& scene) {
  if (scene.effect == "radial-beams") return build_radial(scene.params, scene.radial);
  if (scene.effect == "stencil-outline") return build_outline(scene.params, scene.outline);
  if (scene.effect == "glsl-blur") return build_glsl_blur(scene.params, scene.glsl);
  return build_glow(scene.params);
}

std::vector<std::string> effect_warnings(const Scene& scene) {
  if (scene.effect == "glsl-blur") return glsl_blur_warnings(scene.glsl);
  return glow_warnings(scene.params);
}

} // namespace tierlift::effects
