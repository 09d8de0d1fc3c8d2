// Feeds arbitrary bytes to the front end. Any crash, hang, sanitizer report or broken
// invariant (a valid program that does not survive print → parse or assemble → disasm)
// is a finding.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"
#include "tierlift/assembly/validator.h"

using namespace tierlift;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  auto parsed = assembly::parse_text(text, "fuzz.asm");
  if (!parsed.program) return 0;
  bool valid = assembly::validate(*parsed.program, parsed.diags);
  // Printing must always give text that parses back to the same program.
  auto reparsed = assembly::parse_text(assembly::print_program(*parsed.program), "printed.asm");
  if (!reparsed.program || !ir::same_ir(*parsed.program, *reparsed.program)) std::abort();
  if (!valid) return 0;
  // A valid program must survive the token stream both ways.
  std::vector<uint32_t> tokens = assembly::assemble(*parsed.program);
  ir::DiagnosticSink diags;
  auto back = assembly::disassemble(tokens, diags);
  if (!back || !ir::same_ir(*parsed.program, *back)) std::abort();
  // Arbitrary bytes as a token stream must never crash the reader.
  ir::DiagnosticSink d2;
  if (auto t = assembly::read_token_file(text, d2)) (void)assembly::disassemble(*t, d2);
  return 0;
}
