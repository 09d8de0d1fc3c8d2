// The Direct3D 9 encoding pinned against the published values, typed here as a list of
// their own (the D3DSIO_*, D3DSPSM_*, D3DSPDM_*, D3DSPR_* and D3DSI_TEXLD_* numbers of the
// d3d9types.h documentation), never read from the opcode table they check. The assembler
// and the disassembler share one table, so their round trip agrees with any number in it;
// these tests are what fails when a number is wrong (dp2add 0x5A changed to 0x5C fails
// OpcodePins.TableRowsHaveTheDocumentedNumbers and OpcodePins.AssemblerWritesThem).
//
// Adding an opcode to the table: add its line to kOpcodePins (a row the table has but no
// pin names fails). Pins the table does not have yet (shader model 2.x/3.0 rows) are
// skipped, so they need no change when those rows arrive; a row that does arrive is held
// to its number at once.
#include <gtest/gtest.h>

#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/ir/opcodes.h"
#include "tierlift/ir/registers.h"

namespace {

using namespace tierlift;

constexpr int kAny = -1;

struct OpcodePin {
  std::string_view mnemonic;
  int sources;           // the row's source count, or kAny: tells apart rows of one mnemonic
  uint16_t code;         // D3DSIO_*
  int control;           // bits 16-23 of the instruction token where fixed, or kAny
  std::string_view text; // a listing with the instruction as its only statement
};

// clang-format off
constexpr OpcodePin kOpcodePins[] = {
  {"nop",          kAny, 0x00, kAny, "vs_1_1\nnop"},
  {"mov",          kAny, 0x01, kAny, "vs_1_1\nmov r0, r1"},
  {"add",          kAny, 0x02, kAny, "vs_1_1\nadd r0, r1, r2"},
  {"sub",          kAny, 0x03, kAny, "vs_1_1\nsub r0, r1, r2"},
  {"mad",          kAny, 0x04, kAny, "vs_1_1\nmad r0, r1, r2, r3"},
  {"mul",          kAny, 0x05, kAny, "vs_1_1\nmul r0, r1, r2"},
  {"rcp",          kAny, 0x06, kAny, "vs_1_1\nrcp r0, r1.x"},
  {"rsq",          kAny, 0x07, kAny, "vs_1_1\nrsq r0, r1.x"},
  {"dp3",          kAny, 0x08, kAny, "vs_1_1\ndp3 r0, r1, r2"},
  {"dp4",          kAny, 0x09, kAny, "vs_1_1\ndp4 r0, r1, r2"},
  {"min",          kAny, 0x0A, kAny, "vs_1_1\nmin r0, r1, r2"},
  {"max",          kAny, 0x0B, kAny, "vs_1_1\nmax r0, r1, r2"},
  {"slt",          kAny, 0x0C, kAny, "vs_1_1\nslt r0, r1, r2"},
  {"sge",          kAny, 0x0D, kAny, "vs_1_1\nsge r0, r1, r2"},
  {"exp",          kAny, 0x0E, kAny, "vs_1_1\nexp r0, r1.x"},
  {"log",          kAny, 0x0F, kAny, "vs_1_1\nlog r0, r1.x"},
  {"lit",          kAny, 0x10, kAny, "vs_1_1\nlit r0, r1"},
  {"dst",          kAny, 0x11, kAny, "vs_1_1\ndst r0, r1, r2"},
  {"lrp",          kAny, 0x12, kAny, "vs_2_0\nlrp r0, r1, r2, r3"},
  {"frc",          kAny, 0x13, kAny, "vs_2_0\nfrc r0, r1"},
  {"m4x4",         kAny, 0x14, kAny, "vs_1_1\nm4x4 r0, r1, c0"},
  {"m4x3",         kAny, 0x15, kAny, "vs_1_1\nm4x3 r0.xyz, r1, c0"},
  {"m3x4",         kAny, 0x16, kAny, "vs_1_1\nm3x4 r0, r1, c0"},
  {"m3x3",         kAny, 0x17, kAny, "vs_1_1\nm3x3 r0.xyz, r1, c0"},
  {"m3x2",         kAny, 0x18, kAny, "vs_1_1\nm3x2 r0.xy, r1, c0"},
  {"call",         kAny, 0x19, kAny, "vs_2_0\ncall l1"},
  {"callnz",       kAny, 0x1A, kAny, "vs_2_0\ncallnz l1, b0"},
  {"loop",         kAny, 0x1B, kAny, "vs_2_0\nloop aL, i0"},
  {"ret",          kAny, 0x1C, kAny, "vs_2_0\nret"},
  {"endloop",      kAny, 0x1D, kAny, "vs_2_0\nendloop"},
  {"label",        kAny, 0x1E, kAny, "vs_2_0\nlabel l1"},
  {"dcl",          kAny, 0x1F, kAny, "vs_1_1\ndcl_position v0"},
  {"pow",          kAny, 0x20, kAny, "vs_2_0\npow r0, r1.x, r2.x"},
  {"crs",          kAny, 0x21, kAny, "vs_2_0\ncrs r0.xyz, r1, r2"},
  {"sgn",          kAny, 0x22, kAny, "vs_2_0\nsgn r0, r1, r2, r3"},
  {"abs",          kAny, 0x23, kAny, "vs_2_0\nabs r0, r1"},
  {"nrm",          kAny, 0x24, kAny, "vs_2_0\nnrm r0, r1"},
  {"sincos",       kAny, 0x25, kAny, "vs_2_0\nsincos r0.xy, r1.x, c0, c1"},
  {"rep",          kAny, 0x26, kAny, "vs_2_0\nrep i0"},
  {"endrep",       kAny, 0x27, kAny, "vs_2_0\nendrep"},
  {"if",           1,    0x28, kAny, "vs_2_0\nif b0"},
  {"if",           2,    0x29, kAny, "vs_2_x\nif_gt r0.x, r1.x"},   // D3DSIO_IFC
  {"ifc",          kAny, 0x29, kAny, "vs_2_x\nif_gt r0.x, r1.x"},
  {"else",         kAny, 0x2A, kAny, "vs_2_0\nelse"},
  {"endif",        kAny, 0x2B, kAny, "vs_2_0\nendif"},
  {"break",        0,    0x2C, kAny, "vs_2_x\nbreak"},
  {"break",        2,    0x2D, kAny, "vs_2_x\nbreak_ne r0.x, r1.x"}, // D3DSIO_BREAKC
  {"breakc",       kAny, 0x2D, kAny, "vs_2_x\nbreak_ne r0.x, r1.x"},
  {"mova",         kAny, 0x2E, kAny, "vs_2_0\nmova a0.x, r0.x"},
  {"defb",         kAny, 0x2F, kAny, "vs_2_0\ndefb b0, true"},
  {"defi",         kAny, 0x30, kAny, "vs_2_0\ndefi i0, 1, 2, 3, 4"},
  {"texcoord",     kAny, 0x40, kAny, "ps_1_1\ntexcoord t0"},
  {"texcrd",       kAny, 0x40, kAny, "ps_1_4\ntexcrd r0.rgb, t0"},
  {"texkill",      kAny, 0x41, kAny, "ps_1_1\ntexkill t0"},
  {"tex",          kAny, 0x42, kAny, "ps_1_1\ntex t0"},
  {"texld",        1,    0x42, 0,    "ps_1_4\ntexld r0, t0"},
  {"texld",        2,    0x42, 0,    "ps_2_0\ntexld r0, t0, s0"},
  {"texldp",       kAny, 0x42, 1,    "ps_2_0\ntexldp r0, t0, s0"},  // D3DSI_TEXLD_PROJECT
  {"texldb",       kAny, 0x42, 2,    "ps_2_0\ntexldb r0, t0, s0"},  // D3DSI_TEXLD_BIAS
  {"texbem",       kAny, 0x43, kAny, "ps_1_1\ntexbem t1, t0"},
  {"texbeml",      kAny, 0x44, kAny, "ps_1_1\ntexbeml t1, t0"},
  {"texreg2ar",    kAny, 0x45, kAny, "ps_1_1\ntexreg2ar t1, t0"},
  {"texreg2gb",    kAny, 0x46, kAny, "ps_1_1\ntexreg2gb t1, t0"},
  {"texm3x2pad",   kAny, 0x47, kAny, "ps_1_1\ntexm3x2pad t1, t0"},
  {"texm3x2tex",   kAny, 0x48, kAny, "ps_1_1\ntexm3x2tex t2, t0"},
  {"texm3x3pad",   kAny, 0x49, kAny, "ps_1_1\ntexm3x3pad t1, t0"},
  {"texm3x3tex",   kAny, 0x4A, kAny, "ps_1_1\ntexm3x3tex t3, t0"},
  {"texm3x3spec",  kAny, 0x4C, kAny, "ps_1_1\ntexm3x3spec t3, t0, c0"},
  {"texm3x3vspec", kAny, 0x4D, kAny, "ps_1_1\ntexm3x3vspec t3, t0"},
  {"expp",         kAny, 0x4E, kAny, "vs_1_1\nexpp r0, r1.x"},
  {"logp",         kAny, 0x4F, kAny, "vs_1_1\nlogp r0, r1.x"},
  {"cnd",          kAny, 0x50, kAny, "ps_1_1\ncnd r0, r0.a, r1, t0"},
  {"def",          kAny, 0x51, kAny, "ps_1_1\ndef c0, 1, 0, 0, 1"},
  {"texreg2rgb",   kAny, 0x52, kAny, "ps_1_2\ntexreg2rgb t1, t0"},
  {"texdp3tex",    kAny, 0x53, kAny, "ps_1_2\ntexdp3tex t1, t0"},
  {"texm3x2depth", kAny, 0x54, kAny, "ps_1_3\ntexm3x2depth t2, t0"},
  {"texdp3",       kAny, 0x55, kAny, "ps_1_2\ntexdp3 t1, t0"},
  {"texm3x3",      kAny, 0x56, kAny, "ps_1_2\ntexm3x3 t3, t0"},
  {"texdepth",     kAny, 0x57, kAny, "ps_1_4\ntexdepth r5"},
  {"cmp",          kAny, 0x58, kAny, "ps_2_0\ncmp r0, r1, r2, r3"},
  {"bem",          kAny, 0x59, kAny, "ps_1_4\nbem r1.rg, c0, r0"},
  {"dp2add",       kAny, 0x5A, kAny, "ps_2_0\ndp2add r0, r1, r2, r3.x"},
  {"dsx",          kAny, 0x5B, kAny, "ps_2_x\ndsx r0, r1"},
  {"dsy",          kAny, 0x5C, kAny, "ps_2_x\ndsy r0, r1"},
  {"texldd",       kAny, 0x5D, kAny, "ps_2_x\ntexldd r0, t0, s0, r1, r2"},
  {"setp",         kAny, 0x5E, kAny, "ps_2_x\nsetp_gt p0, r0, r1"},
  {"texldl",       kAny, 0x5F, kAny, "vs_3_0\ntexldl r0, v0, s0"},
  {"breakp",       kAny, 0x60, kAny, "ps_2_x\nbreakp p0.x"},
  // The comparison rows: D3DSHADER_COMPARISON in the control field (GT 1, EQ 2, GE 3, LT 4,
  // NE 5, LE 6).
  {"if_gt",        kAny, 0x29, 1,    "vs_2_x\nif_gt r0.x, r1.x"},
  {"if_eq",        kAny, 0x29, 2,    "vs_2_x\nif_eq r0.x, r1.x"},
  {"if_ge",        kAny, 0x29, 3,    "vs_2_x\nif_ge r0.x, r1.x"},
  {"if_lt",        kAny, 0x29, 4,    "vs_2_x\nif_lt r0.x, r1.x"},
  {"if_ne",        kAny, 0x29, 5,    "vs_2_x\nif_ne r0.x, r1.x"},
  {"if_le",        kAny, 0x29, 6,    "vs_2_x\nif_le r0.x, r1.x"},
  {"break_gt",     kAny, 0x2D, 1,    "vs_2_x\nbreak_gt r0.x, r1.x"},
  {"break_eq",     kAny, 0x2D, 2,    "vs_2_x\nbreak_eq r0.x, r1.x"},
  {"break_ge",     kAny, 0x2D, 3,    "vs_2_x\nbreak_ge r0.x, r1.x"},
  {"break_lt",     kAny, 0x2D, 4,    "vs_2_x\nbreak_lt r0.x, r1.x"},
  {"break_ne",     kAny, 0x2D, 5,    "vs_2_x\nbreak_ne r0.x, r1.x"},
  {"break_le",     kAny, 0x2D, 6,    "vs_2_x\nbreak_le r0.x, r1.x"},
  {"setp_gt",      kAny, 0x5E, 1,    "ps_2_x\nsetp_gt p0, r0, r1"},
  {"setp_eq",      kAny, 0x5E, 2,    "ps_2_x\nsetp_eq p0, r0, r1"},
  {"setp_ge",      kAny, 0x5E, 3,    "ps_2_x\nsetp_ge p0, r0, r1"},
  {"setp_lt",      kAny, 0x5E, 4,    "ps_2_x\nsetp_lt p0, r0, r1"},
  {"setp_ne",      kAny, 0x5E, 5,    "ps_2_x\nsetp_ne p0, r0, r1"},
  {"setp_le",      kAny, 0x5E, 6,    "ps_2_x\nsetp_le p0, r0, r1"},
  {"phase",        kAny, 0xFFFD, kAny, "ps_1_4\nphase"},
};
// clang-format on

// The pins a table row answers to: same mnemonic, and same source count where the pin
// names one.
std::vector<const OpcodePin*> pins_for(const ir::OpInfo& row) {
  std::vector<const OpcodePin*> out;
  for (const OpcodePin& pin : kOpcodePins)
    if (pin.mnemonic == row.mnemonic && (pin.sources == kAny || pin.sources == row.num_src))
      out.push_back(&pin);
  return out;
}

bool table_has(const OpcodePin& pin) {
  for (const ir::OpInfo& row : ir::opcode_table())
    if (row.mnemonic == pin.mnemonic && (pin.sources == kAny || pin.sources == row.num_src))
      return true;
  return false;
}

// The instruction token of a listing whose only statement is one instruction (or dcl/def).
std::optional<uint32_t> instruction_token(std::string_view text) {
  auto r = assembly::parse_text(std::string(text) + "\n");
  if (!r.program) return std::nullopt;
  std::vector<uint32_t> tokens = assembly::assemble(*r.program);
  if (tokens.size() < 3) return std::nullopt;
  return tokens[1];
}

} // namespace

TEST(OpcodePins, TableRowsHaveTheDocumentedNumbers) {
  size_t checked = 0;
  for (const ir::OpInfo& row : ir::opcode_table()) {
    SCOPED_TRACE(fmt::format("{} with {} sources", row.mnemonic, row.num_src));
    std::vector<const OpcodePin*> pins = pins_for(row);
    ASSERT_FALSE(pins.empty()) << "no pin names this row: add its documented D3DSIO number "
                                  "to kOpcodePins";
    for (const OpcodePin* pin : pins) {
      EXPECT_EQ(row.code, pin->code)
          << fmt::format("documented 0x{:X}, the table says 0x{:X}", pin->code, row.code);
      if (pin->control != kAny) {
        EXPECT_EQ(row.control, pin->control);
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 73u); // the shader model 1.x/2.0 rows at least
}

// The assembler's instruction token carries the documented number (and texld's control
// field), for every pin whose row exists: what lands in a stream, not only in the table.
TEST(OpcodePins, AssemblerWritesThem) {
  size_t checked = 0;
  std::vector<std::string_view> pending;
  for (const OpcodePin& pin : kOpcodePins) {
    if (!table_has(pin)) {
      pending.push_back(pin.mnemonic);
      continue;
    }
    SCOPED_TRACE(pin.text);
    std::optional<uint32_t> token = instruction_token(pin.text);
    if (!token) {
      // The row exists but its profile or syntax does not parse yet (a shader model 2.x/3.0
      // row added before its profile): the table test above still pins its number.
      pending.push_back(pin.mnemonic);
      continue;
    }
    EXPECT_EQ(*token & 0xFFFFu, pin.code) << fmt::format("token 0x{:08X}", *token);
    if (pin.control != kAny) {
      EXPECT_EQ((*token >> 16) & 0xFFu, static_cast<uint32_t>(pin.control));
    }
    ++checked;
  }
  EXPECT_GE(checked, 73u);
  if (!pending.empty()) {
    std::string list;
    for (std::string_view m : pending) list += fmt::format(" {}", m);
    std::cout << "[ pending  ] pins without a row (or profile) yet:" << list << "\n";
  }
}

// D3DSPR_*: the register type of each register file, found through its name (so that files
// added later are held to their number as soon as they print a name listed here).
TEST(OpcodePins, RegisterTypes) {
  struct TypePin {
    std::string_view name; // register_name(file, 0)
    uint8_t type;
  };
  static constexpr TypePin kTypePins[] = {
      {"r0", 0},  {"v0", 1},    {"c0", 2},     {"a0", 3},  {"t0", 3},     {"oPos", 4}, {"oD0", 5},
      {"oT0", 6}, {"o0", 6},    {"i0", 7},     {"oC0", 8}, {"oDepth", 9}, {"s0", 10},  {"b0", 14},
      {"aL", 15}, {"vPos", 17}, {"vFace", 17}, {"l0", 18}, {"p0", 19},
  };
  size_t checked = 0;
  for (int f = 0; f < 256; ++f) {
    const auto file = static_cast<ir::RegFile>(f);
    const std::string name = ir::register_name(file, 0);
    if (name == "?") continue;
    SCOPED_TRACE(name);
    const TypePin* pin = nullptr;
    for (const TypePin& p : kTypePins)
      if (p.name == name) pin = &p;
    ASSERT_NE(pin, nullptr) << "no pin names this register file: add its D3DSPR_* number";
    EXPECT_EQ(ir::bytecode_regtype(file), pin->type);
    // Back from the number: type 3 is a0 or t# by stage, type 6 oT# or o# by profile; each
    // file is read back in a profile that has it.
    const bool pixel = name == "t0" || name == "oC0" || name == "oDepth" || name == "s0";
    const bool sm3_pixel = name == "vPos" || name == "p0";
    const ir::Profile profile = pixel          ? ir::Profile::ps_2_0
                                : sm3_pixel    ? ir::Profile::ps_3_0
                                : name == "o0" ? ir::Profile::vs_3_0
                                               : ir::Profile::vs_2_0;
    EXPECT_EQ(ir::regfile_from_bytecode(pin->type, profile), file);
    ++checked;
  }
  EXPECT_GE(checked, 15u);
}

// D3DSPSM_* (source modifier, bits 24-27 of a source token) and D3DSPDM_* / shift (bits
// 20-23 and 24-27 of a destination token), as the assembler writes them.
TEST(OpcodePins, ModifierBits) {
  struct Case {
    const char* text; // the last token of its stream is the operand checked
    uint32_t mask, expect;
  };
  const Case cases[] = {
      {"ps_1_4\nmov r0, r1", 0x0F000000, 0u << 24},           // NONE
      {"ps_1_4\nmov r0, -r1", 0x0F000000, 1u << 24},          // NEG
      {"ps_1_4\nmov r0, r1_bias", 0x0F000000, 2u << 24},      // BIAS
      {"ps_1_4\nmov r0, -r1_bias", 0x0F000000, 3u << 24},     // BIASNEG
      {"ps_1_4\nmov r0, r1_bx2", 0x0F000000, 4u << 24},       // SIGN
      {"ps_1_4\nmov r0, -r1_bx2", 0x0F000000, 5u << 24},      // SIGNNEG
      {"ps_1_4\nmov r0, 1-r1", 0x0F000000, 6u << 24},         // COMP
      {"ps_1_4\nmov r0, r1_x2", 0x0F000000, 7u << 24},        // X2
      {"ps_1_4\nmov r0, -r1_x2", 0x0F000000, 8u << 24},       // X2NEG
      {"ps_1_4\ntexld r0, r1_dz", 0x0F000000, 9u << 24},      // DZ
      {"ps_1_4\ntexld r0, t1_dw.xyw", 0x0F000000, 10u << 24}, // DW
      {"vs_2_0\ncallnz l1, !b0", 0x0F000000, 13u << 24},      // NOT
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    auto r = assembly::parse_text(std::string(c.text) + "\n");
    ASSERT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources);
    std::vector<uint32_t> t = assembly::assemble(*r.program);
    ASSERT_GE(t.size(), 3u);
    EXPECT_EQ(t[t.size() - 2] & c.mask, c.expect) << fmt::format("0x{:08X}", t[t.size() - 2]);
  }
  // _abs (D3DSPSM_ABS 11, ABSNEG 12) exists from shader model 3.0 on.
  struct Dst {
    const char* text;
    uint32_t expect; // the destination token's bits 20-27
  };
  const Dst dsts[] = {
      {"ps_1_4\nmov_sat r0, r1", 1u << 20},  // D3DSPDM_SATURATE
      {"ps_2_0\nmov_pp r0, r1", 2u << 20},   // D3DSPDM_PARTIALPRECISION
      {"ps_2_0\ndcl_centroid t0", 4u << 20}, // D3DSPDM_MSAMPCENTROID
      {"ps_1_4\nmov_x2 r0, r1", 1u << 24},   // shift +1
      {"ps_1_4\nmov_x4 r0, r1", 2u << 24},   // shift +2
      {"ps_1_4\nmov_x8 r0, r1", 3u << 24},   // shift +3
      {"ps_1_4\nmov_d2 r0, r1", 0xFu << 24}, // shift -1
      {"ps_1_4\nmov_d4 r0, r1", 0xEu << 24}, // shift -2
      {"ps_1_4\nmov_d8 r0, r1", 0xDu << 24}, // shift -3
  };
  for (const Dst& d : dsts) {
    SCOPED_TRACE(d.text);
    auto r = assembly::parse_text(std::string(d.text) + "\n");
    ASSERT_TRUE(r.program.has_value()) << ir::render_text(r.diags, r.sources);
    std::vector<uint32_t> t = assembly::assemble(*r.program);
    // The destination follows the instruction token (dcl: after its usage token).
    const size_t at = std::string_view(d.text).find("dcl") != std::string_view::npos ? 3 : 2;
    ASSERT_GT(t.size(), at);
    EXPECT_EQ(t[at] & 0x0FF00000u, d.expect) << fmt::format("0x{:08X}", t[at]);
  }
}
