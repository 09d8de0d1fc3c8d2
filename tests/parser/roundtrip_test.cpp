// print → parse gives the same IR for every listing we have, and the printed text is a
// fixed point (printing the re-parsed program gives the same text again).
#include <filesystem>
#include <fstream>
#include <sstream>

#include "skip_policy.h"
#include "test_util.h"
#include "tierlift/assembly/printer.h"

#include "listing_files.h"

namespace tierlift::assembly::test {
namespace {

namespace fs = std::filesystem;

using tierlift::test::read_file;
std::vector<fs::path> listings_in(const fs::path& dir) {
  return tierlift::test::listings_in(dir, /*recursive=*/true);
}

void expect_round_trip(const fs::path& file) {
  SCOPED_TRACE(file.string());
  ParseResult first = parse_text(read_file(file), file.string());
  ASSERT_TRUE(first.program) << ir::render_text(first.diags, first.sources);
  std::string printed = print_program(*first.program);
  ParseResult second = parse_text(printed, "<printed>");
  ASSERT_TRUE(second.program) << ir::render_text(second.diags, second.sources) << printed;
  EXPECT_TRUE(ir::same_ir(*first.program, *second.program))
      << ir::ir_difference(*first.program, *second.program) << "\n"
      << printed;
  EXPECT_EQ(print_program(*second.program), printed);
}

TEST(ParserRoundTrip, ArticleListings) {
  auto files = listings_in(fs::path(TIERLIFT_SOURCE_DIR) / "listings");
  ASSERT_GE(files.size(), 4u);
  for (const auto& f : files) expect_round_trip(f);
}

TEST(ParserRoundTrip, SharedCorpus) {
  fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::is_directory(dir))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus,
                                  "no shared corpus at " + dir.string());
  auto files = listings_in(dir);
  ASSERT_EQ(files.size(), 16u);
  for (const auto& f : files) expect_round_trip(f);
}

TEST(ParserRoundTrip, ArticleListing2HasNoBreakSpacesAndParses) {
  fs::path f = fs::path(TIERLIFT_SOURCE_DIR) / "listings/gpugems21/listing2_blur8_weighted_sum.psh";
  ir::Program p = must_parse(read_file(f));
  EXPECT_EQ(p.profile, ir::Profile::ps_2_0);
  EXPECT_EQ(p.decls.size(), 9u); // t0..t7 and s0
  EXPECT_EQ(p.code.size(), 17u);
}

TEST(ParserRoundTrip, HandWrittenCoverage) {
  const char* text =
      "vs_2_0\n"
      "dcl_position v0\ndcl_texcoord2 v1\n"
      "def c0, 1, -0, 1e-07, 3.4028235e+38\ndef c1, 0x7fc00001, 0xffc00000, -inf, inf\n"
      "defi i0, 3, -4, 2147483647, -2147483648\ndefb b0, true\ndefb b1, false\n"
      "mova a0.xy, v1\nmov r0, c[a0.x + 4]\nmov r1, c[a0.y]\nmov r2, -c[a0.w + 12].yx\n"
      "loop aL, i0\nadd r0, r0, c[aL + 3]\nendloop\n"
      "callnz l1, !b0\nret\nlabel l1\nsincos r3.xy, r0.w, c1, c2\nsgn r4, r0, r5, r6\nret\n";
  ir::Program p = must_parse(text);
  std::string printed = print_program(p);
  ir::Program q = must_parse(printed);
  EXPECT_TRUE(ir::same_ir(p, q)) << ir::ir_difference(p, q) << printed;
  EXPECT_EQ(p.defs[1].raw[0], 0x7fc00001u); // NaN payload survives
}

TEST(ParserRoundTrip, PrinterCanonicalText) {
  ir::Program p = must_parse("ps.1.4\ntexld r0, t0_dw.xyw\ntexcrd r1.rgb, t1\nphase\n"
                             "MUL_SAT_X2 r0.rgb, 1-r0, -r1_bx2.rgba\n+mov_d2 r0.a, r0_bias.a\n"
                             "cnd r1, r0.b, -r1_x2, r0\n");
  EXPECT_EQ(print_program(p), "ps_1_4\n"
                              "texld r0, t0_dw.xyw\n"
                              "texcrd r1.xyz, t1\n"
                              "phase\n"
                              "mul_x2_sat r0.xyz, 1-r0, -r1_bx2\n"
                              "+mov_d2 r0.w, r0_bias.w\n"
                              "cnd r1, r0.z, -r1_x2, r0\n");
  ir::Program v = must_parse("vs_1_1\ndcl_texcoord0 v3\ndcl_normal2 v1\nmov oT0.xy, c4[a0.x]\n");
  EXPECT_EQ(print_program(v), "vs_1_1\ndcl_texcoord v3\ndcl_normal2 v1\nmov oT0.xy, c[a0.x + 4]\n");
  ir::Program s = must_parse("ps_2_0\ndcl_pp_centroid t0\ndcl_2d s0\ntexld_pp r0, t0, s0\n");
  EXPECT_EQ(print_program(s), "ps_2_0\ndcl_pp_centroid t0\ndcl_2d s0\ntexld_pp r0, t0, s0\n");
}

} // namespace
} // namespace tierlift::assembly::test
