// The ps_1_x range presets: the values NUMERICS.md gives each name, and the parser behind
// --ps1x-max and the scenes' "ps1x_max".
#include <gtest/gtest.h>

#include <cfloat>

#include "tierlift/ir/ps1x_range.h"

using namespace tierlift::ir;

TEST(Ps1xRange, PresetsHaveTheDocumentedValues) {
  EXPECT_EQ(parse_ps1x_max("geforce3"), 1.0f);
  EXPECT_EQ(parse_ps1x_max("radeon8500"), 8.0f);
  EXPECT_EQ(parse_ps1x_max("d3d9"), FLT_MAX);
  EXPECT_EQ(parse_ps1x_max("max"), FLT_MAX);
  EXPECT_EQ(parse_ps1x_max("GeForce3"), 1.0f); // names are case-insensitive
  EXPECT_EQ(kDefaultPs1xPreset, "d3d9");
  EXPECT_EQ(default_ps1x_max(), FLT_MAX);
}

TEST(Ps1xRange, NumbersFromOneUp) {
  EXPECT_EQ(parse_ps1x_max("1"), 1.0f);
  EXPECT_EQ(parse_ps1x_max("8"), 8.0f);
  EXPECT_EQ(parse_ps1x_max("2.5"), 2.5f);
  EXPECT_EQ(parse_ps1x_max("1e30"), 1e30f);
}

TEST(Ps1xRange, RejectsWhatNoPartReports) {
  for (const char* bad : {"", "0.5", "0", "-8", "nan", "inf", "1e40", "eight", "8x", "geforce"}) {
    std::string why;
    EXPECT_FALSE(parse_ps1x_max(bad, &why).has_value()) << bad;
    EXPECT_NE(why.find("radeon8500"), std::string::npos) << bad << ": " << why;
  }
}

TEST(Ps1xRange, LabelsNameThePreset) {
  EXPECT_EQ(ps1x_max_label(FLT_MAX), "d3d9");
  EXPECT_EQ(ps1x_max_label(1.0f), "geforce3");
  EXPECT_EQ(ps1x_max_label(8.0f), "radeon8500");
  EXPECT_EQ(ps1x_max_label(4.0f), "4");
}
