// Every generated listing parses and passes the project's validator, for thousands of seeds
// per profile; listings are deterministic in (profile, seed, index); over a few hundred
// listings every opcode legal in the profile appears.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "sanitizer_scale.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/validator.h"
#include "tierlift/generate/generate.h"
#include "tierlift/ir/opcodes.h"

namespace tierlift::gen {
namespace {

const char* const kProfiles[] = {"vs_1_1", "vs_2_0", "ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4",
                                 "ps_2_0", "vs_2_x", "ps_2_x", "vs_3_0", "ps_3_0"};

// The program of a listing that parses and validates with no error and no warning, or why not.
std::optional<ir::Program> valid_program(const std::string& text, std::string& why) {
  assembly::ParseResult r = assembly::parse_text(text, "generated.asm");
  if (r.program && assembly::validate(*r.program, r.diags) && r.diags.warning_count() == 0)
    return r.program;
  why = ir::render_text(r.diags, r.sources) + text;
  return std::nullopt;
}

class GeneratedListings : public ::testing::TestWithParam<const char*> {};

TEST_P(GeneratedListings, ThousandsOfSeedsValidate) {
  constexpr std::size_t kSeeds = test::scaled_count(2000, 150);
  std::size_t valid = 0;
  for (std::size_t i = 0; i < kSeeds; ++i) {
    const std::string text = generate_listing(GetParam(), 1, i).value();
    std::string why;
    if (valid_program(text, why))
      ++valid;
    else
      ADD_FAILURE() << "index " << i << ":\n" << why;
    if (valid + 5 < i) break; // enough said
  }
  EXPECT_EQ(valid, kSeeds);
  std::printf("[generate] %s: %zu of %zu listings validate\n", GetParam(), valid, kSeeds);
}

TEST_P(GeneratedListings, EveryLegalOpcodeAppears) {
  const ir::Profile p = *ir::parse_profile(GetParam());
  std::map<ir::Opcode, std::size_t> seen;
  std::set<std::string> modifiers;
  constexpr std::size_t kListings = 400;
  for (std::size_t i = 0; i < kListings; ++i) {
    std::string why;
    auto prog = valid_program(generate_listing(GetParam(), 7, i).value(), why);
    ASSERT_TRUE(prog) << why;
    for (const ir::Instruction& ins : prog->code) ++seen[ins.op];
  }
  std::size_t legal = 0, covered = 0;
  for (const ir::OpInfo& row : ir::opcode_table()) {
    if (!ir::legal_in(row, p) || row.cls == ir::OpClass::Decl) continue;
    ++legal;
    if (seen.count(row.op))
      ++covered;
    else
      ADD_FAILURE() << GetParam() << ": " << row.mnemonic << " never generated";
  }
  std::printf("[generate] %s: %zu of %zu legal opcodes in %zu listings\n", GetParam(), covered,
              legal, kListings);
}

// The token stream carries every generated statement: assemble, disassemble, same IR (the
// round-trip stage of `tierlift test`; nop_sat, which the validator lets through and the
// stream cannot hold, is why the generator puts no modifier on nop).
TEST_P(GeneratedListings, TokenStreamRoundTrips) {
  for (std::size_t i = 0; i < test::scaled_count(300, 60); ++i) {
    const std::string text = generate_listing(GetParam(), 2, i).value();
    std::string why;
    auto prog = valid_program(text, why);
    ASSERT_TRUE(prog) << why;
    ir::DiagnosticSink diags;
    auto tokens = assembly::assemble(*prog, diags);
    ASSERT_TRUE(tokens) << text;
    auto back = assembly::disassemble(*tokens, diags);
    ASSERT_TRUE(back) << text;
    ASSERT_TRUE(ir::same_ir(*prog, *back)) << ir::ir_difference(*prog, *back) << "\n" << text;
  }
}

TEST_P(GeneratedListings, DeterministicInSeedAndIndex) {
  EXPECT_EQ(generate_listing(GetParam(), 3, 11).value(),
            generate_listing(GetParam(), 3, 11).value());
  EXPECT_NE(generate_listing(GetParam(), 3, 11).value(),
            generate_listing(GetParam(), 3, 12).value());
  EXPECT_NE(generate_listing(GetParam(), 3, 11).value(),
            generate_listing(GetParam(), 4, 11).value());
}

INSTANTIATE_TEST_SUITE_P(Profiles, GeneratedListings, ::testing::ValuesIn(kProfiles),
                         [](const auto& info) { return std::string(info.param); });

TEST(GenerateListing, UnknownProfileFails) {
  const ir::Result<std::string> text = generate_listing("ps_9_9", 1, 0);
  ASSERT_FALSE(text);
  EXPECT_EQ(text.message(), "unknown profile 'ps_9_9'");
  EXPECT_EQ(text.diagnostics().front().rule, "usage");
}

// The 2.x and 3.0 profiles have at least 12 temporaries (the 2.x caps' minimum, 32 in 3.0):
// their listings use r8..r11 too, which the older profiles' listings (8 at most) never do.
TEST(GenerateListing, LaterProfilesUseTwelveTemps) {
  for (const char* p : {"vs_2_x", "ps_2_x", "vs_3_0", "ps_3_0"}) {
    std::set<uint32_t> temps;
    for (std::size_t i = 0; i < 200; ++i) {
      std::string why;
      auto prog = valid_program(generate_listing(p, 5, i).value(), why);
      ASSERT_TRUE(prog) << why;
      for (const ir::Instruction& ins : prog->code)
        if (ins.dst && ins.dst->file == ir::RegFile::Temp) temps.insert(ins.dst->index);
    }
    EXPECT_EQ(temps.size(), 12u) << p;
    EXPECT_EQ(*temps.rbegin(), 11u) << p;
  }
}

// Every profile the front end knows is written (the 2.x and 3.0 ones were refused until the
// builder had their shapes), and the names the CLI prints are those eleven.
TEST(GenerateListing, EveryFrontEndProfileIsWritten) {
  for (const char* p : kProfiles) EXPECT_TRUE(generate_listing(p, 1, 0)) << p;
  EXPECT_EQ(generated_profile_names(), "vs_1_1, vs_2_0, ps_1_1, ps_1_2, ps_1_3, ps_1_4, ps_2_0, "
                                       "vs_2_x, ps_2_x, vs_3_0, ps_3_0");
}

} // namespace
} // namespace tierlift::gen
