// Every listing of the article and of the shared corpus compiles for its stage and the
// module passes spirv-val (in-process, Vulkan 1.1 rules).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "compile_valid.h"
#include "skip_policy.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"

#include "listing_files.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

using tierlift::test::read_file;

void compile_listing(const fs::path& path) {
  SCOPED_TRACE(path.string());
  auto parsed = assembly::parse_text(read_file(path), path.filename().string());
  ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  auto module = tierlift::test::compile_valid(*parsed.program, parsed.sources);
  ASSERT_TRUE(module);
  EXPECT_EQ(module->stage, parsed.program->stage());
  EXPECT_EQ(module->words[0], 0x07230203u);
  // The optimised module must validate as well.
  codegen::CodegenOptions opt;
  opt.optimize = true;
  ir::DiagnosticSink diags2;
  auto optimised = codegen::compile(*parsed.program, opt, diags2);
  ASSERT_TRUE(optimised) << ir::render_text(diags2, parsed.sources);
  EXPECT_LE(optimised->words.size(), module->words.size());
}

using tierlift::test::listings_in;

} // namespace

TEST(CodegenListings, GpuGemsListingsCompileAndValidate) {
  const auto files = listings_in(fs::path(TIERLIFT_SOURCE_DIR) / "listings/gpugems21");
  ASSERT_EQ(files.size(), 4u);
  for (const auto& f : files) compile_listing(f);
}

TEST(CodegenListings, SharedCorpusCompilesAndValidates) {
  const fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::exists(dir))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus,
                                  "no shared corpus at " + dir.string());
  const auto files = listings_in(dir);
  ASSERT_FALSE(files.empty());
  for (const auto& f : files) compile_listing(f);
}

TEST(CodegenListings, EveryCorpusVertexShaderPairsWithEveryPixelShader) {
  const fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::exists(dir))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus,
                                  "no shared corpus at " + dir.string());
  std::vector<ir::Program> vs, ps;
  auto files = listings_in(dir);
  for (const auto& f : listings_in(fs::path(TIERLIFT_SOURCE_DIR) / "listings/gpugems21"))
    files.push_back(f);
  for (const auto& f : files) {
    auto parsed = assembly::parse_text(read_file(f), f.filename().string());
    ASSERT_TRUE(parsed.program) << f;
    (parsed.program->stage() == ir::ShaderStage::Vertex ? vs : ps).push_back(*parsed.program);
  }
  ASSERT_FALSE(vs.empty());
  ASSERT_FALSE(ps.empty());
  for (size_t i = 0; i < vs.size(); ++i)
    for (size_t j = 0; j < ps.size(); ++j) {
      SCOPED_TRACE("vs " + std::to_string(i) + " with ps " + std::to_string(j));
      ir::DiagnosticSink diags;
      auto pair = codegen::compile_pair(vs[i], ps[j], {}, diags);
      ASSERT_TRUE(pair);
      // Every pixel input has a vertex output at the same location.
      std::set<uint32_t> outs;
      for (const auto& iv : pair->vs.interface)
        if (iv.kind == codegen::InterfaceKind::Output) outs.insert(iv.location);
      for (const auto& iv : pair->ps.interface) {
        if (iv.kind == codegen::InterfaceKind::Input) {
          EXPECT_TRUE(outs.count(iv.location)) << iv.name;
        }
      }
    }
}
