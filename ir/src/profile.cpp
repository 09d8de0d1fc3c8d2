#include "tierlift/ir/profile.h"

#include <array>
#include <string>

namespace tierlift::ir {

std::string_view profile_name(Profile p) {
  static constexpr std::array<std::string_view, kProfileCount> names = {
      "vs_1_1", "vs_2_0", "ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4",
      "ps_2_0", "vs_2_x", "ps_2_x", "vs_3_0", "ps_3_0"};
  return names[profile_index(p)];
}

std::optional<Profile> parse_profile(std::string_view text) {
  if (text.size() != 6) return std::nullopt;
  std::string canon(text);
  // The dot spelling of D3D8 ("ps.1.3") means the same as the underscore one.
  if (canon[2] == '.' && canon[4] == '.') canon[2] = canon[4] = '_';
  // Microsoft's documentation spells the 2.x profiles both ps_2_x and ps_2_X.
  if (canon[5] == 'X') canon[5] = 'x';
  for (Profile p : kAllProfiles)
    if (profile_name(p) == canon) return p;
  return std::nullopt;
}

uint32_t version_token(Profile p) {
  uint32_t base = is_vertex(p) ? 0xFFFE0000u : 0xFFFF0000u;
  return base | (uint32_t{major_of(p)} << 8) | minor_of(p);
}

std::optional<Profile> profile_from_version_token(uint32_t token) {
  for (Profile p : kAllProfiles)
    if (version_token(p) == token) return p;
  return std::nullopt;
}

const ProfileLimits& limits(Profile p) {
  // clang-format off
  //                                slots tex arith temps  c   i   b  v  t  s  oT oD/oC l   ports: r  c  v  t
  static const ProfileLimits vs11 {128,   0,  0,   12,  96,  0,  0, 16, 0, 0, 8, 2,  0,  3, 1, 1, 0};
  static const ProfileLimits vs20 {256,   0,  0,   12, 256, 16, 16, 16, 0, 0, 8, 2, 16,  3, 2, 1, 0};
  static const ProfileLimits ps11 { 12,   4,  8,    2,   8,  0,  0,  2, 4, 4, 0, 0,  0,  2, 2, 2, 2};
  static const ProfileLimits ps12 { 12,   4,  8,    2,   8,  0,  0,  2, 4, 4, 0, 0,  0,  2, 2, 2, 3};
  static const ProfileLimits ps13 { 12,   4,  8,    2,   8,  0,  0,  2, 4, 4, 0, 0,  0,  2, 2, 2, 3};
  static const ProfileLimits ps14 { 28,   6,  8,    6,   8,  0,  0,  2, 6, 6, 0, 0,  0,  3, 2, 2, 1};
  static const ProfileLimits ps20 { 96,  32, 64,   12,  32,  0,  0,  2, 8,16, 0, 4,  0,  3, 2, 1, 1};
  // 2.x: the largest counts the D3DVS20CAPS / D3DPS20CAPS allow (Caps2x narrows them);
  // 3.0: the minimums every 3.0 device has. vs_3_0's "oT" column counts o0..o11, its s#
  // are the four vertex-texture samplers.
  static const ProfileLimits vs2x {256,   0,  0,   32, 256, 16, 16, 16, 0, 0, 8, 2,2048, 3, 2, 1, 0};
  static const ProfileLimits ps2x {512,   0,  0,   32,  32, 16, 16,  2, 8,16, 0, 4,2048, 3, 2, 1, 1};
  static const ProfileLimits vs30 {512,   0,  0,   32, 256, 16, 16, 16, 0, 4,12, 0,2048, 3, 2, 1, 0};
  static const ProfileLimits ps30 {512,   0,  0,   32, 224, 16, 16, 10, 0,16, 0, 4,2048, 3, 2, 1, 0};
  // vs_2_0/ps_2_0 c#: the docs list "read ports 1, reads per instruction 2"; sincos must
  // name two different constants, so two distinct c# per instruction are allowed.
  // clang-format on
  switch (p) {
  case Profile::vs_1_1: return vs11;
  case Profile::vs_2_0: return vs20;
  case Profile::ps_1_1: return ps11;
  case Profile::ps_1_2: return ps12;
  case Profile::ps_1_3: return ps13;
  case Profile::ps_1_4: return ps14;
  case Profile::ps_2_0: return ps20;
  case Profile::vs_2_x: return vs2x;
  case Profile::ps_2_x: return ps2x;
  case Profile::vs_3_0: return vs30;
  case Profile::ps_3_0: return ps30;
  }
  return vs11;
}

Caps2x default_caps(Profile p) {
  const ProfileLimits& l = limits(p);
  Caps2x c{l.temps, l.max_slots, 0, 0, false, false, false, false, false};
  switch (p) {
  case Profile::vs_2_0: c.static_depth = 1; break; // loop/rep one deep, calls one deep
  case Profile::vs_2_x:
  case Profile::vs_3_0:
    c = Caps2x{l.temps, l.max_slots, 4, 24, true, false, false, false, false};
    break;
  case Profile::ps_2_x:
  case Profile::ps_3_0:
    c = Caps2x{l.temps, l.max_slots, 4, 24, true, true, true, true, true};
    break;
  default: break;
  }
  return c;
}

std::optional<std::pair<Profile, Caps2x>> caps_preset(std::string_view name) {
  // fxc's targets, as the D3DX reference (D3DXGetPixelShaderProfile,
  // D3DXGetVertexShaderProfile) describes them: each is ps_2_0 / vs_2_0 plus a list of
  // capabilities, and nothing off that list. ps_2_a: 22 temps, arbitrary swizzles,
  // gradients, predication, no dependent-read or texture-instruction limit; no flow control
  // (its hardware class had no branching in pixel shaders). ps_2_b: 32 temps and no
  // texture-instruction limit, nothing else. vs_2_a: 13 temps, dynamic flow control (24, the
  // one depth vs_2_x allows), predication; loop/rep and call nest one deep, as in vs_2_0.
  // Both pixel targets have 512 slots (the published pixel-shader comparison tables).
  if (name == "ps_2_a")
    return std::pair{Profile::ps_2_x, Caps2x{22, 512, 0, 0, true, true, true, true, true}};
  if (name == "ps_2_b")
    return std::pair{Profile::ps_2_x, Caps2x{32, 512, 0, 0, false, false, false, false, true}};
  if (name == "vs_2_a")
    return std::pair{Profile::vs_2_x, Caps2x{13, 256, 1, 24, true, false, false, false, false}};
  return std::nullopt;
}

} // namespace tierlift::ir
