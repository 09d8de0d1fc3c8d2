// The delta reducer with a synthetic failure: "the listing is valid and has a mad with a
// negated source". What is left is that one instruction, its operands simplified to the
// constant c0, plus what validity needs (the version line and the profile's output write).
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/generate/generate.h"

namespace tierlift::gen {
namespace {

bool valid(const std::string& text) {
  assembly::ParseResult r = assembly::parse_text(text, "reduce.asm");
  return r.program && assembly::validate(*r.program, r.diags);
}

bool has_negated_mad(const std::string& text) {
  static const std::regex mad(R"((^|\n)\+?mad\S* [^\n]*,\s*-)");
  return std::regex_search(text, mad);
}

bool fails(const std::string& text) {
  return has_negated_mad(text) && valid(text);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The first generated listing of `profile` (seed 5) the synthetic predicate holds for.
std::string failing_listing(const char* profile) {
  for (std::size_t i = 0; i < 500; ++i)
    if (std::string t = generate_listing(profile, 5, i).value(); fails(t)) return t;
  return {};
}

// The reduced listing, line by line, as regular expressions.
struct Case {
  const char* profile;
  std::vector<std::string> lines;
};
// One mad, every source c0, the one the predicate needs negated; no modifier, no mask.
const std::string kMad = R"(mad r\d+, (-c0, c0, c0|c0, -c0, c0|c0, c0, -c0))";

class ReduceNegatedMad : public ::testing::TestWithParam<Case> {};

TEST_P(ReduceNegatedMad, LeavesTheMadAndWhatValidityNeeds) {
  const Case& c = GetParam();
  const std::string start = failing_listing(c.profile);
  ASSERT_FALSE(start.empty()) << "no generated " << c.profile << " listing has a negated mad";
  std::size_t calls = 0;
  const std::string reduced = reduce_listing(start, [&](const std::string& t) {
    ++calls;
    return fails(t);
  });
  EXPECT_TRUE(fails(reduced)) << reduced;
  const std::vector<std::string> lines = lines_of(reduced);
  ASSERT_EQ(lines.size(), c.lines.size()) << "from:\n" << start << "to:\n" << reduced;
  for (std::size_t k = 0; k < lines.size(); ++k)
    EXPECT_TRUE(std::regex_match(lines[k], std::regex(c.lines[k])))
        << lines[k] << " !~ " << c.lines[k];
  std::printf("[reduce] %s: %zu lines -> %zu lines, %zu predicate calls\n", c.profile,
              lines_of(start).size(), lines.size(), calls);
}

const Case kCases[] = {
    {"ps_2_0", {"ps_2_0", kMad, "mov oC0, c0"}},
    {"vs_1_1", {"vs_1_1", kMad, "mov oPos, c0"}},
    {"vs_2_0", {"vs_2_0", kMad, "mov oPos, c0"}},
    {"ps_1_1", {"ps_1_1", kMad}},
    // ps_1_4 takes no modifier on a constant: the negated source stays a temp, written first
    // (by whichever instruction wrote it; the reducer changes operands, not opcodes).
    {"ps_1_4",
     {"ps_1_4", R"([a-z0-9]+ r\d, c0(, c0)*)", R"(mad r\d, (c0|-r\d), (c0|-r\d), (c0|-r\d))"}},
};
// How a case prints in test listings (GetParam): the profile and how many lines must remain.
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.profile << ", reduced to " << c.lines.size() << " lines";
}

INSTANTIATE_TEST_SUITE_P(Profiles, ReduceNegatedMad, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.profile); });

TEST(Reduce, IsDeterministic) {
  const std::string start = failing_listing("ps_2_0");
  EXPECT_EQ(reduce_listing(start, fails), reduce_listing(start, fails));
}

TEST(Reduce, AListingThatDoesNotFailComesBackUnchanged) {
  const std::string text = "ps_2_0\nmov oC0, c0\n";
  EXPECT_EQ(reduce_listing(text, fails), text);
}

TEST(Reduce, ModifiersMasksAndSwizzlesGo) {
  // Only the negation of the mad matters: _sat, _pp, the mask, the swizzles and the other
  // sources' registers all go.
  const std::string text = "ps_2_0\ndef c0, 1, 2, 3, 4\ndcl t0\nmov r1, t0\n"
                           "mad_sat_pp r0.xy, r1.wzyx, -r1.x, t0\nmov r0.zw, c0\nmov oC0, r0\n";
  ASSERT_TRUE(fails(text));
  EXPECT_EQ(reduce_listing(text, fails), "ps_2_0\nmad r0, c0, -c0, c0\nmov oC0, c0\n");
}

} // namespace
} // namespace tierlift::gen
