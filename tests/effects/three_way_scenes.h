// The source images the three-way tests run the glow on: two random scenes of odd sizes and
// the default scene. The random ones hold rgb as random multiples of 1/255 and alpha either
// in {0, 1} or a random multiple of 1/255; the seeds are fixed, so every run sees the same.
#pragma once

#include <cstdint>
#include <random>

#include "tierlift/effects/scenes/default_scene.h"
#include "tierlift/image/image.h"

namespace tierlift::effects::test_scenes {

enum class Scene { RandomBinaryAlpha, RandomAlpha, Default };

inline img::Image make_scene(Scene s, uint32_t& w, uint32_t& h) {
  if (s == Scene::Default) {
    w = 96, h = 54;
    return make_default_scene(w, h);
  }
  const bool binary = s == Scene::RandomBinaryAlpha;
  w = binary ? 37 : 50;
  h = binary ? 23 : 31;
  img::Image im(w, h);
  std::mt19937 rng(binary ? 2026u : 1122u);
  std::uniform_int_distribution<int> byte(0, 255), coin(0, 1);
  for (size_t i = 0; i < im.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) im.rgba[i + c] = float(byte(rng)) / 255.0f;
    im.rgba[i + 3] = binary ? float(coin(rng)) : float(byte(rng)) / 255.0f;
  }
  return im;
}

// Every channel a random multiple of 1/255, drawn pixel by pixel in rgba order.
inline img::Image random_bytes(uint32_t w, uint32_t h, uint32_t seed) {
  img::Image im(w, h);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  for (float& v : im.rgba) v = float(byte(rng)) / 255.0f;
  return im;
}

} // namespace tierlift::effects::test_scenes
