// The ps_1_x register range (D3DCAPS9.PixelShader1xMaxValue, "MaxPixelShaderValue"): named
// presets for the parts that ran ps_1_x content, and the parser behind --ps1x-max and the
// scenes' "ps1x_max". NUMERICS.md ("ps_1_x register range presets") says what each models
// and where the value comes from.
#pragma once

#include "tierlift/ir/result.h"
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tierlift::ir {

struct Ps1xPreset {
  std::string_view name;
  float max_value;
  std::string_view models; // one line for --help and the docs
};

// geforce3 (1), radeon8500 (8), d3d9 (FLT_MAX, the default), max (FLT_MAX).
std::span<const Ps1xPreset> ps1x_presets();
inline constexpr std::string_view kDefaultPs1xPreset = "d3d9";
// The default's value (FLT_MAX): what a D3D9-class driver reports.
float default_ps1x_max();

// A preset name (case-insensitive) or a number >= 1 ("8", "1e30"); otherwise a failure whose
// message names the presets (negative, below 1, NaN or infinite values included).
Result<float> parse_ps1x_max(std::string_view text);

// How a value is shown in --json and in the glow table's header: the preset's name when a
// preset has this value ("d3d9" wins over "max" for FLT_MAX), else the number ("4").
std::string ps1x_max_label(float value);

} // namespace tierlift::ir
