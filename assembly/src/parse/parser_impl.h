// The statement parser behind parse_program(): token stream → ir::Program. Split by job:
// parser.cpp (driver, version, recovery), parse_statements.cpp (instructions, dcl, def),
// parse_operands.cpp (registers, modifiers, swizzles, relative addressing).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tierlift/assembly/preprocessor.h"
#include "tierlift/ir/program.h"

namespace tierlift::assembly::detail {

// Register indices above this are refused while parsing (bytecode has 11 bits; the
// validator checks the real profile limits). Keeps offset sums far from overflow.
inline constexpr uint32_t kMaxRegisterIndex = 1u << 20;

// One operand as written, before the statement says whether it is a destination or a source.
struct Operand {
  ir::RegFile file = ir::RegFile::Temp;
  uint32_t index = 0;
  std::optional<ir::RelAddr> rel;
  bool neg = false;     // -r
  bool comp = false;    // 1-r
  bool bnot = false;    // !b
  std::string modifier; // "bx2" of r0_bx2, lower case
  ir::SourceLoc modifier_loc;
  std::optional<std::string_view> suffix; // letters after '.', as written
  ir::SourceLoc suffix_loc;
  ir::SourceLoc loc;
};

std::string lower(std::string_view s);

class Parser {
public:
  Parser(const TokenStream& ts, ir::DiagnosticSink& diags, uint32_t main_file, bool strict)
      : toks_(ts.tokens), diags_(diags), main_file_(main_file), strict_(strict),
        first_error_(diags.error_count()) {}
  // The program, or nullopt when any error was reported.
  std::optional<ir::Program> run();

private:
  // Token cursor. The stream always ends with End, and cur() never moves past it.
  const Token& cur() const { return toks_[pos_]; }
  const Token& peek(size_t k = 1) const {
    return toks_[pos_ + k < toks_.size() ? pos_ + k : toks_.size() - 1];
  }
  void advance() {
    if (pos_ + 1 < toks_.size()) ++pos_;
  }
  bool at_eol() const { return cur().kind == TokKind::Newline || cur().kind == TokKind::End; }
  bool at_punct(std::string_view p) const {
    return cur().kind == TokKind::Punct && cur().text == p;
  }
  void skip_line();
  bool fail(ir::SourceLoc loc, std::string rule, std::string message);
  std::string describe(const Token& t) const;
  ir::SourceLoc span_to_prev(ir::SourceLoc start) const;

  // parser.cpp
  bool version();
  bool statement();
  // "//!comment 0x..." and its "//!comment+" continuation lines (parse_comment_block.cpp).
  bool comment_block();

  // parse_statements.cpp
  bool instruction(const Token& mn, std::string_view base, std::string_view mods, bool coissue,
                   std::optional<ir::SrcOperand> pred = std::nullopt);
  // "(p0)", "(!p0.x)" before a predicated instruction.
  bool predicate(ir::SrcOperand& out);
  bool instr_mods(const Token& mn, std::string_view mods, ir::InstrMods& out);
  bool declaration(const Token& mn, std::string_view parts);
  bool definition(const Token& mn, ir::Opcode op);
  bool take_sign();
  bool float_value(uint32_t& raw);
  bool int_value(uint32_t& raw);
  bool bool_value(uint32_t& raw);
  bool expect_comma();
  // The comma before a def value: missing is taken with a warning unless strict_ (§12.8).
  bool def_comma(std::optional<ir::SourceLoc>& missing);

  // parse_operands.cpp
  bool operand(Operand& out);
  bool register_name(const Token& t, std::string_view name, Operand& out, bool& has_index);
  bool relative(Operand& out, bool has_index);
  bool to_dst(const Operand& in, ir::DstOperand& out);
  bool to_src(const Operand& in, ir::SrcOperand& out);

  const std::vector<Token>& toks_;
  ir::DiagnosticSink& diags_;
  uint32_t main_file_;
  bool strict_;
  size_t first_error_;
  size_t pos_ = 0;
  uint32_t seq_ = 0;
  bool continued_ = false; // the statement being parsed began on its predecessor's line
  ir::Program prog_;
};

} // namespace tierlift::assembly::detail
