// v[aL + n] in vs_3_0 and ps_3_0 (NUMERICS.md F13): the modules pass spirv-val, and a pair
// whose pixel program reads its inputs relatively keeps every vertex output those inputs
// link to. The values are checked on both devices in tests/vulkan/diff_sm3_test.cpp.
#include <gtest/gtest.h>

#include <set>

#include "compile_valid.h"

using namespace tierlift;

namespace {

const char* kPs = "ps_3_0\ndefi i0, 3, 0, 1, 0\ndef c0, 0, 0, 0, 0\ndcl_texcoord0 v0\n"
                  "dcl_color0 v1\ndcl_texcoord3 v2\nmov r0, c0\nloop aL, i0\n"
                  "add r0, r0, v0[aL]\nendloop\nmov oC0, r0\n";
const char* kVs = "vs_3_0\ndefi i0, 2, 1, 1, 0\ndef c0, 0, 0, 0, 0\ndcl_position v0\n"
                  "dcl_texcoord0 v1\ndcl_texcoord1 v2\ndcl_position o0\ndcl_texcoord0 o1\n"
                  "dcl_color0 o2\ndcl_texcoord3 o3\ndcl_texcoord5 o4\nmov o0, v0\nmov r0, c0\n"
                  "loop aL, i0\nadd r0, r0, v[aL]\nendloop\nmov o1, r0\nmov o2, r0\nmov o3, r0\n"
                  "mov o4, r0\n";

} // namespace

TEST(CodegenRelativeInputs, ModulesPassSpirvVal) {
  for (const char* text : {kPs, kVs}) {
    auto parsed = assembly::parse_text(text, "<test>");
    ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
    EXPECT_TRUE(test::compile_valid(*parsed.program, parsed.sources)) << text;
  }
}

TEST(CodegenRelativeInputs, PairKeepsEveryOutputARelativeReadMayReach) {
  const ir::Program vs = test::parse_program(kVs), ps = test::parse_program(kPs);
  ir::DiagnosticSink diags;
  auto pair = codegen::compile_pair(vs, ps, {}, diags);
  ASSERT_TRUE(pair);
  std::set<std::pair<ir::RegFile, uint32_t>> outputs;
  for (const codegen::InterfaceVar& iv : pair->vs.interface)
    if (iv.kind == codegen::InterfaceKind::Output) outputs.insert({iv.file, iv.index});
  // oT0, oD0 and oT3 feed v0..v2; oT5 (texcoord5) is read by nobody and pruned.
  EXPECT_TRUE(outputs.count({ir::RegFile::TexCrdOut, 0}));
  EXPECT_TRUE(outputs.count({ir::RegFile::AttrOut, 0}));
  EXPECT_TRUE(outputs.count({ir::RegFile::TexCrdOut, 3}));
  EXPECT_FALSE(outputs.count({ir::RegFile::TexCrdOut, 5}));
  for (const auto* m : {&pair->vs, &pair->ps}) EXPECT_TRUE(codegen::validate(m->words));
}
