// Register files, swizzles and write masks: the vocabulary of operands.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "tierlift/ir/profile.h"

namespace tierlift::ir {

// One value per register file as the assembler spells it. Bytecode type 3 is a0 in a
// vertex shader and t# in a pixel shader; the IR keeps them apart (Addr vs Texture).
enum class RegFile : uint8_t {
  Temp,      // r#
  Input,     // v#
  Const,     // c#
  Addr,      // a0 (vertex)
  Texture,   // t# (pixel)
  RastOut,   // oPos (0), oFog (1), oPts (2)
  AttrOut,   // oD#
  TexCrdOut, // oT#
  ConstInt,  // i#
  ColorOut,  // oC#
  DepthOut,  // oDepth
  Sampler,   // s#
  ConstBool, // b#
  Loop,      // aL
  Label,     // l#
  Output,    // o# (vs_3_0: outputs declared with a semantic; bytecode type 6, as oT#)
  Predicate, // p0 (2.x, 3.0)
  Misc,      // vPos (0), vFace (1) (ps_3_0)
};

inline constexpr uint32_t kRastPos = 0, kRastFog = 1, kRastPts = 2;
inline constexpr uint32_t kMiscPosition = 0, kMiscFace = 1;

// Bytecode register type (docs/d3d9-rules.md §11.2).
uint8_t bytecode_regtype(RegFile f);
// Type 3 is a0 or t# by stage; type 6 is oT# before vs_3_0 and o# in it.
std::optional<RegFile> regfile_from_bytecode(uint8_t type, Profile profile);

// "r3", "c[a0.x + 4]" is printed elsewhere; this gives the plain name of file+index.
std::string register_name(RegFile f, uint32_t index);

// Swizzle: 2 bits per destination component, component i in bits 2i..2i+1 (as in bytecode
// bits 16–23). Identity .xyzw is 0xE4.
inline constexpr uint8_t kIdentitySwizzle = 0xE4;
constexpr uint8_t swizzle_component(uint8_t swz, int i) {
  return (swz >> (2 * i)) & 3;
}
constexpr uint8_t make_swizzle(int x, int y, int z, int w) {
  return static_cast<uint8_t>(x | (y << 2) | (z << 4) | (w << 6));
}
constexpr uint8_t replicate_swizzle(int c) {
  return make_swizzle(c, c, c, c);
}
constexpr bool is_replicate(uint8_t swz) {
  return swz == replicate_swizzle(swz & 3);
}
// Shortest text that expands back to swz: "" for identity, ".x" for .xxxx, ".xy" for .xyyy.
std::string swizzle_text(uint8_t swz);

// Write mask: x = 1, y = 2, z = 4, w = 8.
inline constexpr uint8_t kFullMask = 0xF;
std::string mask_text(uint8_t mask); // "" for full, ".xz" otherwise

} // namespace tierlift::ir
