// Direct3D 9 token streams, both directions, laid out as Microsoft's assembler does.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"

namespace tierlift::as {

// Version token, statements in listing order (dcl/def/instructions), end token.
std::vector<uint32_t> assemble(const ir::Program& program);

// Token stream → IR. Malformed streams (bad version token, truncated instruction, unknown
// opcode or register type, missing end token) are diagnostics on `file` (position: the
// token index as column 0 is not a text position, so loc.line stays 0 and the message
// names the token offset), and the result is nullopt.
std::optional<ir::Program> disassemble(const std::vector<uint32_t>& tokens,
                                       ir::DiagnosticSink& diags, uint32_t file = 0);

// Reading the two file forms: raw little-endian DWORDs, or C source holding an array of
// hex DWORDs ("0xffff0200, 0x0000001f, ..." as headers and tests keep them). Decides by
// content: a file that is not a multiple of 4 bytes or that holds "0x" text is parsed as C.
std::optional<std::vector<uint32_t>> read_token_file(const std::string& bytes,
                                                     ir::DiagnosticSink& diags,
                                                     uint32_t file = 0);
std::string tokens_to_bytes(const std::vector<uint32_t>& tokens);  // little-endian

}  // namespace tierlift::as
