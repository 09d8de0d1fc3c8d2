// Shared by the codegen tests: a program compiled to SPIR-V whose module must pass spirv-val.
#pragma once

#include <gtest/gtest.h>

#include <optional>

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

} // namespace tierlift::test
