// The ps_1_x register range (D3DCAPS9.PixelShader1xMaxValue, "MaxPixelShaderValue"): named
// presets for the parts that ran ps_1_x content, the default every convention starts from,
// and the parser behind --ps1x-max and the scenes' "ps1x_max". NUMERICS.md ("ps_1_x
// register range presets") says what each models and where the value comes from.
#pragma once

#include <array>
#include <cfloat>
#include <string>
#include <string_view>

#include "tierlift/ir/result.h"

namespace tierlift::ir {

struct Ps1xPreset {
  std::string_view name;
  float max_value;
  std::string_view models; // one line for the docs
};

// The presets, the one list: help texts and messages print from it. Order matters for
// ps1x_max_label: the first preset with a value names it.
inline constexpr std::array<Ps1xPreset, 4> kPs1xPresets{{
    {"d3d9", FLT_MAX,
     "a D3D9-class driver: float pipelines, the range reported as FLT_MAX (the default)"},
    {"geforce3", 1.0f, "the first ps_1_1 parts (GeForce3/4 Ti): registers clamp to [-1, 1]"},
    {"radeon8500", 8.0f, "ps_1_4 parts (Radeon 8500): [-8, 8], the least ps_1_4 allows"},
    {"max", FLT_MAX, "the largest finite float: no clamp short of overflow"},
}};
inline constexpr std::string_view kDefaultPs1xPreset = "d3d9";

// The default preset's value (FLT_MAX: what D3D9 runtimes and drivers report), the one
// default: Conventions::ps1x_max_value starts from it.
constexpr float default_ps1x_max() {
  for (const Ps1xPreset& p : kPs1xPresets)
    if (p.name == kDefaultPs1xPreset) return p.max_value;
  return 0.0f; // unreachable: the table names its default
}

// The choices as one line for --help and messages, from the table: "d3d9 (FLT_MAX, the
// default), geforce3 (1), radeon8500 (8), max (FLT_MAX), or a number >= 1".
std::string ps1x_choices();

// A preset name (case-insensitive) or a number >= 1 ("8", "1e30"); otherwise a failure whose
// message names the presets (negative, below 1, NaN or infinite values included).
Result<float> parse_ps1x_max(std::string_view text);

// How a value is shown in --json and in the glow table's header: the preset's name when a
// preset has this value ("d3d9" wins over "max" for FLT_MAX), else the number ("4").
std::string ps1x_max_label(float value);

} // namespace tierlift::ir
