// The structural IR validator (ir::validate_ir, run before each backend) refuses no legal
// program: every listing of listings/ and of the shared corpus that loads and validates as
// the CLI loads it also passes validate_ir, against its own profile.
#include <filesystem>

#include <gtest/gtest.h>

#include "listing_files.h"
#include "skip_policy.h"
#include "tierlift/assembly/load.h"
#include "tierlift/ir/passes.h"
#include "tierlift/ir/result_diagnostics.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

// Listings of `dir` (and its subfolders) that load; each must pass validate_ir.
int check_folder(const fs::path& dir) {
  int loaded = 0;
  for (const fs::path& file : test::listings_in(dir, true)) {
    SCOPED_TRACE(file.string());
    ir::SourceManager sm;
    const uint32_t f = sm.add(file.string(), test::read_file(file));
    assembly::LoadOptions options;
    options.parse.include_dirs = {file.parent_path().string()};
    assembly::Loaded l = assembly::load_listing(f, sm, options);
    if (!l.program) continue; // helper fragments and deliberately broken files
    ++loaded;
    const ir::Status s = ir::validate_ir(*l.program);
    EXPECT_TRUE(s.ok()) << ir::render_text(s.diagnostics(), sm);
  }
  return loaded;
}

} // namespace

TEST(ValidateIrCorpus, OurListingsPass) {
  EXPECT_GE(check_folder(fs::path(TIERLIFT_SOURCE_DIR) / "listings"), 20);
}

TEST(ValidateIrCorpus, SharedCorpusPasses) {
  const fs::path dir = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::is_directory(dir))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus, dir.string() + " is absent");
  EXPECT_EQ(check_folder(dir), 16);
}
