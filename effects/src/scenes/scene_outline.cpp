// Reads a "stencil-outline" scene's "outline" object: the polygon, its two colours and the
// stencil reference the object writes. Ranges are those of listings/scenes/README.md.
#include <algorithm>

#include <fmt/format.h>

#include "scene_parts.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

constexpr std::string_view kOutlineKeys[] = {"center", "radius",     "sides",      "rotation",
                                             "color",  "glow_color", "stencil_ref"};
constexpr NumberRange kPosition{-32768, 32768};
constexpr NumberRange kPolygonRadius{0, 32768, true};
constexpr NumberRange kDegrees{-360, 360};
constexpr NumberRange kChannel{0, 1000};

// [a, b, …] of `n` numbers in `range` into out[0..n).
template <size_t N>
void read_numbers(const Json& v, const std::string& at, FieldChecker& c, NumberRange range,
                  std::array<double, N>& out) {
  c.numbers(v, at, range, out, fmt::format("an array of {} numbers", N));
}

void read_color(const Json& v, const std::string& at, FieldChecker& c, std::array<float, 4>& out) {
  std::array<double, 4> d{out[0], out[1], out[2], out[3]};
  read_numbers(v, at, c, kChannel, d);
  for (size_t i = 0; i < 4; ++i) out[i] = static_cast<float>(d[i]);
}

} // namespace

void read_outline(const Json& v, FieldChecker& c, OutlineParams& o) {
  if (!c.object(v, "/outline", kOutlineKeys)) return;
  if (const Json* x = member(v, "center")) {
    std::array<double, 2> p{o.center_x, o.center_y};
    read_numbers(*x, "/outline/center", c, kPosition, p);
    o.center_x = p[0];
    o.center_y = p[1];
  }
  if (const Json* x = member(v, "radius"))
    o.radius = c.number(*x, "/outline/radius", kPolygonRadius).value_or(o.radius);
  if (const Json* x = member(v, "sides"))
    o.sides = static_cast<uint32_t>(c.integer(*x, "/outline/sides", 3, 64).value_or(o.sides));
  if (const Json* x = member(v, "rotation"))
    o.rotation = c.number(*x, "/outline/rotation", kDegrees).value_or(o.rotation);
  if (const Json* x = member(v, "color")) read_color(*x, "/outline/color", c, o.color);
  if (const Json* x = member(v, "glow_color"))
    read_color(*x, "/outline/glow_color", c, o.glow_color);
  // The outline pass adds the glow where the stencil is 0, so the object's mark is 1..255
  // (the buffer has 8 bits; D3DRS_STENCILREF beyond them is out of range here).
  if (const Json* x = member(v, "stencil_ref"))
    o.stencil_ref = static_cast<uint32_t>(
        c.integer(*x, "/outline/stencil_ref", 1, 255).value_or(o.stencil_ref));
}

std::span<const std::string_view> scene_outline_keys() {
  return kOutlineKeys;
}

} // namespace tierlift::effects
