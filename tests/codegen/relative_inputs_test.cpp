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

namespace {

// o[aL + n] and o[a0.x + n] in vs_3_0 (NUMERICS.md F13): masked, saturated and predicated
// relative writes; o3, o4, o5 link to oT2, oT0, oD0 (a0.x = 5 names o5).
const char* kVsWrites = "vs_3_0\ndefi i0, 3, 3, 1, 0\ndef c0, 1, 2, 3, 4\ndef c1, 5, 0, 0, 0\n"
                        "dcl_position v0\ndcl_position o0\ndcl_texcoord2 o3\n"
                        "dcl_texcoord0 o4\ndcl_color0 o5\nmov o0, v0\nsetp_gt p0, c0, c1.y\n"
                        "loop aL, i0\nmov o[aL], c0\nmov_sat o[aL + 1].yw, c0\n"
                        "(p0.x) add o[aL].xz, c0, c0\nendloop\nmova a0.x, c1.x\n"
                        "mov o[a0.x], c0\n";
const char* kPsReads = "ps_3_0\ndcl_texcoord0 v0\ndcl_texcoord2 v1\ndcl_color0 v2\n"
                       "mov r1, v1\nadd r0, v0, r1\nadd oC0, r0, v2\n";

} // namespace

TEST(CodegenRelativeOutputs, ModulePassesSpirvVal) {
  auto parsed = assembly::parse_text(kVsWrites, "<test>");
  ASSERT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  EXPECT_TRUE(test::compile_valid(*parsed.program, parsed.sources));
}

// A vertex program that writes its outputs only relatively still feeds every pixel input
// its table reaches: no "the vertex shader never writes" warning, each output declared.
TEST(CodegenRelativeOutputs, PairCountsEveryOutputARelativeWriteMayReach) {
  const ir::Program vs = test::parse_program(kVsWrites), ps = test::parse_program(kPsReads);
  ir::DiagnosticSink diags;
  auto pair = codegen::compile_pair(vs, ps, {}, diags);
  ASSERT_TRUE(pair);
  EXPECT_TRUE(diags.all().empty()) << diags.all().front().message;
  std::set<std::pair<ir::RegFile, uint32_t>> outputs;
  for (const codegen::InterfaceVar& iv : pair->vs.interface)
    if (iv.kind == codegen::InterfaceKind::Output) outputs.insert({iv.file, iv.index});
  EXPECT_TRUE(outputs.count({ir::RegFile::TexCrdOut, 0}));
  EXPECT_TRUE(outputs.count({ir::RegFile::TexCrdOut, 2}));
  EXPECT_TRUE(outputs.count({ir::RegFile::AttrOut, 0}));
  for (const auto* m : {&pair->vs, &pair->ps}) EXPECT_TRUE(codegen::validate(m->words));
}
