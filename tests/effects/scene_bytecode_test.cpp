// A scene's "listings" may name a token stream as well as text (assembly::load_listing decides by
// content), and "ps1x_max" picks the ps_1_x range preset of tier dx8.
#include <gtest/gtest.h>

#include <cfloat>
#include <filesystem>
#include <fstream>

#include "listing_files.h"
#include "tierlift/assembly/bytecode.h"
#include "tierlift/assembly/parser.h"
#include "tierlift/effects/glow/builtin_listing.h"
#include "tierlift/effects/scenes/scene.h"

namespace tierlift::effects {
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir() {
  auto dir = fs::temp_directory_path() / ("tierlift_scene_bc_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

TEST(SceneBytecode, ListingFileMayBeATokenStream) {
  const std::string name = "gpugems21/listing4_blur4_weighted_sum.psh";
  auto text = test::read_file(fs::path(TIERLIFT_SOURCE_DIR) / "listings" / name);
  auto parsed = assembly::parse_text(text);
  ASSERT_TRUE(parsed.program.has_value());
  auto pso = scratch_dir() / "l4.pso";
  std::ofstream(pso, std::ios::binary)
      << assembly::tokens_to_bytes(assembly::assemble(*parsed.program));
  ListingResult from_tokens = glow_listing(name, {{name, pso.string()}});
  ASSERT_TRUE(from_tokens) << from_tokens.message();
  ListingResult built_in = builtin_listing(name);
  ASSERT_TRUE(built_in) << built_in.message();
  EXPECT_TRUE(ir::same_ir(**from_tokens, **built_in))
      << ir::ir_difference(**from_tokens, **built_in);
  // And through a scene file that names it.
  auto scene = scratch_dir() / "s.json";
  std::ofstream(scene) << R"({"glow": {"tier": "dx8", "listings": {")" << name
                       << R"(": "l4.pso"}}})";
  ir::Result<Scene> s = load_scene_file(scene.string());
  ASSERT_TRUE(s) << s.message();
  PlanResult plan_built = build_glow(s->params);
  ASSERT_TRUE(plan_built) << plan_built.message();
}

TEST(SceneBytecode, Ps1xMaxPresets) {
  auto load = [](const std::string& value) {
    return parse_scene(R"({"glow": {"tier": "dx8", "ps1x_max": )" + value + "}}", "s.json", "");
  };
  ir::Result<Scene> d = parse_scene(R"({"glow": {"tier": "dx8"}})", "s.json", "");
  ASSERT_TRUE(d) << d.message();
  EXPECT_EQ(d->params.ps1x_max, FLT_MAX); // the d3d9 preset
  ir::Result<Scene> g = load(R"("geforce3")");
  ASSERT_TRUE(g) << g.message();
  EXPECT_EQ(g->params.ps1x_max, 1.0f);
  ir::Result<Scene> r = load(R"("radeon8500")");
  ASSERT_TRUE(r) << r.message();
  EXPECT_EQ(r->params.ps1x_max, 8.0f);
  ir::Result<Scene> n = load("4");
  ASSERT_TRUE(n) << n.message();
  EXPECT_EQ(n->params.ps1x_max, 4.0f);
  PlanResult plan_built = build_glow(r->params);
  ASSERT_TRUE(plan_built) << plan_built.message();
  EffectPlan& plan = *plan_built;
  EXPECT_EQ(plan.graph.conventions.ps1x_max_value, 8.0f);
  ir::Result<Scene> bad = load("0.5");
  EXPECT_FALSE(bad);
  EXPECT_NE(bad.message().find("/glow/ps1x_max"), std::string::npos) << bad.message();
}

} // namespace
} // namespace tierlift::effects
