// Shader profiles (vs_1_1 … ps_2_0), their version tokens and their register/slot limits.
// Limits are the facts of docs/d3d9-rules.md §2–§3; everything that checks a limit reads them here.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace tierlift::ir {

enum class ShaderStage : uint8_t { Vertex, Pixel };

enum class Profile : uint8_t { vs_1_1, vs_2_0, ps_1_1, ps_1_2, ps_1_3, ps_1_4, ps_2_0 };
inline constexpr int kProfileCount = 7;
inline constexpr Profile kAllProfiles[kProfileCount] = {
    Profile::vs_1_1, Profile::vs_2_0, Profile::ps_1_1, Profile::ps_1_2,
    Profile::ps_1_3, Profile::ps_1_4, Profile::ps_2_0};

constexpr int profile_index(Profile p) {
  return static_cast<int>(p);
}
constexpr ShaderStage stage_of(Profile p) {
  return (p == Profile::vs_1_1 || p == Profile::vs_2_0) ? ShaderStage::Vertex : ShaderStage::Pixel;
}
constexpr bool is_vertex(Profile p) {
  return stage_of(p) == ShaderStage::Vertex;
}
constexpr bool is_pixel(Profile p) {
  return stage_of(p) == ShaderStage::Pixel;
}
// ps_1_1 … ps_1_4: the fixed-point-era pixel profiles with range clamps and modifiers.
constexpr bool is_ps1x(Profile p) {
  return p == Profile::ps_1_1 || p == Profile::ps_1_2 || p == Profile::ps_1_3 ||
         p == Profile::ps_1_4;
}
// ps_1_1 … ps_1_3 (texture-address instructions, r0 as output, no phases).
constexpr bool is_ps11_13(Profile p) {
  return p == Profile::ps_1_1 || p == Profile::ps_1_2 || p == Profile::ps_1_3;
}
constexpr uint8_t major_of(Profile p) {
  return (p == Profile::vs_2_0 || p == Profile::ps_2_0) ? 2 : 1;
}
constexpr uint8_t minor_of(Profile p) {
  switch (p) {
  case Profile::vs_1_1: return 1;
  case Profile::ps_1_1: return 1;
  case Profile::ps_1_2: return 2;
  case Profile::ps_1_3: return 3;
  case Profile::ps_1_4: return 4;
  default: return 0;
  }
}

// "ps_1_3"
std::string_view profile_name(Profile p);
// Accepts both spellings: "ps_1_3" and "ps.1.3" (lower case, as the D3DX lexer does).
std::optional<Profile> parse_profile(std::string_view text);
// Version token: VS 0xFFFE0000 | major<<8 | minor, PS 0xFFFF0000 | major<<8 | minor.
uint32_t version_token(Profile p);
std::optional<Profile> profile_from_version_token(uint32_t token);

struct ProfileLimits {
  // Instruction slots. For vertex profiles only max_slots applies. ps_1_x: texture and
  // arithmetic slots are counted separately (ps_1_4: per phase). ps_2_0: both, plus total.
  uint16_t max_slots;
  uint8_t max_tex_slots;
  uint8_t max_arith_slots;
  uint8_t temps;         // r#
  uint16_t float_consts; // c#
  uint8_t int_consts;    // i#
  uint8_t bool_consts;   // b#
  uint8_t inputs;        // v#
  uint8_t texcoords;     // t# (pixel) — texture registers / interpolated coordinates
  uint8_t samplers;      // s# (ps_2_0) or texture stages (ps_1_x)
  uint8_t tex_outputs;   // oT# (vertex)
  uint8_t color_outputs; // oD# (vertex) or oC# (ps_2_0)
  uint8_t labels;        // l# (vs_2_0)
  // Read ports: distinct registers of one file one instruction may read.
  uint8_t temp_ports, const_ports, input_ports, texture_ports;
};
const ProfileLimits& limits(Profile p);

} // namespace tierlift::ir
