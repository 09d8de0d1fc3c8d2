// The glow render and the glow fog's inputs and constants (glow_context.h).
#include "tierlift/effects/glow/glow_context.h"

#include <cmath>

#include <fmt/format.h>

namespace tierlift::effects {

img::Image fog_depth_texture(const GlowFog& fog, uint32_t width, uint32_t height) {
  img::Image out(width, height, img::Format::RGBA32F);
  const img::Image* depth = fog.depth.get();
  const bool usable = depth && depth->width == width && depth->height == height;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      // The built-in floor: the row's centre as a fraction of the height, counted from the
      // bottom, so the top rows are the far ones.
      const float d = usable ? depth->at(x, y)[0] : float(1.0 - (y + 0.5) / height);
      float* p = out.at(x, y);
      p[0] = p[1] = p[2] = d;
      p[3] = 1;
    }
  return out;
}

std::array<std::array<float, 4>, 3> fog_constants(const GlowFog& fog, double scale) {
  const double span = fog.end - fog.start;
  const auto slope = static_cast<float>(-1 / span / scale);
  const auto bias = static_cast<float>(fog.end / span / scale);
  return {{{slope, slope, slope, slope},
           {bias, bias, bias, bias},
           {float(fog.color[0]), float(fog.color[1]), float(fog.color[2]), 0}}};
}

std::string fog_ps1x_limit(const GlowFog& fog) {
  const double span = fog.end - fog.start;
  const double slope = 1 / span / 4, bias = fog.end / span / 4;
  if (slope > 1)
    return fmt::format("fog from {} to {} is {} deep; a ps.1.x constant holds at most 1, so the "
                       "fog factor's slope 1/(4·(end − start)) needs end − start >= 0.25",
                       fog.start, fog.end, span);
  if (std::abs(bias) > 1)
    return fmt::format("fog from {} to {}: a ps.1.x constant holds at most 1, so end/(4·(end − "
                       "start)) = {:.4g} must lie in [-1, 1]",
                       fog.start, fog.end, bias);
  return {};
}

std::string context_summary(const GlowContext& c) {
  if (!c.on()) return {};
  std::string line = fmt::format("glow sources: the {}'s rgb × alpha",
                                 c.glow_image ? "glow image" : "scene image");
  if (c.fog.on)
    line += fmt::format(", fogged from depth {} to {} toward ({}, {}, {}) (depth: {})", c.fog.start,
                        c.fog.end, c.fog.color[0], c.fog.color[1], c.fog.color[2],
                        c.fog.depth ? "the depth image's red channel" : "the built-in floor");
  return line;
}

} // namespace tierlift::effects
