// Malformed token streams: each one is a diagnostic naming the token offset, never a crash
// or a read past the end of the vector (ASan watches the latter).
#include <gtest/gtest.h>

#include <random>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"

using tierlift::assembly::assemble;
using tierlift::assembly::disassemble;
using tierlift::ir::DiagnosticSink;

namespace {

// ps_2_0: dcl t0; dcl_2d s0; texld r0, t0, s0; mov oC0, r0 (see encode_ps_test.cpp)
const std::vector<uint32_t> kPs20 = {0xFFFF0200, 0x0200001F, 0x80000000, 0xB00F0000, 0x0200001F,
                                     0x90000000, 0xA00F0800, 0x03000042, 0x800F0000, 0xB0E40000,
                                     0xA0E40800, 0x02000001, 0x800F0800, 0x80E40000, 0x0000FFFF};
// vs_1_1: dcl_texcoord v3; add oT0, v3, c[a0.x + 2]
const std::vector<uint32_t> kVs11 = {0xFFFE0101, 0x0000001F, 0x80000005, 0x900F0003, 0x00000002,
                                     0xE00F0000, 0x90E40003, 0xA0E42002, 0x0000FFFF};

// Disassembly must fail with one error whose message starts "token <at> (".
void expect_error(const std::vector<uint32_t>& t, size_t at, const std::string& words) {
  DiagnosticSink diags;
  auto p = disassemble(t, diags);
  EXPECT_FALSE(p.has_value());
  ASSERT_EQ(diags.error_count(), 1u);
  const auto& d = diags.all()[0];
  EXPECT_EQ(d.rule, "bytecode");
  EXPECT_EQ(d.message.rfind("token " + std::to_string(at) + " (", 0), 0u) << d.message;
  EXPECT_NE(d.message.find(words), std::string::npos) << d.message;
}

std::vector<uint32_t> with(std::vector<uint32_t> t, size_t i, uint32_t v) {
  t[i] = v;
  return t;
}

} // namespace

TEST(BytecodeMalformed, ValidStreamsDisassemble) {
  DiagnosticSink diags;
  EXPECT_TRUE(disassemble(kPs20, diags).has_value());
  EXPECT_TRUE(disassemble(kVs11, diags).has_value());
  EXPECT_FALSE(diags.has_errors());
}

TEST(BytecodeMalformed, EmptyAndBadVersion) {
  expect_error({}, 0, "empty");
  expect_error({0x12345678, 0x0000FFFF}, 0, "not a shader version");
  expect_error({0xFFFF0301, 0x0000FFFF}, 0, "3.1"); // no such profile (ps_3_0 is one)
  expect_error({0xFFFE0100, 0x0000FFFF}, 0, "1.0");
}

TEST(BytecodeMalformed, MissingEndAndTrailingData) {
  std::vector<uint32_t> t(kPs20.begin(), kPs20.end() - 1);
  expect_error(t, 14, "missing end token");
  t = kPs20;
  t.push_back(0xDEADBEEF);
  expect_error(t, 15, "trailing");
  expect_error(with(kPs20, 14, 0x0001FFFF), 14, "end token");
}

TEST(BytecodeMalformed, TruncatedAtEveryLength) {
  for (const auto& full : {kPs20, kVs11}) {
    for (size_t n = 1; n + 1 < full.size(); ++n) {
      std::vector<uint32_t> t(full.begin(), full.begin() + static_cast<ptrdiff_t>(n));
      DiagnosticSink diags;
      EXPECT_FALSE(disassemble(t, diags).has_value()) << n;
      EXPECT_EQ(diags.error_count(), 1u);
    }
  }
  // SM2: the length field runs past the end.
  expect_error({0xFFFF0200, 0x02000001, 0x800F0800}, 1, "runs past the end");
  // SM1: no length field, the stream ends inside the operands.
  expect_error({0xFFFF0101, 0x00000002, 0x800F0000}, 1, "truncated");
}

TEST(BytecodeMalformed, LengthFieldMustMatchOperands) {
  // mov with length 3: its operands take 2 → the third token is unaccounted for.
  std::vector<uint32_t> t = {0xFFFF0200, 0x03000001, 0x800F0800,
                             0x80E40000, 0x80E40000, 0x0000FFFF};
  expect_error(t, 1, "take 2");
  // mov with length 1: too short for its two operands.
  expect_error({0xFFFF0200, 0x01000001, 0x800F0800, 0x0000FFFF}, 1, "too short");
  // SM1 must leave bits 24-27 clear.
  expect_error(with(kVs11, 4, 0x03000002), 4, "length");
}

TEST(BytecodeMalformed, UnknownOpcodes) {
  expect_error(with(kPs20, 11, 0x02001234), 11, "unknown opcode 0x1234");
  // dsx (0x5B) exists only in ps_2_x and ps_3_0: the table names it.
  expect_error(with(kPs20, 11, 0x0200005B), 11,
               "'dsx' (opcode 0x5B) is not an instruction of ps_2_0");
  // dp4 exists, but not in ps_1_1.
  expect_error({0xFFFF0101, 0x00000009, 0x800F0000, 0x80E40000, 0x80E40000, 0x0000FFFF}, 1,
               "not an instruction of ps_1_1");
  // texld with control 3 (no such variant).
  expect_error(with(kPs20, 7, 0x03030042), 7, "control");
}

TEST(BytecodeMalformed, ReservedAndInvalidBits) {
  expect_error(with(kPs20, 11, 0x12000001), 11, "predicated");
  expect_error(with(kPs20, 11, 0x22000001), 11, "bit 29");
  expect_error(with(kPs20, 11, 0x42000001), 11, "co-issue"); // not ps_1_x
  expect_error(with(kPs20, 12, 0x800F4800), 12, "reserved bits 14-15");
  expect_error(with(kPs20, 12, 0x000F0800), 12, "bit 31");          // no param bit
  expect_error(with(kPs20, 12, 0x808F0800), 12, "result modifier"); // bit 3 of resmod
  expect_error(with(kPs20, 12, 0x850F0800), 12, "shift");           // shift 5
  expect_error(with(kPs20, 12, 0x800F2800), 12, "relative addressing of a destination");
  expect_error(with(kPs20, 13, 0x8EE40000), 13, "source modifier 14");
  expect_error(with(kPs20, 13, 0x80E42000), 13, "pixel shader"); // relative in ps
  expect_error(with(kPs20, 2, 0x80000001), 2, "usage 0");        // ps dcl usage
  expect_error(with(kPs20, 5, 0x88000000), 5, "sampler type 1");
  expect_error(with(kVs11, 2, 0x80000014), 2, "usage 20");
  expect_error(with(kVs11, 2, 0x80100005), 2, "reserved"); // index bit 20
}

TEST(BytecodeMalformed, FieldsNoTextCanSpell) {
  // Write mask 0 on oC0.
  expect_error(with(kPs20, 12, 0x80000800), 12, "empty write mask");
  // dcl_sat t0 (sat = 1<<20) and a _pp vertex input (pp = 2<<20).
  expect_error(with(kPs20, 3, 0xB01F0000), 3, "modifier");
  expect_error(with(kVs11, 3, 0x902F0003), 3, "modifier");
  // _pp on a sampler declaration.
  expect_error(with(kPs20, 6, 0xA02F0800), 6, "modifier");
}

TEST(BytecodeMalformed, BadRegisterTypesAndNumbers) {
  // type 13 (CONST4, software vertex processing): lo 0b101, hi 0b01 → 0x5000_0800.
  expect_error(with(kPs20, 13, 0xD0E40800), 13, "register type 13");
  // RastOut only has oPos, oFog, oPts.
  expect_error(with(kVs11, 5, 0xC00F0003), 5, "no register number 3");
  // dcl of an output register.
  expect_error(with(kVs11, 3, 0xE00F0000), 3, "cannot be declared");
}

TEST(BytecodeMalformed, Vs20RelativeToken) {
  // mov r0, c[a0.x + 1] with a broken address token.
  std::vector<uint32_t> ok = {0xFFFE0200, 0x03000001, 0x800F0000,
                              0xA0E42001, 0xB0000000, 0x0000FFFF};
  DiagnosticSink diags;
  EXPECT_TRUE(disassemble(ok, diags).has_value());
  // a0 takes any swizzle (Microsoft writes a0.xyww as it stands); aL only the identity or a
  // replicate.
  EXPECT_TRUE(disassemble(with(ok, 4, 0xB0F40000), diags).has_value());
  expect_error(with(ok, 4, 0xF0F40800), 4, "identity or a replicate");
  expect_error(with(ok, 4, 0x80000000), 4, "not a0 or aL");
  expect_error(with(ok, 4, 0xB1000000), 4, "modifier");
  // The address token is missing: the length field only covers two operands.
  expect_error({0xFFFE0200, 0x02000001, 0x800F0000, 0xA0E42001, 0x0000FFFF}, 1, "too short");
}

TEST(BytecodeMalformed, Definitions) {
  std::vector<uint32_t> def = {0xFFFF0200, 0x05000051, 0xA00F0003, 0x3F800000, 0, 0, 0, 0x0000FFFF};
  DiagnosticSink diags;
  EXPECT_TRUE(disassemble(def, diags).has_value());
  expect_error(with(def, 2, 0xA0070003), 2, "full write mask");
  expect_error(with(def, 2, 0x800F0003), 2, "defines c#");
  std::vector<uint32_t> defb = {0xFFFE0200, 0x0200002F, 0xE00F0801, 0x00000002, 0x0000FFFF};
  expect_error(defb, 3, "defb value");
}

TEST(BytecodeMalformed, Comments) {
  // A comment anywhere between statements is kept, word for word and in its place.
  std::vector<uint32_t> t = kPs20;
  t.insert(t.begin() + 1, {0x0002FFFE, 0x42415443, 0x0000001C});
  t.insert(t.begin() + 14, {0x0000FFFE}); // empty comment
  DiagnosticSink diags;
  auto p = disassemble(t, diags);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->comments.size(), 2u);
  EXPECT_EQ(assemble(*p), t);
  // Comment longer than what is left: 0x7FFF DWORDs announced, 2 present.
  expect_error({0xFFFF0200, 0x7FFFFFFE, 0x0000FFFF, 0x0000FFFF}, 1, "runs past the end");
  expect_error({0xFFFF0200, 0x8001FFFE, 0, 0x0000FFFF}, 1, "bit 31");
  // A comment that swallows the end token leaves the stream without one.
  expect_error({0xFFFF0200, 0x0001FFFE, 0x0000FFFF}, 3, "missing end token");
}

// Every single-bit flip of valid streams and a stream of random words: no crash, and
// whatever is accepted re-assembles to exactly the input (nothing silently dropped).
TEST(BytecodeMalformed, BitFlipsAreRejectedOrRoundTripExactly) {
  const std::vector<uint32_t> ps14 = {0xFFFF0104, 0x00000051, 0xA00F0000, 0x3F000000, 0x3F000000,
                                      0x3F000000, 0x3F000000, 0x00000040, 0x80070001, 0xB0E40001,
                                      0x00000042, 0x800F0000, 0xB9E40000, 0x0000FFFD, 0x40000001,
                                      0x80080000, 0x80E40002, 0x0000FFFF};
  const std::vector<uint32_t> vs20 = {0xFFFE0200, 0x0200001F, 0x80020005, 0x900F0004, 0x03000001,
                                      0x800F0000, 0xA0E42007, 0xB0550000, 0x0200001B, 0xF0E40800,
                                      0xF0E40002, 0x0000001D, 0x0000FFFF};
  size_t accepted = 0;
  for (const auto& base : {kPs20, kVs11, ps14, vs20}) {
    for (size_t i = 0; i < base.size(); ++i) {
      for (int bit = 0; bit < 32; ++bit) {
        std::vector<uint32_t> t = base;
        t[i] ^= 1u << bit;
        DiagnosticSink diags;
        auto p = disassemble(t, diags);
        if (!p) {
          EXPECT_TRUE(diags.has_errors());
          continue;
        }
        ++accepted;
        EXPECT_EQ(assemble(*p), t) << "token " << i << " bit " << bit;
        // And through the printed text (what `disasm` writes and `assemble` reads).
        auto text = tierlift::assembly::parse_text(tierlift::assembly::print_program(*p), "d.asm");
        ASSERT_TRUE(text.program.has_value()) << tierlift::assembly::print_program(*p);
        EXPECT_EQ(assemble(*text.program), t) << tierlift::assembly::print_program(*p);
      }
    }
  }
  EXPECT_GT(accepted, 100u); // masks, swizzles, register numbers, float bits
  std::mt19937 rng(12345);
  for (int n = 0; n < 2000; ++n) {
    std::vector<uint32_t> t(1 + rng() % 24);
    for (auto& w : t) w = rng();
    t[0] = (n % 2) ? 0xFFFF0200 : 0xFFFE0101;
    DiagnosticSink diags;
    auto p = disassemble(t, diags);
    if (!p) {
      EXPECT_TRUE(diags.has_errors());
      continue;
    }
    EXPECT_EQ(assemble(*p), t);
    auto text = tierlift::assembly::parse_text(tierlift::assembly::print_program(*p), "d.asm");
    ASSERT_TRUE(text.program.has_value()) << tierlift::assembly::print_program(*p);
    EXPECT_EQ(assemble(*text.program), t) << tierlift::assembly::print_program(*p);
  }
}
