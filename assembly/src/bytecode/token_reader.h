// The token-stream reader behind disassemble(). It walks the stream once, never reads past
// the end of the vector (every read goes through next()), and stops at the first problem:
// after a malformed token the operand boundaries of the rest are unknown, so further
// messages would be noise.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"

namespace tierlift::assembly::bc {

class TokenReader {
public:
  TokenReader(const std::vector<uint32_t>& tokens, ir::DiagnosticSink& diags, uint32_t file)
      : t_(tokens), diags_(diags), file_(file) {}
  std::optional<ir::Program> run();

private:
  // --- stream walk (disassemble.cpp)
  bool version();
  bool statement();
  bool instruction(const ir::OpInfo& info, uint32_t tok);
  bool declaration();
  bool definition(const ir::OpInfo& info);
  const ir::OpInfo* lookup(uint32_t tok);

  // --- operands (decode_operands.cpp)
  bool dst(uint32_t tok, size_t at, ir::DstOperand& out, ir::InstrMods& mods);
  bool src(uint32_t tok, size_t at, ir::SrcOperand& out);
  bool relative(ir::SrcOperand& out);
  bool param_common(uint32_t tok, size_t at, const char* what, ir::RegFile& file, uint32_t& index);

  // Next token of the current instruction, or a "truncated" diagnostic.
  bool next(uint32_t& tok, size_t& at);
  // "token 12 (0x0200001F): message" with rule "bytecode"; always returns false.
  bool fail(size_t at, const std::string& message);
  // The byte offset of token `index` ("shader.bin:+0x1c: error: ..."); loc() is that of the
  // current instruction token.
  ir::SourceLoc loc_at(size_t index) const { return ir::SourceLoc::at_byte(file_, 4 * index); }
  ir::SourceLoc loc() const { return loc_at(instr_at_); }

  const std::vector<uint32_t>& t_;
  ir::DiagnosticSink& diags_;
  uint32_t file_;
  ir::Program p_;
  size_t pos_ = 0;
  size_t limit_ = 0;    // operands of the current instruction end here
  size_t instr_at_ = 0; // index of the current instruction token
  bool sized_ = false;  // limit_ comes from the SM2 length field (not the stream end)
  uint32_t seq_ = 0;
};

} // namespace tierlift::assembly::bc
