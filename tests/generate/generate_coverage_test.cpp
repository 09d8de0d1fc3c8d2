// Over a few hundred listings the generator uses every source modifier, instruction
// modifier, register file and write mask the ISA gives each profile. The expected sets are
// the ISA's (docs/d3d9-rules.md §3–§4), written out here, not read from the generator.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "tierlift/generate/generate.h"

namespace tierlift::gen {
namespace {

struct Expected {
  const char* profile;
  std::set<std::string> source_modifiers, instruction_modifiers, register_files;
  std::size_t write_masks, min_swizzles;
  // The 2.x and 3.0 features: opcodes and declarations each profile's listings must use.
  std::set<std::string> opcodes = {}, declarations = {};
};

// Flow and predicates of the 2.x and 3.0 profiles (docs/d3d9-rules.md §14).
const std::set<std::string> kFlow2x = {
    "if",       "if_gt",  "if_lt",   "if_eq",   "if_ne",   "if_ge", "if_le", "break", "break_gt",
    "break_le", "breakp", "setp_gt", "setp_eq", "setp_le", "rep",   "call",  "callnz"};

const std::set<std::string> kPs1xMods = {"negate (-)", "_bias", "-_bias", "_bx2", "-_bx2", "1-"};
const std::set<std::string> kPs14Mods = {"negate (-)", "_bias", "-_bias", "_bx2", "-_bx2",
                                         "1-",         "_x2",   "-_x2",   "_dz",  "_dw"};
const std::set<std::string> kVsFiles = {"r",    "v",  "c",  "a",    "c[a0]",
                                        "oPos", "oD", "oT", "oFog", "oPts"};

// clang-format off
const Expected kExpected[] = {
    {"vs_1_1", {"negate (-)"}, {}, kVsFiles, 15, 200},
    {"vs_2_0", {"negate (-)", "!"}, {}, {"r", "v", "c", "a", "c[a0]", "c[aL]", "aL", "b", "i", "l", "oPos", "oD", "oT", "oFog", "oPts"}, 15, 200},
    {"ps_1_1", kPs1xMods, {"_sat", "_x2", "_x4", "_d2", "+"}, {"r", "v", "c", "t"}, 3, 2},
    {"ps_1_2", kPs1xMods, {"_sat", "_x2", "_x4", "_d2", "+"}, {"r", "v", "c", "t"}, 3, 2},
    {"ps_1_3", kPs1xMods, {"_sat", "_x2", "_x4", "_d2", "+"}, {"r", "v", "c", "t"}, 3, 2},
    {"ps_1_4", kPs14Mods, {"_sat", "_x2", "_x4", "_x8", "_d2", "_d4", "_d8", "+"}, {"r", "v", "c", "t"}, 15, 5},
    // ps_2_0: identity, the four replicates, .yzxw, .zxyw, .wzyx.
    {"ps_2_0", {"negate (-)"}, {"_sat", "_pp"}, {"r", "v", "c", "t", "s", "oC", "oDepth"}, 15, 8},
    {"vs_2_x", {"negate (-)", "!"}, {"(p0)"}, {"r", "v", "c", "a", "c[a0]", "c[aL]", "aL", "b", "i", "l", "p", "oPos", "oD", "oT", "oFog", "oPts"}, 15, 200,
     kFlow2x, {"dcl_position v", "dcl_texcoord v"}},
    {"ps_2_x", {"negate (-)", "!"}, {"_sat", "_pp", "(p0)"}, {"r", "v", "c", "t", "s", "b", "i", "l", "p", "oC", "oDepth"}, 15, 100,
     {"dsx", "dsy", "texldd", "texldp", "texldb", "texkill", "setp_ne", "if_gt", "break_ge", "breakp"}, {"dcl t", "dcl v", "dcl_2d s", "dcl_cube s", "dcl_volume s"}},
    {"vs_3_0", {"negate (-)", "!"}, {"_sat", "(p0)"}, {"r", "v", "c", "a", "c[a0]", "c[aL]", "v[aL]", "o", "o[aL]", "aL", "b", "i", "l", "p", "s"}, 15, 200,
     {"texldl", "loop", "setp_lt", "if_ge", "break_ne", "breakp", "sincos"},
     {"dcl_position v", "dcl_color v", "dcl_texcoord v", "dcl_position o", "dcl_color o", "dcl_texcoord o", "dcl_2d s"}},
    {"ps_3_0", {"negate (-)", "!"}, {"_sat", "_pp", "(p0)"}, {"r", "v", "c", "c[aL]", "v[aL]", "vPos", "vFace", "aL", "s", "p", "oC", "oDepth"}, 15, 100,
     {"dsx", "dsy", "texld", "texldl", "texldd", "texldp", "texldb", "loop", "setp_gt", "if_eq", "break_lt", "breakp"},
     {"dcl_texcoord v", "dcl_color v", "dcl vPos", "dcl vFace", "dcl_2d s", "dcl_cube s", "dcl_volume s"}},
};
// clang-format on

class GeneratedCoverage : public ::testing::TestWithParam<Expected> {};

std::string missing(const std::set<std::string>& want,
                    const std::map<std::string, std::size_t>& got) {
  std::string out;
  for (const std::string& w : want)
    if (!got.count(w)) out += " " + w;
  return out;
}

TEST_P(GeneratedCoverage, EveryModifierFileAndMaskAppears) {
  const Expected& e = GetParam();
  Coverage c;
  for (std::size_t i = 0; i < 400; ++i) c.add(generate_listing(e.profile, 7, i).value());
  EXPECT_EQ(c.invalid, 0u);
  EXPECT_EQ(missing(e.source_modifiers, c.source_modifiers), "");
  EXPECT_EQ(missing(e.instruction_modifiers, c.instruction_modifiers), "");
  EXPECT_EQ(missing(e.register_files, c.register_files), "");
  EXPECT_EQ(c.write_masks.size(), e.write_masks);
  EXPECT_GE(c.swizzles.size(), e.min_swizzles);
  EXPECT_EQ(missing(e.opcodes, c.opcodes), "");
  EXPECT_EQ(missing(e.declarations, c.declarations), "");
  std::printf("[generate] %s coverage:\n%s", e.profile, c.summary().c_str());
}

// How a case prints in test listings (GetParam): the profile and the sizes of its sets.
void PrintTo(const Expected& e, std::ostream* os) {
  *os << e.profile << ": " << e.source_modifiers.size() << " source modifiers, "
      << e.instruction_modifiers.size() << " instruction modifiers, " << e.register_files.size()
      << " register files, " << e.write_masks << " write masks";
}

INSTANTIATE_TEST_SUITE_P(Profiles, GeneratedCoverage, ::testing::ValuesIn(kExpected),
                         [](const auto& info) { return std::string(info.param.profile); });

} // namespace
} // namespace tierlift::gen
