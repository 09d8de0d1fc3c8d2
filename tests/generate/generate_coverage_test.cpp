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
};

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
