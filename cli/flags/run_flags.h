// The values of `tierlift run`'s flags, parsed into the settings pass::prepare_pass takes
// (tierlift/pass/setup.h). Each parser gives the value, or nullopt and a one-line reason in
// `error`. A library of its own so tests can reach it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "tierlift/pass/setup.h"

namespace tierlift::cli {

using pass::AddressMode;
using pass::ConstSetting;
using pass::Filter;
using pass::kMaxSamplers;
using pass::ProbePoint;
using pass::RegisterSetting;
using pass::StageMask;
using pass::TextureSetting;
using pass::Vec4;

// --const [vs:|ps:]cN=x,y,z,w | iN=a,b,c,d | bN=true|false
std::optional<ConstSetting> parse_const_setting(std::string_view text, std::string& error);
// --input v#|t#=x,y,z,w (pixel stage)
std::optional<RegisterSetting> parse_input_setting(std::string_view text, std::string& error);
// --attr vN=x,y,z,w|quad-uv (vertex stage)
std::optional<RegisterSetting> parse_attr_setting(std::string_view text, std::string& error);
// --texture sN=FILE.png|FILE.pfm|builtin:NAME[:WxH]
std::optional<TextureSetting> parse_texture_setting(std::string_view text, std::string& error);
// --probe X,Y
std::optional<ProbePoint> parse_probe(std::string_view text, std::string& error);
// "WxH", 1..img::kMaxDimension each.
std::optional<std::array<uint32_t, 2>> parse_size(std::string_view text, std::string& error);
std::optional<Filter> parse_filter(std::string_view text);       // point|linear
std::optional<AddressMode> parse_address(std::string_view text); // clamp|wrap|mirror|border
std::optional<ir::PixelCenter> parse_pixel_center(std::string_view text); // d3d9|modern

} // namespace tierlift::cli
