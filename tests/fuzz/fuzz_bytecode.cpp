// Feeds arbitrary bytes to the bytecode reader: the file forms (raw DWORDs or a C array,
// read_token_file) and the same bytes taken directly as little-endian DWORDs. Any crash,
// hang or sanitizer report is a finding, and so is a broken invariant: a stream the reader
// accepts must assemble back to exactly its own words (comment blocks included), and through
// the printed text to the same words again.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/assembly/printer.h"
#include "tierlift/assembly/validator.h"

using namespace tierlift;

namespace {

bool has_identity_scalar_source(const ir::Program& program) {
  for (const ir::Instruction& ins : program.code) {
    const ir::OpInfo& info = ir::op_info(ins.op);
    for (size_t k = 0; k < ins.src.size() && k < info.num_src; ++k)
      if (info.src[k] == ir::OperandKind::Scalar && ins.src[k].swizzle == ir::kIdentitySwizzle)
        return true;
  }
  return false;
}

void check_stream(const std::vector<uint32_t>& tokens) {
  ir::DiagnosticSink diags;
  auto program = assembly::disassemble(tokens, diags);
  if (!program) {
    if (!diags.has_errors()) std::abort(); // a rejection always says why
    return;
  }
  (void)assembly::validate(*program, diags);
  (void)assembly::print_program(*program);
  // What the reader built, the writer must carry back to the same program.
  ir::DiagnosticSink d2;
  auto again = assembly::assemble(*program, d2);
  if (!again) return; // the writer says which statement it cannot carry
  if (*again != tokens) std::abort();
  ir::DiagnosticSink d3;
  auto back = assembly::disassemble(*again, d3);
  if (!back || !ir::same_ir(*program, *back)) std::abort();
  // disasm ∘ assemble through the text form is the identity too, except where the text has
  // no spelling for the stream: a scalar source (rcp, rsq, exp, log, pow ...) with the
  // identity swizzle prints bare, and a bare scalar source reads .x in text, while the
  // runtime read .w (the windows leniency rewrites it to .w, with a warning, at validation).
  if (has_identity_scalar_source(*program)) return;
  auto reparsed = assembly::parse_text(assembly::print_program(*program), "disasm.asm");
  if (!reparsed.program) std::abort();
  ir::DiagnosticSink d4;
  auto from_text = assembly::assemble(*reparsed.program, d4);
  if (!from_text || *from_text != tokens) std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  ir::DiagnosticSink diags;
  if (auto tokens = assembly::read_token_file(bytes, diags))
    check_stream(*tokens);
  else if (!diags.has_errors())
    std::abort();
  std::vector<uint32_t> raw(size / 4);
  if (!raw.empty()) std::memcpy(raw.data(), data, raw.size() * 4);
  check_stream(raw);
  return 0;
}
