// CodegenOptions::trace: the instrumented pixel module passes spirv-val for every pixel
// listing we have (and the hard forms: co-issue, ps_1_4 phases, texkill with either kill mode,
// texm pads), records exactly the instructions that store a register, and leaves the module
// untouched when unset (and in a vertex module).
#include <gtest/gtest.h>

#include <filesystem>

#include "compile_valid.h"
#include "listing_files.h"
#include "skip_policy.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/ir/semantics.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

using tierlift::test::compile_valid;
using tierlift::test::count_occurrences;
using tierlift::test::parse_program;

codegen::CodegenOptions traced(uint32_t x = 3, uint32_t y = 2) {
  codegen::CodegenOptions o;
  o.trace = codegen::TracePixel{x, y, codegen::kTraceBinding};
  return o;
}

// The instructions a traced module must record: those with a destination register that the
// program stores (every one but flow control, nop and the texm pads, which write no register).
std::vector<uint32_t> storing_instructions(const ir::Program& p) {
  std::vector<uint32_t> out;
  for (size_t i = 0; i < p.code.size(); ++i) {
    const ir::Instruction& ins = p.code[i];
    const ir::OpInfo& info = ir::op_info(ins.op);
    if (!ins.dst || info.cls == ir::OpClass::Flow || ins.op == ir::Opcode::TexKill ||
        ir::is_texm_pad(ins.op) || (ins.dst->mask & 0xF) == 0)
      continue;
    out.push_back(static_cast<uint32_t>(i));
  }
  return out;
}

void check_traced(const ir::Program& program, const ir::SourceManager& sources,
                  codegen::CodegenOptions options = traced()) {
  auto module = compile_valid(program, sources, options);
  ASSERT_TRUE(module);
  ASSERT_TRUE(module->trace);
  EXPECT_EQ(module->trace->binding, codegen::kTraceBinding);
  EXPECT_EQ(module->trace->entries, program.code.size());
  EXPECT_EQ(module->trace->points, storing_instructions(program));
  ir::Result<std::string> dis = codegen::disassemble(module->words);
  ASSERT_TRUE(dis) << dis.message();
  EXPECT_EQ(count_occurrences(*dis, "BuiltIn FragCoord"), 1u);
  EXPECT_EQ(count_occurrences(*dis, "Binding 18"), 1u);
  // As many guarded record blocks as recorded instructions.
  EXPECT_EQ(count_occurrences(*dis, "OpIAdd %uint"), module->trace->points.size());
  options.optimize = true; // spirv-opt keeps it valid too
  compile_valid(program, sources, options);
}

void check_listing(const fs::path& path) {
  SCOPED_TRACE(path.string());
  auto parsed = assembly::parse_text(tierlift::test::read_file(path), path.filename().string());
  ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  if (parsed.program->stage() != ir::ShaderStage::Pixel) return;
  check_traced(*parsed.program, parsed.sources);
}

TEST(CodegenTrace, EveryPixelListingOfTheRepositoryValidates) {
  size_t n = 0;
  for (const auto& f :
       tierlift::test::listings_in(fs::path(TIERLIFT_SOURCE_DIR) / "listings", true)) {
    check_listing(f);
    ++n;
  }
  EXPECT_GT(n, 10u);
}

TEST(CodegenTrace, SharedCorpusValidates) {
  const fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::exists(dir))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus,
                                  "no shared corpus at " + dir.string());
  for (const auto& f : tierlift::test::listings_in(dir)) check_listing(f);
}

TEST(CodegenTrace, HardFormsValidate) {
  const char* listings[] = {
      // ps_1_1 co-issue, texture registers, a texm3x2 pair.
      "ps_1_1\ntex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\nmul r0.rgb, t0, t2\n"
      "+add r0.a, t0, c0\n",
      // ps_1_4 phases.
      "ps_1_4\ntexcrd r0.rgb, t0\nmov r1, c0\nphase\ntexld r2, r0\nadd r0, r2, r1\n",
      // ps_2_0 texkill and an output written per component.
      "ps_2_0\ndcl t0\ndcl_2d s0\ntexkill t0\ntexld r0, t0, s0\nmov oC0.xy, r0\n"
      "mov oC0.zw, t0\n",
  };
  for (const char* text : listings) {
    SCOPED_TRACE(text);
    auto parsed = assembly::parse_text(text, "<test>");
    ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
    check_traced(*parsed.program, parsed.sources);
    codegen::CodegenOptions demote = traced();
    demote.kill = codegen::KillMode::Demote;
    check_traced(*parsed.program, parsed.sources, demote);
  }
}

TEST(CodegenTrace, UnsetLeavesTheModuleAsItWas) {
  const ir::Program ps = parse_program("ps_2_0\ndcl t0\nadd r0, t0, c0\nmov oC0, r0\n");
  ir::DiagnosticSink diags;
  auto plain = codegen::compile(ps, {}, diags);
  auto again = codegen::compile(ps, {}, diags);
  auto instrumented = codegen::compile(ps, traced(), diags);
  ASSERT_TRUE(plain && again && instrumented);
  EXPECT_EQ(plain->words, again->words);
  EXPECT_FALSE(plain->trace);
  EXPECT_NE(plain->words, instrumented->words);
  ir::Result<std::string> dis = codegen::disassemble(plain->words);
  ASSERT_TRUE(dis);
  EXPECT_EQ(dis->find("StorageBuffer"), std::string::npos);
  EXPECT_EQ(dis->find("FragCoord"), std::string::npos);
  // The instrumented module's interface is the plain one's: a device binds it alike.
  ASSERT_EQ(plain->interface.size(), instrumented->interface.size());
  for (size_t i = 0; i < plain->interface.size(); ++i)
    EXPECT_EQ(plain->interface[i].location, instrumented->interface[i].location);
}

TEST(CodegenTrace, AVertexModuleIgnoresIt) {
  const ir::Program vs =
      parse_program("vs_1_1\ndcl_position v0\nmov a0.x, v0.x\nmov oPos, c[a0.x + 1]\n");
  ir::DiagnosticSink diags;
  auto plain = codegen::compile(vs, {}, diags);
  auto with = codegen::compile(vs, traced(), diags);
  ASSERT_TRUE(plain && with);
  EXPECT_EQ(plain->words, with->words);
  EXPECT_FALSE(with->trace);
}

// The guard compares the truncated gl_FragCoord with the pixel asked for.
TEST(CodegenTrace, TheGuardNamesThePixel) {
  const ir::Program ps = parse_program("ps_2_0\ndef c0, 1, 2, 3, 4\nmov oC0, c0\n");
  auto module = compile_valid(ps, {}, traced(1234, 567));
  ASSERT_TRUE(module);
  ir::Result<std::string> dis = codegen::disassemble(module->words);
  ASSERT_TRUE(dis);
  EXPECT_NE(dis->find("OpConstant %uint 1234"), std::string::npos) << *dis;
  EXPECT_NE(dis->find("OpConstant %uint 567"), std::string::npos);
  EXPECT_NE(dis->find("OpConvertFToU"), std::string::npos);
}

} // namespace
