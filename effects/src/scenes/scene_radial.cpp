// Reads a scene's "radial" object (effect "radial-beams"): centre, steps, step, strength,
// tier, amplitude, rate, frame. Ranges are those of listings/scenes/README.md; each error
// sits at the offending value.
#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kRadialKeys[] = {"centre", "steps",     "step", "strength",
                                            "tier",   "amplitude", "rate", "frame"};

constexpr NumberRange kUnit{0, 1};
constexpr NumberRange kStep{0, 0.5, true};
constexpr NumberRange kAmplitude{0, 4096};
constexpr NumberRange kRate{0, 1e6, true};

} // namespace

std::span<const std::string_view> scene_radial_keys() {
  return kRadialKeys;
}

void read_radial(const Json& v, FieldChecker& c, EffectParams& glow, RadialParams& r) {
  const std::string at = "/radial";
  if (!c.object(v, at, kRadialKeys)) return;
  if (const Json* t = member(v, "tier"))
    if (auto name = c.string(*t, at + "/tier")) {
      if (auto tier = parse_tier(*name); tier && (*tier == Tier::Dx9 || *tier == Tier::Dx8))
        glow.tier = *tier;
      else
        c.error(at + "/tier",
                fmt::format("\"{}\" is not a tier; expected \"dx9\" or \"dx8\"", *name));
    }
  if (const Json* ce = member(v, "centre"))
    c.numbers(*ce, at + "/centre", kUnit, r.centre, "[x, y] (texture coordinates, 0..1)");
  if (const Json* n = member(v, "steps"))
    r.steps = unsigned(c.integer(*n, at + "/steps", 1, 256).value_or(r.steps));
  if (const Json* s = member(v, "step")) {
    if (auto x = c.number(*s, at + "/step", kStep)) {
      // The last copy's texture range [N·step, 1 − N·step] must not turn inside out.
      if (2.0 * r.steps * *x >= 1)
        c.error(at + "/step", fmt::format("{} with {} steps zooms past the centre (2 · steps · "
                                          "step = {} must stay below 1)",
                                          FieldChecker::shown(*s), r.steps, 2.0 * r.steps * *x));
      else
        r.step = *x;
    }
  } else if (2.0 * r.steps * r.step >= 1) {
    c.error(at + "/steps", fmt::format("{} steps of the default step {} zoom past the centre "
                                       "(2 · steps · step must stay below 1)",
                                       r.steps, r.step));
  }
  if (const Json* s = member(v, "strength")) {
    const bool dx8 = glow.tier == Tier::Dx8;
    // ps.1.x: the composite's constant clamps to [-1, 1].
    const NumberRange range{0, dx8 ? 1.0 : 1000.0};
    if (auto x = c.number(*s, at + "/strength", range)) r.strength = *x;
  }
  if (const Json* a = member(v, "amplitude"))
    r.amplitude = c.number(*a, at + "/amplitude", kAmplitude).value_or(r.amplitude);
  if (const Json* a = member(v, "rate"))
    r.rate = c.number(*a, at + "/rate", kRate).value_or(r.rate);
  if (const Json* f = member(v, "frame"))
    r.frame = unsigned(c.integer(*f, at + "/frame", 0, 1000000).value_or(r.frame));
}

} // namespace tierlift::effects
