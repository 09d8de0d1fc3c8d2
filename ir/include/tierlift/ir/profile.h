// Shader profiles (vs_1_1 … ps_3_0), their version tokens and their register/slot limits.
// Limits are the facts of docs/d3d9-rules.md §2–§3; everything that checks a limit reads them here.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>

namespace tierlift::ir {

enum class ShaderStage : uint8_t { Vertex, Pixel };

// The order is the column order of the opcode table's slot costs. Shader models 2.x and
// 3.0 come after the seven profiles the interpreter and the code generator execute.
enum class Profile : uint8_t {
  vs_1_1,
  vs_2_0,
  ps_1_1,
  ps_1_2,
  ps_1_3,
  ps_1_4,
  ps_2_0,
  vs_2_x,
  ps_2_x,
  vs_3_0,
  ps_3_0
};
inline constexpr int kProfileCount = 11;
inline constexpr Profile kAllProfiles[kProfileCount] = {
    Profile::vs_1_1, Profile::vs_2_0, Profile::ps_1_1, Profile::ps_1_2,
    Profile::ps_1_3, Profile::ps_1_4, Profile::ps_2_0, Profile::vs_2_x,
    Profile::ps_2_x, Profile::vs_3_0, Profile::ps_3_0};
// The profiles the interpreter and the SPIR-V code generator run (shader models 1 and 2.0).
inline constexpr int kExecutableProfileCount = 7;
inline constexpr Profile kExecutableProfiles[kExecutableProfileCount] = {
    Profile::vs_1_1, Profile::vs_2_0, Profile::ps_1_1, Profile::ps_1_2,
    Profile::ps_1_3, Profile::ps_1_4, Profile::ps_2_0};

constexpr int profile_index(Profile p) {
  return static_cast<int>(p);
}
constexpr ShaderStage stage_of(Profile p) {
  return (p == Profile::vs_1_1 || p == Profile::vs_2_0 || p == Profile::vs_2_x ||
          p == Profile::vs_3_0)
             ? ShaderStage::Vertex
             : ShaderStage::Pixel;
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
// vs_3_0 and ps_3_0.
constexpr bool is_sm3(Profile p) {
  return p == Profile::vs_3_0 || p == Profile::ps_3_0;
}
// vs_2_x and ps_2_x: shader model 2.0 plus the optional features of the 2.0 caps.
constexpr bool is_sm2x(Profile p) {
  return p == Profile::vs_2_x || p == Profile::ps_2_x;
}
constexpr uint8_t major_of(Profile p) {
  if (is_sm3(p)) return 3;
  return (p == Profile::vs_2_0 || p == Profile::ps_2_0 || is_sm2x(p)) ? 2 : 1;
}
// Minor version as the version token holds it (vs_2_x / ps_2_x: 1).
constexpr uint8_t minor_of(Profile p) {
  switch (p) {
  case Profile::vs_1_1: return 1;
  case Profile::ps_1_1: return 1;
  case Profile::ps_1_2: return 2;
  case Profile::ps_1_3: return 3;
  case Profile::ps_1_4: return 4;
  case Profile::vs_2_x: return 1;
  case Profile::ps_2_x: return 1;
  default: return 0;
  }
}
// Shader model 2.0 or later (vs_2_0, ps_2_0, the 2.x and 3.0 profiles).
constexpr bool is_sm2_or_later(Profile p) {
  return major_of(p) >= 2;
}
// The profiles with flow control, predicates p0 and the comparison forms of if and break.
constexpr bool has_predication(Profile p) {
  return is_sm2x(p) || is_sm3(p);
}

// "ps_1_3"
std::string_view profile_name(Profile p);
// Accepts both spellings: "ps_1_3" and "ps.1.3" (lower case, as the D3DX lexer does), and
// "ps_2_x" in upper or lower case ("ps_2_X").
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
  uint16_t labels;       // l# (vs_2_0: 16; SM 2.x and 3.0: 2048)
  // Read ports: distinct registers of one file one instruction may read.
  uint8_t temp_ports, const_ports, input_ports, texture_ports;
};
const ProfileLimits& limits(Profile p);

// The 2.x and 3.0 features a device reports in its D3DVS20CAPS / D3DPS20CAPS (and the
// shader model 3 minimums): the knobs a ps_2_x / vs_2_x listing is validated against. fxc's
// targets ps_2_a, ps_2_b and vs_2_a are presets of these (docs/d3d9-rules.md §14).
struct Caps2x {
  uint8_t temps;           // r# (NumTemps: 12..32)
  uint16_t slots;          // instruction slots (96..512 pixel, 256 vertex; 512 in SM3)
  uint8_t static_depth;    // nesting of call/callnz/if b#/rep/loop (StaticFlowControlDepth)
  uint8_t dynamic_depth;   // nesting of if_comp/if pred/break_comp (DynamicFlowControlDepth)
  bool predication;        // p0, setp, (p0) instructions
  bool gradients;          // dsx, dsy, texldd (pixel)
  bool arbitrary_swizzle;  // any source swizzle (pixel)
  bool no_dependent_limit; // no limit on dependent texture reads (pixel)
  bool no_texture_limit;   // no separate texture-instruction limit (pixel)
};
// The default for a profile: for vs_2_x / ps_2_x the most every 2.x device may report
// (Windows validates against the device, so a listing one device takes is legal); for the
// other profiles their fixed features.
Caps2x default_caps(Profile p);
// The fxc targets that share the 2.x version tokens: "ps_2_a", "ps_2_b", "vs_2_a".
std::optional<std::pair<Profile, Caps2x>> caps_preset(std::string_view name);

} // namespace tierlift::ir
