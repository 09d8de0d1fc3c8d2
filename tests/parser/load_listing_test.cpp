// assembly::load_listing: one entry for every form of listing file, told apart by content.
// Token streams here are written out by hand (docs/d3d9-rules.md §9): ps_1_1 = 0xFFFF0101,
// mov = 0x01, r0 = 0x800F0000, v0 = 0x90E40000, c0 = 0xA0E40000, end = 0x0000FFFF.
#include <gtest/gtest.h>

#include "loaded_listing.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/load.h"

namespace {

using namespace tierlift;
using Tokens = std::vector<uint32_t>;

using Loaded = test::LoadedListing;

Loaded load(std::string bytes, std::string name = "shader.pso", assembly::LoadOptions o = {}) {
  return test::load_bytes(std::move(bytes), std::move(name), o);
}

const Tokens kPs11Mov = {0xFFFF0101, 0x00000001, 0x800F0000, 0x90E40000, 0x0000FFFF};

} // namespace

TEST(LoadListing, RawTokenStreamWhateverTheName) {
  for (const char* name : {"a.pso", "a.bin", "a.fxo", "a.psh", "noext"}) {
    Loaded l = load(assembly::tokens_to_bytes(kPs11Mov), name);
    ASSERT_TRUE(l.r().program.ok()) << name << "\n" << l.rendered;
    EXPECT_EQ(l.r().form, assembly::ListingForm::TokenStream);
    EXPECT_EQ(l.r().program->profile, ir::Profile::ps_1_1);
    EXPECT_EQ(l.r().program->code.size(), 1u);
  }
}

// fxc /Fh writes a BYTE array of decimal values: 1, 1, 255, 255 is 0xFFFF0101.
TEST(LoadListing, FxcHeaderByteArray) {
  std::string h = "#if 0\n//    ps_1_1\n//    mov r0, v0\n#endif\n\nconst BYTE g_ps11_main[] =\n{\n"
                  "      1,   1, 255, 255,   1,   0,   0,   0,   0,   0,  15, 128,\n"
                  "      0,   0, 228, 144, 255, 255,   0,   0\n};\n";
  Loaded l = load(h, "shader.h");
  ASSERT_TRUE(l.r().program.ok()) << l.rendered;
  EXPECT_EQ(l.r().form, assembly::ListingForm::TokenArray);
  EXPECT_EQ(l.r().tokens, kPs11Mov);
}

TEST(LoadListing, DwordArrayAndText) {
  Loaded a = load("const DWORD s[] = { 0xffff0101, 0x00000001, 0x800f0000, 0x90e40000, "
                  "0x0000ffff };\n",
                  "s.h");
  ASSERT_TRUE(a.r().program.ok()) << a.rendered;
  EXPECT_EQ(a.r().form, assembly::ListingForm::TokenArray);
  Loaded t = load("ps.1.1\nmov r0, v0\n", "s.psh");
  ASSERT_TRUE(t.r().program.ok()) << t.rendered;
  EXPECT_EQ(t.r().form, assembly::ListingForm::Text);
}

// Diagnostics on a token stream name the byte offset of the token: an unknown opcode
// 0x00AB as the 2nd instruction token (index 4, byte 0x10).
TEST(LoadListing, DiagnosticsNameTheTokenOffset) {
  Tokens t = kPs11Mov;
  t.insert(t.end() - 1, 0x000000AB);
  Loaded l = load(assembly::tokens_to_bytes(t));
  EXPECT_FALSE(l.r().program.ok());
  EXPECT_EQ(l.rendered.rfind("shader.pso:+0x10: error: ", 0), 0u) << l.rendered;
  // One line: no source line and no caret under it.
  EXPECT_EQ(l.rendered.find('\n'), l.rendered.size() - 1) << l.rendered;
}

// A validator error on a stream: ps_1_1 has r0 and r1 only; "mov r2, v0" at token 1
// (byte 4) names its destination token (byte 8).
TEST(LoadListing, ValidatorErrorsNameTheTokenOffset) {
  Tokens t = {0xFFFF0101, 0x00000001, 0x800F0002, 0x90E40000,
              0x00000001, 0x800F0000, 0x90E40000, 0x0000FFFF};
  Loaded l = load(assembly::tokens_to_bytes(t));
  EXPECT_FALSE(l.r().program.ok());
  EXPECT_NE(l.rendered.find("shader.pso:+0x8: error: "), std::string::npos) << l.rendered;
  EXPECT_NE(l.rendered.find("[register-range]"), std::string::npos) << l.rendered;
}

// A binary file that is no token stream: one line that says what it is and which command
// takes it, never a caret line of unprintable bytes.
TEST(LoadListing, BinaryFilesGetOneLine) {
  struct Case {
    std::string bytes, expect;
  } cases[] = {
      {std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), "PNG image"},
      {std::string("DXBC\x01\x02\x03\x04\0\0\0\0", 12), "DXBC container"},
      {assembly::tokens_to_bytes({0xFEFF0901, 0, 0, 0}), "effect"},
      {std::string(400, '\x01') + std::string("\0\0\0\0", 4), "binary file"},
  };
  for (const Case& c : cases) {
    Loaded l = load(c.bytes, "thing.bin");
    EXPECT_FALSE(l.r().program.ok());
    EXPECT_EQ(l.r().form, assembly::ListingForm::Binary);
    EXPECT_EQ(l.rendered.rfind("thing.bin: error: this is ", 0), 0u) << l.rendered;
    EXPECT_NE(l.rendered.find(c.expect), std::string::npos) << l.rendered;
    EXPECT_EQ(l.rendered.find('\n'), l.rendered.size() - 1) << l.rendered;
    EXPECT_EQ(l.rendered.find('?'), std::string::npos) << l.rendered;
  }
}

// A text listing and its token stream load to the same IR (what the devices run).
TEST(LoadListing, TextAndTokensGiveTheSameProgram) {
  const char* text = "vs_2_0\ndcl_position v0\nloop aL, i0\nadd r0, r0, c0[aL + 1]\nendloop\n"
                     "def c10, 1, 2, 3, 4\nmov r1, c0[a0.y]\nmov oPos, v0\n";
  assembly::LoadOptions skip;
  skip.skip_validation = true;
  Loaded t = load(text, "x.vsh", skip);
  ASSERT_TRUE(t.r().program.ok()) << t.rendered;
  Loaded b = load(assembly::tokens_to_bytes(assembly::assemble(*t.r().program)), "x.vso", skip);
  ASSERT_TRUE(b.r().program.ok()) << b.rendered;
  EXPECT_TRUE(ir::same_ir(*t.r().program, *b.r().program))
      << ir::ir_difference(*t.r().program, *b.r().program);
}
