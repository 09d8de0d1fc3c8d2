// The ps_1_x range presets: the values NUMERICS.md gives each name, and the parser behind
// --ps1x-max and the scenes' "ps1x_max".
#include <gtest/gtest.h>

#include <cfloat>

#include "tierlift/ir/conventions.h"
#include "tierlift/ir/ps1x_range.h"

using namespace tierlift::ir;

// The parsed value; a failure is a test failure (and reads -1).
static float value_of(std::string_view text) {
  const Result<float> r = parse_ps1x_max(text);
  EXPECT_TRUE(r) << text << ": " << r.message();
  return r ? *r : -1.0f;
}

TEST(Ps1xRange, PresetsHaveTheDocumentedValues) {
  EXPECT_EQ(value_of("geforce3"), 1.0f);
  EXPECT_EQ(value_of("radeon8500"), 8.0f);
  EXPECT_EQ(value_of("d3d9"), FLT_MAX);
  EXPECT_EQ(value_of("max"), FLT_MAX);
  EXPECT_EQ(value_of("GeForce3"), 1.0f); // names are case-insensitive
  EXPECT_EQ(kDefaultPs1xPreset, "d3d9");
  EXPECT_EQ(default_ps1x_max(), FLT_MAX);
}

TEST(Ps1xRange, NumbersFromOneUp) {
  EXPECT_EQ(value_of("1"), 1.0f);
  EXPECT_EQ(value_of("8"), 8.0f);
  EXPECT_EQ(value_of("2.5"), 2.5f);
  EXPECT_EQ(value_of("1e30"), 1e30f);
}

TEST(Ps1xRange, RejectsWhatNoPartReports) {
  for (const char* bad : {"", "0.5", "0", "-8", "nan", "inf", "1e40", "eight", "8x", "geforce"}) {
    const Result<float> m = parse_ps1x_max(bad);
    EXPECT_FALSE(m) << bad;
    EXPECT_NE(m.message().find("radeon8500"), std::string::npos) << bad << ": " << m.message();
  }
}

TEST(Ps1xRange, LabelsNameThePreset) {
  EXPECT_EQ(ps1x_max_label(FLT_MAX), "d3d9");
  EXPECT_EQ(ps1x_max_label(1.0f), "geforce3");
  EXPECT_EQ(ps1x_max_label(8.0f), "radeon8500");
  EXPECT_EQ(ps1x_max_label(4.0f), "4");
}

// The help texts and messages print the choices from the table, in its order.
TEST(Ps1xRange, ChoicesComeFromTheTable) {
  EXPECT_EQ(ps1x_choices(), "d3d9 (FLT_MAX, the default), geforce3 (1), radeon8500 (8), "
                            "max (FLT_MAX), or a number >= 1");
  EXPECT_NE(parse_ps1x_max("0.5").message().find(ps1x_choices()), std::string::npos);
}

// One default: the conventions a device starts from are the d3d9 preset's, as in `tierlift
// run`, `tierlift glow` and scenes (it was 1, geforce3's, for a bare Conventions).
TEST(Ps1xRange, ConventionsStartFromTheDefaultPreset) {
  EXPECT_EQ(Conventions{}.ps1x_max_value, FLT_MAX);
  EXPECT_EQ(ps1x_max_label(Conventions{}.ps1x_max_value), kDefaultPs1xPreset);
}
