// The values of `tierlift run`'s flags, parsed into the settings pass::prepare_pass takes
// (tierlift/pass/setup.h). Each parser gives the value, or a failure with one "usage" error
// naming the flag and the value. The word lookups (filter, address, pixel centre) give
// nullopt for a word they do not know: their callers name the choices in their own message.
// A library of its own so tests can reach it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/ir/result.h"
#include "tierlift/pass/setup.h"

namespace tierlift::assembly {
struct ConstantTable;
} // namespace tierlift::assembly

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

// --const [vs:|ps:]NAME=VALUE, parsed once into typed settings: NAME a register (cN=x,y,z,w,
// iN=a,b,c,d, bN=true|false) or a constant named by the constant table (CTAB) of the vertex
// or pixel listing (either may be null; "vs:"/"ps:" picks the table, neither prefix tries
// both): a matrix or array takes 4 numbers per register in register order and gives a
// setting per register. Fails (rule "usage") when the name is in neither table or the value
// does not fit.
ir::Result<std::vector<ConstSetting>> parse_const_assignment(std::string_view text,
                                                             const assembly::ConstantTable* vs,
                                                             const assembly::ConstantTable* ps);
// Every --const of a run, in order.
ir::Result<std::vector<ConstSetting>> parse_const_assignments(const std::vector<std::string>& texts,
                                                              const assembly::ConstantTable* vs,
                                                              const assembly::ConstantTable* ps);
// One register setting (no constant tables).
ir::Result<ConstSetting> parse_const_setting(std::string_view text);
// --input v#|t#=x,y,z,w (pixel stage)
ir::Result<RegisterSetting> parse_input_setting(std::string_view text);
// --attr vN=x,y,z,w|quad-uv (vertex stage)
ir::Result<RegisterSetting> parse_attr_setting(std::string_view text);
// --texture sN=FILE.png|FILE.pfm|builtin:NAME[:WxH]
ir::Result<TextureSetting> parse_texture_setting(std::string_view text);
// --bump-matrix STAGE=m00,m01,m10,m11 (texbem/texbeml, texture stage 0..7)
ir::Result<pass::BumpSetting> parse_bump_setting(std::string_view text);
// --probe X,Y
ir::Result<ProbePoint> parse_probe(std::string_view text);
// "WxH", 1..img::kMaxDimension each.
ir::Result<std::array<uint32_t, 2>> parse_size(std::string_view text);
std::optional<Filter> parse_filter(std::string_view text);       // point|linear
std::optional<AddressMode> parse_address(std::string_view text); // clamp|wrap|mirror|border
std::optional<ir::PixelCenter> parse_pixel_center(std::string_view text); // d3d9|modern
std::optional<pass::MipFilter> parse_mip_filter(std::string_view text);   // none|point|linear
std::optional<uint32_t> parse_level_count(std::string_view text);         // 1..32

} // namespace tierlift::cli
