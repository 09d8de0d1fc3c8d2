// The scene `tierlift glow` runs with no input, made in code: bright neon strips and a few
// small round lights (alpha 1: they glow) and one grey panel (alpha 0: lit but not glowing)
// on a dark ground (alpha 0). Every feature is placed relative to the size, so a small test
// scene shows the same layout. Colours are multiples of 1/255, exact in every format.
#pragma once

#include <cstdint>

#include "tierlift/image/image.h"

namespace tierlift::effects {

inline constexpr uint32_t kDefaultSceneWidth = 1280, kDefaultSceneHeight = 720;

// Strip thickness max(1, h/60); light radius max(1, h/90).
// Ground: (10, 10, 16)/255; panel: (90, 90, 100)/255; glowing colours have a channel of 1.
// `light_orbit` (pixels) and `angle` (radians) move the three round lights on circles of
// that radius, a third of a turn apart (EffectParams::motion); 0: where they always are.
img::Image make_default_scene(uint32_t width = kDefaultSceneWidth,
                              uint32_t height = kDefaultSceneHeight,
                              img::Format format = img::Format::RGBA32F, double light_orbit = 0,
                              double angle = 0);

} // namespace tierlift::effects
