// Round trips over real listings: text → IR → tokens → IR is the same IR, and tokens →
// IR → tokens gives the same tokens. The article's listings are also checked against
// token streams written out by hand.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "skip_policy.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"

#include "listing_files.h"

namespace fs = std::filesystem;
using tierlift::ir::DiagnosticSink;
using Tokens = std::vector<uint32_t>;

namespace {

using tierlift::test::listings_in;
std::string slurp(const fs::path& p) {
  return tierlift::test::read_file(p);
}

std::string first_message(const DiagnosticSink& d) {
  return d.all().empty() ? std::string("(no diagnostic)") : d.all()[0].message;
}

// Both round trips for one listing; returns the tokens.
Tokens round_trip(const fs::path& file) {
  SCOPED_TRACE(file.string());
  auto parsed = tierlift::assembly::parse_text(slurp(file), file.filename().string());
  EXPECT_TRUE(parsed.program.has_value()) << first_message(parsed.diags);
  if (!parsed.program) return {};
  const auto& p = *parsed.program;
  DiagnosticSink diags;
  auto tokens = tierlift::assembly::assemble(p, diags);
  EXPECT_TRUE(tokens.has_value()) << first_message(diags);
  if (!tokens) return {};
  auto back = tierlift::assembly::disassemble(*tokens, diags);
  EXPECT_TRUE(back.has_value()) << first_message(diags);
  if (!back) return {};
  EXPECT_TRUE(tierlift::ir::same_ir(p, *back)) << tierlift::ir::ir_difference(p, *back);
  EXPECT_EQ(tierlift::assembly::assemble(*back), *tokens);
  // What `tierlift disasm` shows must read back as the same program.
  auto reparsed = tierlift::assembly::parse_text(tierlift::assembly::print_program(*back));
  EXPECT_TRUE(reparsed.program.has_value()) << first_message(reparsed.diags);
  if (reparsed.program) {
    EXPECT_TRUE(tierlift::ir::same_ir(*back, *reparsed.program))
        << tierlift::ir::ir_difference(*back, *reparsed.program);
  }
  // And through the file form.
  auto reread =
      tierlift::assembly::read_token_file(tierlift::assembly::tokens_to_bytes(*tokens), diags);
  EXPECT_TRUE(reread.has_value());
  if (reread) {
    EXPECT_EQ(*reread, *tokens);
  }
  return *tokens;
}

// One push_back a token: GCC 12 at -O3 (the Release build) reports a false
// -Wstringop-overflow on vector::insert of a list into the one-token vector (GCC bug 107852).
void append(Tokens& t, std::initializer_list<uint32_t> more) {
  for (uint32_t token : more) t.push_back(token);
}

} // namespace

TEST(BytecodeRoundTrip, ArticleListings) {
  auto files = listings_in(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "gpugems21");
  ASSERT_EQ(files.size(), 4u);
  for (const auto& f : files) round_trip(f);
}

TEST(BytecodeRoundTrip, SharedCorpus) {
  auto files = listings_in(fs::path(TIERLIFT_SHARED_DIR) / "corpus");
  if (files.empty())
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus, "no shared corpus");
  for (const auto& f : files) round_trip(f);
}

// listings/gpugems21/<name> round-tripped: the tokens `want`, then the end token 0x0000FFFF.
void expect_article_tokens(const std::string& name, Tokens want) {
  want.push_back(0x0000FFFF);
  EXPECT_EQ(round_trip(fs::path(TIERLIFT_SOURCE_DIR) / "listings/gpugems21" / name), want) << name;
}

TEST(BytecodeRoundTrip, Listing1MatchesHandTokens) {
  // vs_2_0; dcl_position v0, dcl_normal v1, dcl_color v2, dcl_texcoord v3 → usage tokens
  // 0x80000000 | usage (position 0, normal 3, color 10, texcoord 5), dst 0x900F000n.
  Tokens want = {0xFFFE0200};
  append(want, {0x0200001F, 0x80000000, 0x900F0000, 0x0200001F, 0x80000003, 0x900F0001, 0x0200001F,
                0x8000000A, 0x900F0002, 0x0200001F, 0x80000005, 0x900F0003});
  append(want, {0x02000001, 0xC00F0000, 0x90E40000}); // mov oPos, v0
  for (uint32_t n = 0; n < 8; ++n) // add oTn, v3, cn: oT type 6, v type 1, c type 2
    append(want, {0x03000002, 0xE00F0000 | n, 0x90E40003, 0xA0E40000 | n});
  expect_article_tokens("listing1_blur8_coords.vsh", want);
}

TEST(BytecodeRoundTrip, Listing2MatchesHandTokens) {
  Tokens want = {0xFFFF0200};
  for (uint32_t n = 0; n < 8; ++n) append(want, {0x0200001F, 0x80000000, 0xB00F0000 | n});
  append(want, {0x0200001F, 0x90000000, 0xA00F0800}); // dcl_2d s0
  // texld rD, tN, s0: dst r 0x800F000D, src t 0xB0E4000N, sampler 0xA0E40800
  auto texld = [&](uint32_t d, uint32_t t) {
    append(want, {0x03000042, 0x800F0000 | d, 0xB0E40000 | t, 0xA0E40800});
  };
  // mad r0, rS, cK, r0
  auto mad = [&](uint32_t s, uint32_t k) {
    append(want, {0x04000004, 0x800F0000, 0x80E40000 | s, 0xA0E40000 | k, 0x80E40000});
  };
  texld(0, 0);
  texld(1, 1);
  append(want, {0x03000005, 0x800F0000, 0x80E40000, 0xA0E40000}); // mul r0, r0, c0
  mad(1, 1);
  for (uint32_t k = 2; k < 8; k += 2) {
    texld(1, k);
    texld(2, k + 1);
    mad(1, k);
    mad(2, k + 1);
  }
  append(want, {0x02000001, 0x800F0800, 0x80E40000}); // mov oC0, r0
  expect_article_tokens("listing2_blur8_weighted_sum.psh", want);
}

TEST(BytecodeRoundTrip, Listing3MatchesHandTokens) {
  Tokens want = {0xFFFE0101, 0x0000001F, 0x80000000, 0x900F0000, 0x0000001F,
                 0x80000005, 0x900F0003, 0x00000001, 0xC00F0000, 0x90E40000};
  for (uint32_t n = 0; n < 4; ++n) // SM1: no length field
    append(want, {0x00000002, 0xE00F0000 | n, 0x90E40003, 0xA0E40000 | n});
  expect_article_tokens("listing3_blur4_coords.vsh", want);
}

TEST(BytecodeRoundTrip, Listing4MatchesHandTokens) {
  // ps_1_3: tex tN = 0x00000042, 0xB00F000N (t type 3); then mul/mad, no length fields.
  Tokens want = {0xFFFF0103};
  for (uint32_t n = 0; n < 4; ++n) append(want, {0x00000042, 0xB00F0000 | n});
  append(want, {0x00000005, 0x800F0000, 0xB0E40000, 0xA0E40000}); // mul r0, t0, c0
  for (uint32_t n = 1; n < 4; ++n)                                // mad r0, tN, cN, r0
    append(want, {0x00000004, 0x800F0000, 0xB0E40000 | n, 0xA0E40000 | n, 0x80E40000});
  expect_article_tokens("listing4_blur4_weighted_sum.psh", want);
}

TEST(BytecodeRoundTrip, ParsedInstructionsMatchHandTokens) {
  struct Case {
    const char* text;
    Tokens want;
  };
  const Case cases[] = {
      // ps_1_1 co-issue: "+" sets bit 30; r0.a / .w mask 8.
      {"ps.1.1\ntex t0\nmul r0.rgb, t0, v0\n+mov r0.a, t0\n",
       {0xFFFF0101, 0x00000042, 0xB00F0000, 0x00000005, 0x80070000, 0xB0E40000, 0x90E40000,
        0x40000001, 0x80080000, 0xB0E40000, 0x0000FFFF}},
      // _x2 shift 1, _bx2 = 4, 1-x = 6, negate = 1 (ps_1_4: r0-r5).
      {"ps_1_4\nmad_x2 r0, r1_bx2, 1-r2, -r3\n",
       {0xFFFF0104, 0x00000004, 0x810F0000, 0x84E40001, 0x86E40002, 0x81E40003, 0x0000FFFF}},
      // vs_1_1 relative: bit 13, no extra token.
      {"vs_1_1\ndcl_position v0\nmov a0.x, v0.x\nmov oPos, c[a0.x + 3]\n",
       {0xFFFE0101, 0x0000001F, 0x80000000, 0x900F0000, 0x00000001, 0xB0010000, 0x90000000,
        0x00000001, 0xC00F0000, 0xA0E42003, 0x0000FFFF}},
      // def with exact float bits: 0.5 = 0x3F000000, -2 = 0xC0000000, 0.1 = 0x3DCCCCCD.
      {"ps_2_0\ndef c1, 0.5, -2, 0.1, 0\nmov oC0, c1\n",
       {0xFFFF0200, 0x05000051, 0xA00F0001, 0x3F000000, 0xC0000000, 0x3DCCCCCD, 0x00000000,
        0x02000001, 0x800F0800, 0xA0E40001, 0x0000FFFF}},
      // ps_1_4 phase token.
      {"ps_1_4\ntexld r0, t0\nphase\nmov r0, r0\n",
       {0xFFFF0104, 0x00000042, 0x800F0000, 0xB0E40000, 0x0000FFFD, 0x00000001, 0x800F0000,
        0x80E40000, 0x0000FFFF}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    auto parsed = tierlift::assembly::parse_text(c.text);
    ASSERT_TRUE(parsed.program.has_value()) << first_message(parsed.diags);
    EXPECT_EQ(tierlift::assembly::assemble(*parsed.program), c.want);
  }
}
