// Every row of the opcode table parses, in a profile where it is legal, from a statement
// built out of the row's own operand kinds: the table and the parser must agree.
#include <fmt/format.h>

#include "test_util.h"
#include "tierlift/ir/opcodes.h"

namespace tierlift::assembly::test {
namespace {

using ir::OperandKind;
using ir::RegFile;

struct Spelling {
  const char* text;
  RegFile file;
};

Spelling spelling(OperandKind k) {
  switch (k) {
  case OperandKind::Scalar: return {"r1.x", RegFile::Temp};
  case OperandKind::Matrix: return {"c0", RegFile::Const};
  case OperandKind::Sampler: return {"s0", RegFile::Sampler};
  case OperandKind::Bool: return {"b0", RegFile::ConstBool};
  case OperandKind::Int: return {"i0", RegFile::ConstInt};
  case OperandKind::Label: return {"l0", RegFile::Label};
  case OperandKind::LoopReg: return {"aL", RegFile::Loop};
  case OperandKind::Const: return {"c1", RegFile::Const};
  case OperandKind::Temp: return {"r2", RegFile::Temp};
  default: return {"r1", RegFile::Temp};
  }
}

std::optional<ir::Profile> first_legal_profile(const ir::OpInfo& row) {
  for (ir::Profile p : ir::kAllProfiles)
    if (ir::legal_in(row, p)) return p;
  return std::nullopt;
}

TEST(ParserOpcodeRows, EveryInstructionRowParsesWithItsShape) {
  int checked = 0;
  for (const ir::OpInfo& row : ir::opcode_table()) {
    if (row.cls == ir::OpClass::Decl) continue; // dcl/def have their own syntax, below
    auto profile = first_legal_profile(row);
    ASSERT_TRUE(profile) << row.mnemonic << " is legal nowhere";
    std::string stmt(row.mnemonic);
    std::vector<std::string> ops;
    if (row.has_dst) ops.push_back(ir::is_ps11_13(*profile) ? "t1" : "r0");
    for (int i = 0; i < row.num_src; ++i) ops.push_back(spelling(row.src[i]).text);
    for (size_t i = 0; i < ops.size(); ++i) stmt += (i ? ", " : " ") + ops[i];
    std::string text = fmt::format("{}\n{}\n", ir::profile_name(*profile), stmt);
    SCOPED_TRACE(text);
    ir::Program p = must_parse(text);
    ASSERT_EQ(p.code.size(), 1u);
    const ir::Instruction& ins = p.code[0];
    EXPECT_EQ(ins.op, row.op);
    EXPECT_EQ(ins.dst.has_value(), row.has_dst);
    ASSERT_EQ(ins.src.size(), row.num_src);
    for (int i = 0; i < row.num_src; ++i) EXPECT_EQ(ins.src[i].file, spelling(row.src[i]).file);
    ++checked;
  }
  EXPECT_EQ(checked, ir::kOpcodeCount - 4); // every row but dcl, def, defi, defb
}

TEST(ParserOpcodeRows, DeclarationAndDefinitionRows) {
  ir::Program v = must_parse(
      "vs_2_0\ndcl_position v0\ndef c0, 1, 2, 3, 4\ndefi i0, 1, 2, 3, 0\ndefb b0, true\n");
  ASSERT_EQ(v.decls.size(), 1u);
  ASSERT_EQ(v.defs.size(), 3u);
  EXPECT_EQ(v.defs[0].file, RegFile::Const);
  EXPECT_EQ(v.defs[0].raw[3], 0x40800000u); // 4.0f
  EXPECT_EQ(v.defs[1].file, RegFile::ConstInt);
  EXPECT_EQ(v.defs[2].file, RegFile::ConstBool);
  EXPECT_TRUE(v.code.empty());
}

TEST(ParserOpcodeRows, WrongOperandCountIsReportedAtTheMnemonicOrTheExtraOperand) {
  expect_first_errors({
      {.text = "vs_1_1\nadd r0, r1\n",
       .rule = "operand-count",
       .line = 2,
       .col = 1,
       .message_has = "3 operands"},
      {.text = "vs_1_1\nmov r0, r1, r2\n", .rule = "operand-count", .line = 2, .col = 13},
      {.text = "ps_1_4\nphase r0\n", .rule = "operand-count", .col = 7},
  });
}

} // namespace
} // namespace tierlift::assembly::test
