// Every listing of the shared corpus and of listings/ that parses and validates must also
// prepare (ShaderVM::create succeeds) and run once on neutral inputs without crashing.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "skip_policy.h"
#include "vm_test_util.h"

using namespace vmtest;
namespace fs = std::filesystem;

namespace {
void run_folder(const fs::path& dir, int& ran) {
  for (const auto& e : fs::directory_iterator(dir)) {
    auto ext = e.path().extension().string();
    if (ext != ".vsh" && ext != ".psh") continue;
    std::ifstream f(e.path());
    std::stringstream ss;
    ss << f.rdbuf();
    auto r = tierlift::assembly::parse_text(ss.str(), e.path().string());
    if (!r.program) continue; // the parser's own tests judge these
    tierlift::ir::DiagnosticSink d;
    if (!tierlift::assembly::validate(*r.program, d)) continue;
    SCOPED_TRACE(e.path().string());
    ShaderVM vm = vm_of(*r.program, {});
    ConstantBank c;
    c.f.assign(256, Vec4{0.5f, 0.5f, 0.5f, 0.5f});
    if (r.program->stage() == tierlift::ir::ShaderStage::Vertex) {
      vm.run_vertex({}, c);
    } else {
      EchoTextures tex;
      vm.run_pixel({}, c, tex);
    }
    ++ran;
  }
}
} // namespace

TEST(VmCorpus, EveryValidListingRuns) {
  int ran = 0;
  run_folder(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / "gpugems21", ran);
  EXPECT_GE(ran, 4);
  fs::path shared = fs::path(TIERLIFT_SHARED_DIR) / "corpus";
  if (!fs::exists(shared))
    TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireCorpus,
                                  "no shared corpus at " + shared.string());
  run_folder(shared, ran);
  std::printf("listings run: %d\n", ran);
}
