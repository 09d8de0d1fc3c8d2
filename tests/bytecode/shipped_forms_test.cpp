// Forms that shipped D3D8/D3D9 listings use and tierlift used to refuse (issue 29, "every
// form above taken"). Each test is a listing of that form, loaded the way `tierlift check`
// loads it, and compared with tokens worked out by hand from the token layout
// (docs/d3d9-rules.md §11): instruction token = opcode (+ 0x40000000 when co-issued); a
// parameter token is 0x80000000 | type[2:0] << 28 | modifier << 24 | mask or swizzle << 16 |
// number, with r = type 0, v = 1, c = 2, t = 3. Identity swizzle 0xE4, full mask 0xF.
#include <gtest/gtest.h>

#include <filesystem>

#include "loaded_listing.h"
#include "temp_dir.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/load.h"

namespace {

using namespace tierlift;
using Tokens = std::vector<uint32_t>;
using test::load_bytes;
using test::LoadedListing;

Tokens tokens_of(const LoadedListing& l) {
  EXPECT_TRUE(l.r().program.ok()) << l.rendered;
  if (!l.r().program.ok()) return {};
  return assembly::assemble(*l.r().program);
}

// ps.1.1: tex t0; mul r0.rgb, v0, t0; co-issued mov r0.a, t0.
const Tokens kCoissuePair = {0xFFFF0101, 0x00000042, 0xB00F0000, 0x00000005, 0x80070000, 0x90E40000,
                             0xB0E40000, 0x40000001, 0x80080000, 0xB0E40000, 0x0000FFFF};
constexpr const char* kCoissueListing = "ps.1.1\ntex t0\nmul r0.rgb, v0, t0\n+mov r0.a, t0\n";

} // namespace

// "mul r0.rgb, v0, t0 +" then "mov r0.a, t0": the pairing '+' ends the first line.
TEST(ShippedForms, CoissuePlusAtTheEndOfTheFirstLine) {
  EXPECT_EQ(tokens_of(load_bytes(kCoissueListing, "a.psh")), kCoissuePair);
  for (const char* text : {
           "ps.1.1\ntex t0\nmul r0.rgb, v0, t0 +\nmov r0.a, t0\n",
           "ps.1.1\r\ntex t0\r\nmul r0.rgb, v0, t0 + ; colour, then alpha\r\nmov r0.a, t0\r\n",
           "ps.1.1\ntex t0\nmul r0.rgb, v0, t0 +\n\n// the alpha half\nmov r0.a, t0\n",
           "ps.1.1\ntex t0\nmul r0.rgb, v0, t0 +\n+ mov r0.a, t0\n", // marked twice: one pair
       }) {
    SCOPED_TRACE(text);
    LoadedListing l = load_bytes(text, "a.psh");
    EXPECT_EQ(tokens_of(l), kCoissuePair);
    EXPECT_EQ(l.diags.warning_count(), 0u) << l.rendered;
  }
  // The '+' still needs an instruction after it.
  LoadedListing dangling = load_bytes("ps.1.1\ntex t0\nmul r0.rgb, v0, t0 +\n", "a.psh");
  EXPECT_FALSE(dangling.r().program.ok());
}

// One game's dumps end every file with a NUL byte; other tools pad with several.
TEST(ShippedForms, TrailingNulBytesEndTheText) {
  for (size_t nuls : {1u, 4u, 7u}) {
    LoadedListing l = load_bytes(std::string(kCoissueListing) + std::string(nuls, '\0'), "a.psh");
    EXPECT_EQ(l.r().form, assembly::ListingForm::Text) << nuls;
    EXPECT_EQ(tokens_of(l), kCoissuePair) << nuls;
  }
  // Positions are those of the file: an error on line 3, column 5.
  LoadedListing bad =
      load_bytes(std::string("ps.1.1\ntex t0\nmul q0, v0, t0\n") + std::string(2, '\0'), "b.psh");
  EXPECT_EQ(bad.r().form, assembly::ListingForm::Text);
  EXPECT_NE(bad.rendered.find("b.psh:3:5: error:"), std::string::npos) << bad.rendered;
  // A NUL byte with text after it is still a binary file.
  LoadedListing mid = load_bytes(std::string("ps.1.1\ntex t0") + '\0' + "mov r0, t0\n", "c.psh");
  EXPECT_FALSE(mid.r().program.ok());
}

// Comments in a legacy 8-bit code page: Windows-1252 "é" (0xE9) and Windows-1251
// "Привет" (0xCF 0xF0 0xE8 0xE2 0xE5 0xF2) are not UTF-8, and the file is still text.
TEST(ShippedForms, CommentsInALegacyCodePage) {
  const std::string latin = "; \xE9"
                            "clairage diffus\n";
  const std::string cyrillic = "// \xCF\xF0\xE8\xE2\xE5\xF2\n";
  LoadedListing l = load_bytes(latin + cyrillic + kCoissueListing, "legacy.psh");
  EXPECT_EQ(l.r().form, assembly::ListingForm::Text);
  EXPECT_EQ(tokens_of(l), kCoissuePair);
  // An error after such a comment on the same line: one byte is one column, as saved, and
  // the quoted line shows the byte read as Windows-1252 ("é" = U+00E9).
  LoadedListing bad = load_bytes("ps.1.1 /* \xE9t\xE9 */ mov q0, v0\n", "bad.psh");
  EXPECT_NE(bad.rendered.find("bad.psh:1:22: error:"), std::string::npos) << bad.rendered;
  EXPECT_NE(bad.rendered.find("/* \xC3\xA9t\xC3\xA9 */"), std::string::npos) << bad.rendered;
  // Outside a comment such a byte is still refused, with its position.
  LoadedListing stray = load_bytes("ps.1.1\nmov r0, v0 \xE9\n", "stray.psh");
  EXPECT_FALSE(stray.r().program.ok());
  EXPECT_NE(stray.rendered.find("stray.psh:2:"), std::string::npos) << stray.rendered;
}

// #include "..\common\light.inl": a Windows path; found with '\' read as '/' on POSIX.
TEST(ShippedForms, BackslashIncludePaths) {
  test::TempDir dir("backslash_include");
  std::filesystem::create_directories(dir / "common");
  std::filesystem::create_directories(dir / "shaders");
  dir.file("common/light.inl", "#define LIGHT v0\n");
  dir.file("shaders/sub.inl", "#define TEXEL t0\n");
  const std::string main = "#include \"..\\common\\light.inl\"\n"
                           "#include \".\\sub.inl\"\n"
                           "ps.1.1\ntex TEXEL\nmul r0.rgb, LIGHT, TEXEL\n+mov r0.a, TEXEL\n";
  const std::string path = dir.file("shaders/main.psh", main);
  LoadedListing l = load_bytes(main, path);
  EXPECT_EQ(tokens_of(l), kCoissuePair);
  // A name that exists neither way is still reported as written.
  LoadedListing missing = load_bytes("#include \"..\\nowhere\\x.inl\"\nps.1.1\n", path);
  EXPECT_NE(missing.rendered.find("cannot find include file '..\\nowhere\\x.inl'"),
            std::string::npos)
      << missing.rendered;
}

// "#define TEX t0" then "TEX_bx2": the macro expands and the modifier stays on it.
TEST(ShippedForms, MacroFollowedByAModifier) {
  const char* text =
      "ps.1.1\n#define TEX t0\n#define LIGHT v0\n#define OP mul\n#define TEX_BASE t1\n"
      "tex TEX\ntex TEX_BASE\n"
      "OP_sat r0, TEX_bx2, -LIGHT_bias\n"
      "add r0, r0, TEX_BASE_bx2\n";
  // t0_bx2 = 0xB4E40000 (modifier 4), -v0_bias = 0x93E40000 (modifier 3), _sat = 0x00100000.
  const Tokens expected = {0xFFFF0101, 0x00000042, 0xB00F0000, 0x00000042, 0xB00F0001,
                           0x00000005, 0x801F0000, 0xB4E40000, 0x93E40000, 0x00000002,
                           0x800F0000, 0x80E40000, 0xB4E40001, 0x0000FFFF};
  EXPECT_EQ(tokens_of(load_bytes(text, "m.psh")), expected);
  // Only modifiers follow a macro that way: TEX_foo is still an unknown register.
  LoadedListing bad = load_bytes("ps.1.1\n#define TEX t0\ntex t0\nmov r0, TEX_foo\n", "m.psh");
  EXPECT_NE(bad.rendered.find("unknown register"), std::string::npos) << bad.rendered;
}

// Precompiled bytecode kept as a C array among other C++: the first array whose first
// value is a version token is the shader, and a note names it when there are several.
TEST(ShippedForms, TokenArrayInsideOtherCode) {
  const std::string source = R"(#include <d3d9.h>
namespace fx {
static const float kWeights[] = {0.25f, 0.5f, 0.25f};
static const DWORD kDecl[] = {0x00020000, 0x000F0001};
struct Blur { int taps; };
int taps(const Blur& b) { if (b.taps > 3) { return 3; } return b.taps; }
// ps.1.1 / tex t0 / mul r0.rgb, v0, t0 / +mov r0.a, t0
static const DWORD g_blur_ps[] = {
    0xffff0101, 0x00000042, 0xb00f0000, 0x00000005, 0x80070000, 0x90e40000, 0xb0e40000,
    0x40000001, 0x80080000, 0xb0e40000, 0x0000ffff};
static const DWORD g_copy_ps[] = {0xffff0101, 0x00000001, 0x800f0000, 0x90e40000, 0x0000ffff};
}
)";
  LoadedListing l = load_bytes(source, "shaders.cpp");
  EXPECT_EQ(l.r().form, assembly::ListingForm::TokenArray) << l.rendered;
  EXPECT_EQ(tokens_of(l), kCoissuePair);
  EXPECT_EQ(l.count(ir::Severity::Note, "token-file"), 1u) << l.rendered;
  EXPECT_NE(l.rendered.find("shaders.cpp:8:"), std::string::npos) << l.rendered;
  EXPECT_NE(l.rendered.find("2 arrays"), std::string::npos) << l.rendered;
  EXPECT_NE(l.rendered.find("'g_blur_ps' at line 8"), std::string::npos) << l.rendered;
  // One array: no note.
  LoadedListing one =
      load_bytes(source.substr(0, source.find("static const DWORD g_copy")) + "}\n", "one.cpp");
  EXPECT_EQ(tokens_of(one), kCoissuePair);
  EXPECT_EQ(one.count(ir::Severity::Note, "token-file"), 0u) << one.rendered;
}

namespace {

// ps.1.1: tex t0; tex t1; def c0, 0.5, 0.5, 0.5, 1 (after the tex, as written); mul r0, c0,
// t1. def = opcode 0x51, c0 = 0xA00F0000, 0.5f = 0x3F000000, 1.0f = 0x3F800000.
const Tokens kDefAfterTex = {0xFFFF0101, 0x00000042, 0xB00F0000, 0x00000042, 0xB00F0001, 0x00000051,
                             0xA00F0000, 0x3F000000, 0x3F000000, 0x3F000000, 0x3F800000, 0x00000005,
                             0x800F0000, 0xA0E40000, 0xB0E40001, 0x0000FFFF};

// "line:col rule" of every diagnostic of `severity`.
std::string where(const LoadedListing& l, ir::Severity severity) {
  std::string out;
  for (const ir::Diagnostic& d : l.diags.all())
    if (d.severity == severity)
      out += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + " " + d.rule + "\n";
  return out;
}

assembly::LoadOptions strict() {
  assembly::LoadOptions o;
  o.strict = true;
  return o;
}

} // namespace

// Valve's ps_1_1 listings (Source SDK 2013) write "def c0 0.5f 0.5f 0.5f 1.0f" after their
// tex instructions, and shipped that way: taken with a warning for each form (rule "syntax"
// at the first missing comma, rule "order" at the def); --strict refuses both, with the same
// positions (docs/d3d9-rules.md §12.8).
TEST(ShippedForms, DefWithoutCommasAfterTex) {
  const std::string text = "ps.1.1\ntex t0\ntex t1\ndef c0 0.5f 0.5f 0.5f 1.0f\nmul r0, c0, t1\n";
  LoadedListing l = load_bytes(text, "a.psh");
  EXPECT_EQ(tokens_of(l), kDefAfterTex);
  EXPECT_EQ(where(l, ir::Severity::Warning), "4:8 syntax\n4:1 order\n") << l.rendered;
  EXPECT_NE(l.rendered.find("--strict rejects it"), std::string::npos) << l.rendered;

  LoadedListing s = load_bytes(text, "a.psh", strict());
  EXPECT_FALSE(s.r().program.ok());
  EXPECT_EQ(where(s, ir::Severity::Error), "4:8 syntax\n") << s.rendered;
  EXPECT_NE(s.rendered.find("expected ','"), std::string::npos) << s.rendered;

  // With its commas, the def after tex alone: a warning by default, an error under --strict.
  const std::string commas = "ps.1.1\ntex t0\ntex t1\ndef c0, 0.5, 0.5, 0.5, 1\nmul r0, c0, t1\n";
  LoadedListing c = load_bytes(commas, "b.psh");
  EXPECT_EQ(tokens_of(c), kDefAfterTex);
  EXPECT_EQ(where(c, ir::Severity::Warning), "4:1 order\n") << c.rendered;
  LoadedListing cs = load_bytes(commas, "b.psh", strict());
  EXPECT_FALSE(cs.r().program.ok());
  EXPECT_EQ(where(cs, ir::Severity::Error), "4:1 order\n") << cs.rendered;
  EXPECT_NE(cs.rendered.find("def must come before the first instruction (tex at line 2)"),
            std::string::npos)
      << cs.rendered;
}
