// Built-in textures for tests and the CLI: "builtin:NAME[:WxH][:SEED]".
//   impulse  one white texel (1,1,1,1) at texel (W/2, H/2) (integer division) on black
//            (0,0,0,1)
//   checker  8×8-texel squares, white where (x/8 + y/8) is even, else black; alpha 1
//   ramp     horizontal ramp sampled at texel centres: texel x holds (x + 0.5)/W in R, G
//            and B (so a bilinear read at u inside [0.5/W, 1 − 0.5/W] returns u); alpha 1
//   noise    R, G, B uniform in [0, 1) from splitmix64 (24-bit values, exact in float and
//            identical on every platform), alpha 1; SEED defaults to 1
// Default size 64×64. All are RGBA32F.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "tierlift/image/image.h"
#include "tierlift/image/io.h"

namespace tierlift::img {

inline constexpr std::string_view kBuiltinPrefix = "builtin:";
inline constexpr uint32_t kBuiltinDefaultSize = 64;

bool is_builtin_spec(std::string_view spec); // starts with "builtin:"
// Parses the spec and makes the texture; an unknown name, a malformed or out-of-range size
// (0, > kMaxDimension) or a bad seed gives an error.
ImageResult make_builtin(std::string_view spec);

Image builtin_impulse(uint32_t width, uint32_t height);
Image builtin_checker(uint32_t width, uint32_t height);
Image builtin_ramp(uint32_t width, uint32_t height);
Image builtin_noise(uint32_t width, uint32_t height, uint64_t seed = 1);

// The generator behind builtin_noise: splitmix64, and a float in [0, 1) from its top 24 bits.
uint64_t splitmix64(uint64_t& state);
float unit_float24(uint64_t bits);

// read_image(), or make_builtin() for "builtin:" specs.
ImageResult load_texture(const std::string& spec_or_path);

} // namespace tierlift::img
