// Direct3D 9 token streams, both directions, laid out as Microsoft's assembler does.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"

namespace tierlift::assembly {

// Version token, statements in listing order (dcl/def/instructions), end token. Fields
// that do not fit their bits are truncated to them; use the checked form below to hear
// about it.
std::vector<uint32_t> assemble(const ir::Program& program);
// The same tokens, but every statement the stream cannot carry so that disassemble() gives
// it back (register number above 2047, relative addressing the profile has no encoding
// for, an opcode or operand shape not of this profile, defb other than 0/1, ...) becomes a
// diagnostic at the statement's position ("bytecode" rule), and the result is nullopt.
std::optional<std::vector<uint32_t>> assemble(const ir::Program& program,
                                              ir::DiagnosticSink& diags);

// Token stream → IR. Malformed streams (bad version token, truncated instruction, unknown
// opcode or register type, missing end token) are diagnostics on `file` (position: the
// token index as column 0 is not a text position, so loc.line stays 0 and the message
// names the token offset), and the result is nullopt.
std::optional<ir::Program> disassemble(const std::vector<uint32_t>& tokens,
                                       ir::DiagnosticSink& diags, uint32_t file = 0);

// Reading the two file forms: raw little-endian DWORDs, or C source holding an array of
// DWORDs ("const DWORD g_ps[] = { 0xffff0200, 0x0000001f, ... };" as headers and tests keep
// them; comments, u/l suffixes and decimal numbers are fine; an array whose element type
// names BYTE/char/uint8_t holds bytes, packed little-endian; a bare list without braces is
// read whole). Decides by content: a file whose first DWORD is a version token, or that is a
// multiple of 4 bytes and holds bytes no text has (NUL, control characters), is raw; any
// other file is C text. Problems in the text are diagnostics at line:col of `file`.
std::optional<std::vector<uint32_t>> read_token_file(const std::string& bytes,
                                                     ir::DiagnosticSink& diags, uint32_t file = 0);
std::string tokens_to_bytes(const std::vector<uint32_t>& tokens); // little-endian

} // namespace tierlift::assembly
