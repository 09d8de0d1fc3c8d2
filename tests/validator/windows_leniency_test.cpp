// What the Direct3D runtimes took beyond the documented rules (NUMERICS.md, "Windows
// leniency"): taken with a warning that names the rule, rewritten to what Windows ran;
// rejected under strict. Streams written out by hand (docs/d3d9-rules.md §9): vs_1_1 =
// 0xFFFE0101; mov = 0x01, rcp = 0x06, exp = 0x0E; oPos = 0xC00F0000, oD0 = 0xD00F0000,
// r0 = 0x800F0000; c# = 0xA0E4000n with the identity swizzle .xyzw (0xE4).
#include <gtest/gtest.h>

#include "loaded_listing.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/load.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/ir/semantics.h"

namespace {

using namespace tierlift;
using Tokens = std::vector<uint32_t>;

using Loaded = test::LoadedListing;

Loaded load(std::string bytes, bool strict) {
  assembly::LoadOptions o;
  o.strict = strict;
  return test::load_bytes(std::move(bytes), "s.vso", o);
}

// mov oPos, c0 / OP r0, c1 (identity swizzle) / mov oD0, r0
Tokens d3d8_scalar_stream(uint32_t opcode) {
  return {0xFFFE0101, 0x00000001, 0xC00F0000, 0xA0E40000, opcode,    0x800F0000,
          0xA0E40001, 0x00000001, 0xD00F0000, 0x80E40000, 0x0000FFFF};
}

} // namespace

TEST(WindowsLeniency, ScalarSourceWithoutReplicateReadsW) {
  for (uint32_t opcode : {0x0Eu /* exp */, 0x0Fu /* log */, 0x06u /* rcp */, 0x07u /* rsq */}) {
    SCOPED_TRACE(opcode);
    Loaded l = load(assembly::tokens_to_bytes(d3d8_scalar_stream(opcode)), false);
    ASSERT_TRUE(l.r().program.ok()) << l.rendered;
    EXPECT_EQ(l.count(ir::Severity::Warning, "swizzle"), 1u) << l.rendered;
    // The warning sits on the source token (index 6, byte 0x18) and names c1.w.
    EXPECT_NE(l.rendered.find("s.vso:+0x18: warning: "), std::string::npos) << l.rendered;
    EXPECT_NE(l.rendered.find("c1.w"), std::string::npos) << l.rendered;
    // The IR reads .w: replicate w = 0b11'11'11'11.
    EXPECT_EQ(l.r().program->code[1].src[0].swizzle, 0xFF);
  }
}

TEST(WindowsLeniency, StrictRejectsTheScalarSource) {
  Loaded l = load(assembly::tokens_to_bytes(d3d8_scalar_stream(0x0E)), true);
  EXPECT_FALSE(l.r().program.ok());
  EXPECT_EQ(l.count(ir::Severity::Error, "swizzle"), 1u) << l.rendered;
  EXPECT_NE(l.rendered.find("s.vso:+0x18: error: "), std::string::npos) << l.rendered;
}

// Text keeps the assembler's rule: a bare rcp source is .x (docs/d3d9-rules.md §4.3), no warning.
TEST(WindowsLeniency, BareRcpInTextStillReadsX) {
  Loaded l = load("vs.1.1\nmov oPos, c0\nrcp r0, c1\nmov oD0, r0\n", false);
  ASSERT_TRUE(l.r().program.ok()) << l.rendered;
  EXPECT_EQ(l.r().program->code[1].src[0].swizzle, 0x00);
  EXPECT_EQ(l.diags.warning_count(), 0u) << l.rendered;
}

// ps_1_4 "texcrd r0, t0" without a mask: Microsoft's assembler writes the full mask
// (0x800F0000; Wine's d3dcompiler asm tests expect exactly that for "texcrd r0, t0", and
// 0x801F0004 for "texcrd_sat r4, t3"), so the stream keeps it; what the instruction
// defines is still .xyz (.xy with _dw). tierlift used to write 0x80070000 here.
// Tokens by hand: def = 0x51, texcrd = 0x40, cnd = 0x50; 1.0f = 0x3F800000.
TEST(WindowsLeniency, Ps14TexcrdWithoutMaskKeepsTheFullMask) {
  const char* text = "ps_1_4\ndef c0, 0, 0, 0, 1\ntexcrd r0, t0\nmov r0.a, c0.a\n"
                     "cnd r0, r0, c1, c2\n";
  Loaded l = load(text, false);
  ASSERT_TRUE(l.r().program.ok()) << l.rendered;
  EXPECT_EQ(l.count(ir::Severity::Warning, "write-mask"), 1u) << l.rendered;
  EXPECT_NE(l.rendered.find("keeps the full mask"), std::string::npos) << l.rendered;
  EXPECT_EQ(l.rendered.find("as Windows did"), std::string::npos) << l.rendered;
  const ir::Instruction& texcrd = l.r().program->code[0];
  EXPECT_EQ(texcrd.dst->mask, 0xF);
  EXPECT_EQ(ir::written_mask(texcrd, ir::Profile::ps_1_4), 0x7);
  Tokens expected = {0xFFFF0104, 0x00000051, 0xA00F0000, 0x00000000, 0x00000000,
                     0x00000000, 0x3F800000, 0x00000040, 0x800F0000, 0xB0E40000,
                     0x00000001, 0x80080000, 0xA0FF0000, 0x00000050, 0x800F0000,
                     0x80E40000, 0xA0E40001, 0xA0E40002, 0x0000FFFF};
  EXPECT_EQ(assembly::assemble(*l.r().program), expected);
  // texcrd_sat is refused by the validator; the assembler still writes its full mask.
  assembly::ParseResult sat = assembly::parse_text("ps_1_4\ntexcrd_sat r4, t3\nmov r0.rgb, r4\n");
  ASSERT_TRUE(sat.program.has_value());
  EXPECT_EQ(assembly::assemble(*sat.program),
            (Tokens{0xFFFF0104, 0x00000040, 0x801F0004, 0xB0E40003, 0x00000001, 0x80070000,
                    0x80E40004, 0x0000FFFF}));
  // _dw defines .rg.
  Loaded dw = load("ps_1_4\ntexcrd r0, t0_dw.xyw\nmov r0.a, c0.a\n", false);
  ASSERT_TRUE(dw.r().program.ok()) << dw.rendered;
  EXPECT_EQ(ir::written_mask(dw.r().program->code[0], ir::Profile::ps_1_4), 0x3);
}

TEST(WindowsLeniency, StrictRejectsTexcrdWithoutMask) {
  Loaded l = load("ps_1_4\ntexcrd r0, t0\nmov r0.a, c0.a\n", true);
  EXPECT_FALSE(l.r().program.ok());
  EXPECT_EQ(l.count(ir::Severity::Error, "write-mask"), 1u) << l.rendered;
}

// ps_1_4 texld takes no mask at all: nothing to forgive, in either mode.
TEST(WindowsLeniency, Ps14TexldWithoutMaskIsLegal) {
  for (bool strict : {false, true}) {
    Loaded l = load("ps_1_4\ntexld r0, t0\n", strict);
    EXPECT_TRUE(l.r().program.ok()) << l.rendered;
  }
}
