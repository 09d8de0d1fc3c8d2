// Shared by the codegen tests: a program compiled to SPIR-V whose module must pass spirv-val,
// a listing parsed for a test, and a count of what a disassembly holds.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/ir/diagnostic.h"

namespace tierlift::test {

// `program` compiled with `options`; a refusal (its diagnostics rendered against `sources`)
// or a module that spirv-val rejects fails the test. Nothing when the compiler refused it.
inline std::optional<codegen::ShaderModule>
compile_valid(const ir::Program& program, const ir::SourceManager& sources,
              const codegen::CodegenOptions& options = {}) {
  ir::DiagnosticSink diags;
  std::optional<codegen::ShaderModule> module = codegen::compile(program, options, diags);
  EXPECT_TRUE(module) << ir::render_text(diags, sources);
  if (module) {
    const ir::Status valid = codegen::validate(module->words);
    EXPECT_TRUE(valid) << valid.message();
  }
  return module;
}

// `text` parsed (not validated); a parse error fails the test and gives an empty program.
inline ir::Program parse_program(const std::string& text) {
  auto parsed = assembly::parse_text(text, "<test>");
  EXPECT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  return parsed.program ? *parsed.program : ir::Program{};
}

// How often `what` occurs in `text` (overlaps counted).
inline size_t count_occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

} // namespace tierlift::test
