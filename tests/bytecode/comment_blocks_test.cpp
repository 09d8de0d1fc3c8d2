// Comment tokens of a token stream (fxc's CTAB constant table, debug information, any block a
// tool wrote) survive disassembly: they print as "//!comment 0x…" lines, parse back, and
// assemble to the same words at the same place, so disassemble then assemble gives back every
// byte of every stream (docs/d3d9-rules.md §11.4). Streams here are written by hand from the
// D3D9 token layout: comment token 0xFFFE with the payload length in bits 16-30.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "listing_files.h"
#include "loaded_listing.h"
#include "skip_policy.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

using Tokens = std::vector<uint32_t>;

// ps_2_0: a 3-word "DBUG" block after the version, mov oC0, c0, an empty block, end.
const Tokens kStream = {0xFFFF0200, 0x0003FFFE, 0x47554244, 0x0000001C, 0x00000000,
                        0x02000001, 0x800F0800, 0xA0E40000, 0x0000FFFE, 0x0000FFFF};
const char* const kText = "ps_2_0\n"
                          "//!comment 0x47554244 0x0000001c 0x00000000\n"
                          "mov oC0, c0\n"
                          "//!comment\n";

std::string hex(const Tokens& t) {
  std::string s;
  for (uint32_t v : t) s += fmt::format("{:08x} ", v);
  return s;
}

// Bytes → program → text → program → bytes.
Tokens through_text(const Tokens& tokens, std::string& text) {
  ir::DiagnosticSink diags;
  auto p = assembly::disassemble(tokens, diags);
  EXPECT_TRUE(p.has_value());
  if (!p) return {};
  text = assembly::print_program(*p);
  auto reparsed = assembly::parse_text(text, "disasm.asm");
  EXPECT_TRUE(reparsed.program.has_value()) << ir::render_text(reparsed.diags, reparsed.sources);
  if (!reparsed.program) return {};
  auto back = assembly::assemble(*reparsed.program, diags);
  EXPECT_TRUE(back.has_value());
  return back.value_or(Tokens{});
}

struct FirstError {
  std::string rule, message;
  uint32_t line = 0, col = 0;
};
FirstError first_error(const std::string& text) {
  auto r = assembly::parse_text(text, "t.asm");
  EXPECT_FALSE(r.program.has_value()) << text;
  for (const ir::Diagnostic& d : r.diags.all())
    if (d.severity == ir::Severity::Error) return {d.rule, d.message, d.loc.line, d.loc.col};
  return {};
}

// Every token stream of a folder: fxc's headers (.inc) and C sources (.c) in tests/corpus,
// and whatever token files a corpus folder holds.
std::vector<fs::path> bytecode_files(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".inc" || ext == ".c" || ext == ".pso" || ext == ".vso" || ext == ".tok" ||
        ext == ".vsh" || ext == ".psh")
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The identity on every file of `dir` that holds a token stream; returns how many did.
size_t identity_on_streams(const fs::path& dir) {
  size_t streams = 0;
  for (const fs::path& file : bytecode_files(dir)) {
    assembly::LoadOptions options;
    options.parse.include_dirs.push_back(file.parent_path().string());
    test::LoadedListing l = test::load_bytes(test::read_file(file), file.string(), options);
    if (l.r().tokens.empty()) continue; // a text listing
    SCOPED_TRACE(file.string());
    ++streams;
    EXPECT_TRUE(l.r().program.ok()) << l.rendered;
    if (!l.r().program.ok()) continue;
    EXPECT_EQ(hex(assembly::assemble(*l.r().program)), hex(l.r().tokens));
    std::string text;
    EXPECT_EQ(hex(through_text(l.r().tokens, text)), hex(l.r().tokens)) << text;
  }
  return streams;
}

} // namespace

TEST(CommentBlocks, DisassemblyKeepsThemInPlace) {
  ir::DiagnosticSink diags;
  auto p = assembly::disassemble(kStream, diags);
  ASSERT_TRUE(p.has_value());
  ASSERT_EQ(p->comments.size(), 2u);
  EXPECT_EQ(p->comments[0].words, (Tokens{0x47554244, 0x0000001C, 0x00000000}));
  EXPECT_TRUE(p->comments[1].words.empty());
  EXPECT_EQ(assembly::print_program(*p), kText);
  EXPECT_EQ(hex(assembly::assemble(*p)), hex(kStream));
  std::string text;
  EXPECT_EQ(hex(through_text(kStream, text)), hex(kStream));
}

TEST(CommentBlocks, TextAssemblesToTheStream) {
  auto r = assembly::parse_text(kText, "t.asm");
  ASSERT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources);
  EXPECT_EQ(hex(assembly::assemble(*r.program)), hex(kStream));
  EXPECT_EQ(r.program->comments[0].loc.line, 2u);
  EXPECT_EQ(r.program->comments[0].loc.col, 1u);
}

// Eight words a line; "//!comment+" lines add to the block above; case of hex digits is free.
TEST(CommentBlocks, LongBlocksSpanLines) {
  Tokens stream = {0xFFFE0200, 0x0009FFFE};
  for (uint32_t w = 1; w <= 9; ++w) stream.push_back(w);
  stream.push_back(0x0000FFFF);
  ir::DiagnosticSink diags;
  auto p = assembly::disassemble(stream, diags);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(assembly::print_program(*p),
            "vs_2_0\n//!comment 0x00000001 0x00000002 0x00000003 0x00000004 0x00000005 "
            "0x00000006 0x00000007 0x00000008\n//!comment+ 0x00000009\n");
  auto r =
      assembly::parse_text("vs_2_0\n//!comment 0x1 0x2 0X3 0x4\n//!comment+ 0x5 0x6 0x7 0x8 0x9\n");
  ASSERT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources);
  EXPECT_EQ(hex(assembly::assemble(*r.program)), hex(stream));
  // Two "//!comment" lines are two blocks.
  auto two = assembly::parse_text("vs_2_0\n//!comment 0x1\n//!comment 0x2\n");
  ASSERT_TRUE(two.program.has_value());
  EXPECT_EQ(hex(assembly::assemble(*two.program)),
            hex({0xFFFE0200, 0x0001FFFE, 1, 0x0001FFFE, 2, 0x0000FFFF}));
}

TEST(CommentBlocks, ErrorsHavePositions) {
  FirstError e = first_error("ps_2_0\nmov oC0, c0\n//!comment+ 0x1\n");
  EXPECT_EQ(e.rule, "comment-block");
  EXPECT_EQ(e.line, 3u);
  EXPECT_EQ(e.col, 1u);
  e = first_error("ps_2_0\n//!comment 0x1 zz\nmov oC0, c0\n");
  EXPECT_EQ(e.rule, "comment-block");
  EXPECT_EQ(e.line, 2u);
  EXPECT_EQ(e.col, 16u);
  EXPECT_NE(e.message.find("found 'zz'"), std::string::npos) << e.message;
  e = first_error("ps_2_0\n//!comment 0x123456789\n"); // nine digits do not fit 32 bits
  EXPECT_EQ(e.rule, "comment-block");
  EXPECT_EQ(e.col, 12u);
  e = first_error("ps_2_0\n//!comment 12\n"); // decimal is not taken: words are hexadecimal
  EXPECT_EQ(e.rule, "comment-block");
}

TEST(CommentBlocks, OtherCommentsStayComments) {
  // "//!commentary" and "// !comment" are ordinary comments; a block in #if 0 is skipped.
  auto r =
      assembly::parse_text("ps_2_0\n//!commentary 0xzz\n// !comment zz\n#if 0\n//!comment 0x1\n"
                           "#endif\nmov oC0, c0\n");
  ASSERT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources);
  EXPECT_TRUE(r.program->comments.empty());
}

// The comment token holds the payload's length in 15 bits.
TEST(CommentBlocks, TooLongForTheTokenIsRefused) {
  ir::Program p;
  p.profile = ir::Profile::ps_2_0;
  ir::CommentBlock big;
  big.words.assign(0x8000, 0);
  big.loc = {0, 2, 1, 10};
  p.comments.push_back(big);
  ir::DiagnosticSink diags;
  EXPECT_FALSE(assembly::assemble(p, diags).has_value());
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.all()[0].rule, "bytecode");
  EXPECT_EQ(diags.all()[0].loc.line, 2u);
  big.words.resize(0x7FFF);
  p.comments = {big};
  ir::DiagnosticSink ok;
  auto tokens = assembly::assemble(p, ok);
  ASSERT_TRUE(tokens.has_value());
  EXPECT_EQ((*tokens)[1], 0x7FFFFFFEu);
}

// fmt keeps a listing's own comments and prints each block once, where it stood.
TEST(CommentBlocks, FormatterPrintsEachBlockOnce) {
  const std::string source = "ps_2_0\n// a note\n//!comment 0x1\nmov oC0, c0 // tail\n";
  auto r = assembly::parse_text(source, "t.asm");
  ASSERT_TRUE(r.program.has_value());
  EXPECT_EQ(assembly::print_program_with_comments(*r.program, source, 0),
            "ps_2_0\n// a note\n//!comment 0x00000001\nmov oC0, c0  // tail\n");
}

// The identity on every token stream of tests/corpus: fxc's 19 headers (each with its CTAB)
// and SDL's C source.
TEST(CommentBlocks, IdentityOnEveryCorpusStream) {
  EXPECT_EQ(identity_on_streams(fs::path(TIERLIFT_SOURCE_DIR) / "tests" / "corpus"), 20u);
}

TEST(CommentBlocks, IdentityOnSharedCorpusStreams) {
  const fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::is_directory(dir))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus, "no shared corpus");
  identity_on_streams(dir); // text listings there are skipped; any stream must round-trip
}
