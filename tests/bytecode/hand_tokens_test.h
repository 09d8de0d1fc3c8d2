// Shared check for the hand-derived token tests: the IR assembles to exactly the tokens
// worked out by hand, and those tokens disassemble to the same IR.
#pragma once

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/ir/program.h"

namespace tierlift::test {

inline std::string hex(const std::vector<uint32_t>& t) {
  std::string s;
  for (uint32_t v : t) s += fmt::format("0x{:08X} ", v);
  return s;
}

inline void expect_tokens(const ir::Program& p, const std::vector<uint32_t>& expected) {
  ir::DiagnosticSink diags;
  auto checked = assembly::assemble(p, diags);
  ASSERT_TRUE(checked.has_value()) << (diags.all().empty() ? "" : diags.all()[0].message);
  EXPECT_EQ(hex(*checked), hex(expected));
  EXPECT_EQ(assembly::assemble(p), expected);
  auto back = assembly::disassemble(expected, diags);
  ASSERT_TRUE(back.has_value()) << (diags.all().empty() ? "" : diags.all()[0].message);
  EXPECT_TRUE(ir::same_ir(p, *back)) << ir::ir_difference(p, *back);
}

} // namespace tierlift::test
