// read_token_file: raw little-endian bytes and the C-array text form.
#include <gtest/gtest.h>

#include "tierlift/assembly/bytecode.h"

using tierlift::assembly::read_token_file;
using tierlift::assembly::tokens_to_bytes;
using tierlift::ir::DiagnosticSink;

namespace {

const std::vector<uint32_t> kDclT0 = {0xFFFF0200, 0x0200001F, 0x80000000, 0xB00F0000, 0x0000FFFF};

std::optional<std::vector<uint32_t>> read(const std::string& text, DiagnosticSink& diags) {
  return read_token_file(text, diags, 0);
}

} // namespace

TEST(TokenFile, BytesAreLittleEndian) {
  std::string b = tokens_to_bytes({0x0200001F, 0xFFFF0200});
  ASSERT_EQ(b.size(), 8u);
  // 0x0200001F → 1F 00 00 02; 0xFFFF0200 → 00 02 FF FF
  EXPECT_EQ(b, std::string("\x1F\x00\x00\x02\x00\x02\xFF\xFF", 8));
}

TEST(TokenFile, RawBytesRoundTrip) {
  DiagnosticSink diags;
  auto t = read(tokens_to_bytes(kDclT0), diags);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, kDclT0);
  // A raw file with a bad version token is still raw (it holds NUL bytes): the
  // disassembler, not the file reader, gets to complain.
  auto bad = read(tokens_to_bytes({0x00000001, 0x0000FFFF}), diags);
  ASSERT_TRUE(bad.has_value());
  EXPECT_EQ(bad->size(), 2u);
  EXPECT_FALSE(diags.has_errors());
}

TEST(TokenFile, CArrayWithCommentsSuffixesAndDecimal) {
  const std::string text = "// ps_2_0 { not the array }\n"
                           "/* dcl t0 */\n"
                           "#define X { 1 }\n"
                           "const DWORD g_ps[] = {\n"
                           "    0xffff0200, 0x0200001fu, /* usage */ 0x80000000UL, // dst t0\n"
                           "    0xB00F0000Lu,\n"
                           "    65535, };\n"
                           "const DWORD g_other[] = { 7 };\n";
  DiagnosticSink diags;
  auto t = read(text, diags);
  ASSERT_TRUE(t.has_value()) << diags.all()[0].message;
  EXPECT_EQ(*t, kDclT0); // 65535 = 0xFFFF, the end token
}

TEST(TokenFile, BareListAndByteArray) {
  DiagnosticSink diags;
  auto t = read("0xffff0200, 0x0200001f,\n0x80000000, 0xb00f0000, 0x0000ffff\n", diags);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, kDclT0);
  // fxc's newer /Fh form: a BYTE array, four bytes per DWORD, little-endian.
  auto b = read("const BYTE g_ps20[] =\n{\n  0, 2, 255, 255, 31, 0, 0, 2,\n  0, 0, 0, 128, "
                "0, 0, 15, 176, 255, 255, 0, 0\n};\n",
                diags);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(*b, kDclT0);
  // Octal, as in C: 017 = 15.
  auto o = read("{ 017 }", diags);
  ASSERT_TRUE(o.has_value());
  EXPECT_EQ(*o, std::vector<uint32_t>{15});
  EXPECT_FALSE(diags.has_errors());
}

TEST(TokenFile, ErrorsHaveLineAndColumn) {
  DiagnosticSink diags;
  EXPECT_FALSE(read("const DWORD a[] = {\n  0xffff0200,\n  foo, 0x0000ffff };\n", diags));
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.all()[0].loc.line, 3u);
  EXPECT_EQ(diags.all()[0].loc.col, 3u);
  EXPECT_EQ(diags.all()[0].rule, "token-file");
  EXPECT_NE(diags.all()[0].message.find("'f'"), std::string::npos);

  diags.clear();
  EXPECT_FALSE(read("{ 0x100000000 }", diags)); // 33 bits
  EXPECT_NE(diags.all()[0].message.find("32 bits"), std::string::npos);
  EXPECT_EQ(diags.all()[0].loc.col, 3u);

  diags.clear();
  EXPECT_FALSE(read("{ 0xffff0200, 0x0000ffff", diags));
  EXPECT_NE(diags.all()[0].message.find("missing '}'"), std::string::npos);

  diags.clear();
  EXPECT_FALSE(read("{ 0xffff0200 0x0000ffff }", diags));
  EXPECT_NE(diags.all()[0].message.find("expected ','"), std::string::npos);

  diags.clear();
  EXPECT_FALSE(read("{ 12abc }", diags));
  EXPECT_NE(diags.all()[0].message.find("malformed number"), std::string::npos);

  diags.clear();
  EXPECT_FALSE(read("{ 0x }", diags));
  EXPECT_FALSE(read("{ 1.5 }", diags));
  EXPECT_FALSE(read("{ -1 }", diags));
  EXPECT_FALSE(read("{ }", diags));
  EXPECT_FALSE(read("", diags));
  EXPECT_FALSE(read("const BYTE b[] = { 1, 2, 3 };", diags));      // not whole DWORDs
  EXPECT_FALSE(read("const BYTE b[] = { 1, 2, 3, 256 };", diags)); // not a byte
  EXPECT_EQ(diags.error_count(), 7u);
}

TEST(TokenFile, BinaryOfOddSizeIsAnError) {
  DiagnosticSink diags;
  EXPECT_FALSE(read(std::string("\x00\x02\xFF\xFF\x01", 5), diags));
  ASSERT_EQ(diags.error_count(), 1u);
  EXPECT_NE(diags.all()[0].message.find("multiple of 4"), std::string::npos);
}
