// Link-time pruning: Listing 1 (writes oT0..oT7) against Listing 4 (reads t0..t3) leaves out
// oT4..oT7, the instructions writing them, the constants c4..c7 only they read, and the
// unread inputs; against Listing 2 (reads t0..t7) no output is removed. The SPIR-V itself
// is inspected: its Output variables and their Location decorations.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"

namespace fs = std::filesystem;
using namespace tierlift;

namespace {

ir::Program load(const std::string& name) {
  const fs::path p = fs::path(TIERLIFT_SOURCE_DIR) / "listings/gpugems21" / name;
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  auto parsed = assembly::parse_text(ss.str(), name);
  EXPECT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  return parsed.program ? *parsed.program : ir::Program{};
}

// Locations of the module's Output (or Input) variables, read from the words themselves:
// OpVariable (59) with storage class Output (3) / Input (1) and OpDecorate (71) Location (30).
std::set<uint32_t> locations(const std::vector<uint32_t>& words, uint32_t storage_class) {
  std::set<uint32_t> vars;
  std::map<uint32_t, uint32_t> location_of;
  for (size_t i = 5; i < words.size();) {
    const uint32_t op = words[i] & 0xFFFF, count = words[i] >> 16;
    if (count == 0) break;
    if (op == 59 && words[i + 3] == storage_class) vars.insert(words[i + 2]);
    if (op == 71 && words[i + 2] == 30) location_of[words[i + 1]] = words[i + 3];
    i += count;
  }
  std::set<uint32_t> out;
  for (uint32_t v : vars)
    if (location_of.count(v)) out.insert(location_of[v]);
  return out;
}

// Listings vs_name and ps_name of listings/gpugems21 compiled as one pipeline.
std::optional<codegen::CompiledPair> link(const std::string& vs_name, const std::string& ps_name,
                                          ir::DiagnosticSink& diags) {
  return codegen::compile_pair(load(vs_name), load(ps_name), {}, diags);
}

int dead_instructions(const codegen::CompiledPair& pair) {
  int dead = 0;
  for (const auto& p : pair.pruned) dead += p.kind == codegen::PrunedItem::Kind::DeadInstruction;
  return dead;
}

bool pruned(const codegen::CompiledPair& pair, codegen::PrunedItem::Kind kind,
            const std::string& what) {
  for (const auto& p : pair.pruned)
    if (p.kind == kind && p.what == what) return true;
  return false;
}

} // namespace

TEST(CodegenPruning, Listing1AgainstListing4DropsOT4ToOT7) {
  ir::DiagnosticSink diags;
  auto pair = link("listing1_blur8_coords.vsh", "listing4_blur4_weighted_sum.psh", diags);
  ASSERT_TRUE(pair);
  EXPECT_EQ(locations(pair->vs.words, 3), (std::set<uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(locations(pair->ps.words, 1), (std::set<uint32_t>{0, 1, 2, 3}));
  using K = codegen::PrunedItem::Kind;
  for (int n = 4; n < 8; ++n) {
    EXPECT_TRUE(pruned(*pair, K::VertexOutput, "oT" + std::to_string(n))) << n;
    EXPECT_TRUE(pruned(*pair, K::Constant, "c" + std::to_string(n))) << n;
  }
  for (int n = 0; n < 4; ++n)
    EXPECT_FALSE(pruned(*pair, K::VertexOutput, "oT" + std::to_string(n)));
  EXPECT_EQ(dead_instructions(*pair), 4); // add oT4..oT7
  // Listing 1 declares v1 (normal) and v2 (color) and never reads them.
  EXPECT_TRUE(pruned(*pair, K::VertexInput, "v1"));
  EXPECT_TRUE(pruned(*pair, K::VertexInput, "v2"));
  EXPECT_FALSE(pruned(*pair, K::VertexInput, "v3"));
  EXPECT_EQ(locations(pair->vs.words, 1), (std::set<uint32_t>{0, 3}));
  // The vertex inputs carry their D3D usage so a device can bind streams by it.
  for (const auto& iv : pair->vs.interface) {
    if (iv.kind != codegen::InterfaceKind::Input) continue;
    ASSERT_TRUE(iv.usage.has_value()) << iv.name;
    EXPECT_EQ(*iv.usage, iv.index == 0 ? ir::DeclUsage::Position : ir::DeclUsage::TexCoord);
  }
  // Only c0..c3 remain in the vertex constant block.
  EXPECT_EQ(pair->vs.uniforms.float_count, 4u);
  const ir::Status valid = codegen::validate(pair->vs.words);
  EXPECT_TRUE(valid) << valid.message();
  const ir::Status valid_ps = codegen::validate(pair->ps.words);
  EXPECT_TRUE(valid_ps) << valid_ps.message();
}

TEST(CodegenPruning, Listing1AgainstListing2RemovesNothing) {
  ir::DiagnosticSink diags;
  auto pair = link("listing1_blur8_coords.vsh", "listing2_blur8_weighted_sum.psh", diags);
  ASSERT_TRUE(pair);
  EXPECT_EQ(locations(pair->vs.words, 3), (std::set<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  for (const auto& p : pair->pruned) {
    EXPECT_NE(p.kind, codegen::PrunedItem::Kind::VertexOutput) << p.what;
    EXPECT_NE(p.kind, codegen::PrunedItem::Kind::DeadInstruction) << p.what;
    EXPECT_NE(p.kind, codegen::PrunedItem::Kind::Constant) << p.what;
  }
  EXPECT_EQ(pair->vs.uniforms.float_count, 8u);
  EXPECT_EQ(diags.warning_count(), 0u);
}

TEST(CodegenPruning, MissingVertexOutputIsDeclaredAndWarned) {
  // Listing 3 writes oT0..oT3; Listing 2 reads t0..t7: t4..t7 must still exist on the
  // vertex side (reading zero) so the pipeline interface matches, with a warning.
  ir::DiagnosticSink diags;
  auto pair = link("listing3_blur4_coords.vsh", "listing2_blur8_weighted_sum.psh", diags);
  ASSERT_TRUE(pair);
  EXPECT_EQ(locations(pair->vs.words, 3), (std::set<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(diags.warning_count(), 4u);
}

TEST(CodegenPruning, StageMismatchIsAnError) {
  const ir::Program vs = load("listing1_blur8_coords.vsh");
  ir::DiagnosticSink diags;
  EXPECT_FALSE(codegen::compile_pair(vs, vs, {}, diags));
  EXPECT_TRUE(diags.has_errors());
}

namespace {
std::optional<ir::Program> parse(const std::string& text) {
  auto parsed = assembly::parse_text(text, "<test>");
  EXPECT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  return parsed.program;
}
} // namespace

TEST(CodegenPruning, DeadPixelSampleDropsItsInterpolant) {
  // r1 = sample(t1) never reaches oC0: the texld is dead, so t1 is not read and the vertex
  // shader's oT1 (and the instruction and constant feeding it) go too.
  auto vs = parse("vs_1_1\ndcl_position v0\ndcl_texcoord v1\nmov oPos, v0\nmov oT0, v1\n"
                  "add oT1, v1, c9\n");
  auto ps = parse("ps_2_0\ndcl t0\ndcl t1\ndcl_2d s0\ntexld r0, t0, s0\ntexld r1, t1, s0\n"
                  "mov oC0, r0\n");
  ASSERT_TRUE(vs && ps);
  ir::DiagnosticSink diags;
  auto pair = codegen::compile_pair(*vs, *ps, {}, diags);
  ASSERT_TRUE(pair);
  using K = codegen::PrunedItem::Kind;
  EXPECT_TRUE(pruned(*pair, K::VertexOutput, "oT1"));
  EXPECT_TRUE(pruned(*pair, K::Constant, "c9"));
  EXPECT_TRUE(pruned(*pair, K::PixelInput, "t1"));
  EXPECT_TRUE(pruned(*pair, K::DeadInstruction, "texld r1"));
  EXPECT_EQ(locations(pair->vs.words, 3), (std::set<uint32_t>{0}));
  EXPECT_EQ(locations(pair->ps.words, 1), (std::set<uint32_t>{0}));
  EXPECT_EQ(pair->vs.uniforms.size_bytes, 0u); // no constant left: no block at all
}

TEST(CodegenPruning, PartialWritesKeepEarlierComponents) {
  // r0.x is overwritten, r0.y is not: the first mov stays; the write to r1 is dead.
  auto vs = parse("vs_1_1\ndcl_position v0\nmov r0, v0\nmov r1, c2\nmov r0.x, c1\n"
                  "mov oPos, r0\n");
  auto ps = parse("ps_1_1\nmov r0, v0\n");
  ASSERT_TRUE(vs && ps);
  ir::DiagnosticSink diags;
  auto pair = codegen::compile_pair(*vs, *ps, {}, diags);
  ASSERT_TRUE(pair);
  using K = codegen::PrunedItem::Kind;
  EXPECT_EQ(dead_instructions(*pair), 1);
  EXPECT_TRUE(pruned(*pair, K::DeadInstruction, "mov r1"));
  EXPECT_TRUE(pruned(*pair, K::Constant, "c2"));
  // The pixel shader reads v0, so the vertex side declares oD0 at location 8.
  EXPECT_EQ(locations(pair->vs.words, 3), (std::set<uint32_t>{8}));
}

TEST(CodegenPruning, ExplainNamesEveryItem) {
  ir::DiagnosticSink diags;
  auto pair = link("listing1_blur8_coords.vsh", "listing4_blur4_weighted_sum.psh", diags);
  ASSERT_TRUE(pair);
  const std::string text = codegen::explain(pair->pruned);
  EXPECT_NE(text.find("vertex: removed output oT7: the pixel shader never reads t7"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("vertex: removed instruction add oT4"), std::string::npos) << text;
  EXPECT_EQ(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')), pair->pruned.size());
}
