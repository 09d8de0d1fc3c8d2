// A generated 10 MB listing parses completely (linear-time lexer and parser; no timing
// assertion here, the benchmark measures speed).
#include "test_util.h"

namespace tierlift::assembly::test {
namespace {

TEST(ParserLargeInput, TenMegabyteListing) {
  std::string text = "vs_2_0\ndcl_position v0\n";
  const std::string lines[] = {"mad r1, r0.x, c[a0.x + 12], r2 ; comment\n",
                               "add r0.xy, -v0, c4_abs.wzyx\n", "/* block */ mov r3, r1\n"};
  size_t count = 0;
  while (text.size() < 10u * 1024 * 1024) text += lines[count++ % 3];
  ParseResult r = parse_text(std::move(text));
  ASSERT_TRUE(r.program) << ir::render_text(r.diags, r.sources).substr(0, 2000);
  EXPECT_EQ(r.program->code.size(), count);
  EXPECT_EQ(r.program->code.back().loc.line, count + 2);
}

TEST(ParserLargeInput, OneHugeLineOfGarbageGivesFewErrors) {
  std::string text = "vs_1_1\n" + std::string(1u << 20, '@') + "\n";
  for (int i = 0; i < 10000; ++i) text += "frob\n";
  ParseResult r = parse_text(std::move(text));
  ASSERT_FALSE(r.program);
  EXPECT_LE(r.diags.error_count(), 101u);
}

} // namespace
} // namespace tierlift::assembly::test
