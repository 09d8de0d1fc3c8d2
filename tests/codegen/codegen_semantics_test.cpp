// What the emitted SPIR-V must (and must not) contain for the numeric rules, the resource
// and interface mapping of docs/spirv-mapping.md, and bad input turned into diagnostics.
#include <gtest/gtest.h>

#include <bit>
#include <regex>
#include <set>
#include <string>
#include <string_view>

#include "tierlift/assembly/parser.h"
#include "tierlift/codegen/codegen.h"
#include "tierlift/vulkan/uniforms.h"

using namespace tierlift;

namespace {

std::optional<codegen::ShaderModule> build(const std::string& text,
                                           const codegen::CodegenOptions& opt = {}) {
  auto parsed = assembly::parse_text(text, "<test>");
  EXPECT_TRUE(parsed.program) << ir::render_text(parsed.diags, parsed.sources);
  if (!parsed.program) return std::nullopt;
  ir::DiagnosticSink diags;
  auto m = codegen::compile(*parsed.program, opt, diags);
  EXPECT_TRUE(m) << ir::render_text(diags, parsed.sources);
  return m;
}

std::string dis(const codegen::ShaderModule& m) {
  ir::Result<std::string> text = codegen::disassemble(m.words);
  EXPECT_TRUE(text) << text.message();
  return text ? *text : std::string();
}

// The disassembly of `text` built with `opt`; empty (failures recorded) when it was refused.
std::string disassembly(const std::string& text, const codegen::CodegenOptions& opt = {}) {
  auto m = build(text, opt);
  return m ? dis(*m) : std::string();
}

// Result ids of every instruction with the given opcode name, e.g. "OpFMul".
std::set<std::string> results_of(const std::string& text, const std::string& op) {
  std::set<std::string> ids;
  const std::regex re("(%\\w+) = " + op + " ");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    ids.insert((*it)[1]);
  return ids;
}

// Every one of `parts` occurs in the disassembly `text` (contains) or none does (lacks).
void expect_contains(const std::string& text, std::initializer_list<std::string_view> parts) {
  for (std::string_view part : parts) EXPECT_NE(text.find(part), std::string::npos) << part;
}
void expect_lacks(const std::string& text, std::initializer_list<std::string_view> parts) {
  for (std::string_view part : parts) EXPECT_EQ(text.find(part), std::string::npos) << part;
}

const char* kMadPs20 = "ps_2_0\ndcl t0\ndcl t1\nmad r0, t0, t1, c0\nmov oC0, r0\n";

} // namespace

TEST(CodegenSemantics, EveryFloatAddAndMulIsNoContraction) {
  const std::string text = disassembly(kMadPs20);
  ASSERT_FALSE(text.empty());
  int checked = 0;
  for (const char* op : {"OpFMul", "OpFAdd", "OpFSub", "OpFDiv"})
    for (const std::string& id : results_of(text, op)) {
      EXPECT_NE(text.find("OpDecorate " + id + " NoContraction"), std::string::npos) << id;
      ++checked;
    }
  // The unfused mad: one vec4 product and one vec4 sum, both present and both decorated.
  EXPECT_EQ(results_of(text, "OpFMul").size(), 1u);
  EXPECT_EQ(results_of(text, "OpFAdd").size(), 1u);
  EXPECT_GE(checked, 2);
  EXPECT_EQ(text.find("Fma"), std::string::npos);
}

TEST(CodegenSemantics, MadMultiplyHonoursZeroTimesAnything) {
  const std::string text = disassembly(kMadPs20);
  ASSERT_FALSE(text.empty());
  // legacy_mul: both factors compared with 0 (ordered), or'ed, then a select.
  EXPECT_GE(results_of(text, "OpFOrdEqual").size(), 2u);
  EXPECT_FALSE(results_of(text, "OpLogicalOr").empty());
  EXPECT_FALSE(results_of(text, "OpSelect").empty());
}

TEST(CodegenSemantics, MinMaxUseOrderedSelectsNotFMinFMax) {
  const std::string text =
      disassembly("vs_2_0\ndcl_position v0\ndcl_normal v1\nmin r0, v0, v1\nmax r1, v0, v1\n"
                  "add oPos, r0, r1\n");
  ASSERT_FALSE(text.empty());
  expect_lacks(text, {"FMin", "FMax", "NMin"});
  EXPECT_FALSE(results_of(text, "OpFOrdLessThan").empty());
  EXPECT_FALSE(results_of(text, "OpFOrdGreaterThanEqual").empty());
  EXPECT_EQ(text.find("OpFUnord"), std::string::npos);
}

TEST(CodegenSemantics, NoDotFractOrFmaAnywhere) {
  // dp4, frc and nrm must be explicit sums / x − floor(x) (NUMERICS.md 15, 22).
  const std::string text =
      disassembly("vs_2_0\ndcl_position v0\ndp4 r0.x, v0, c0\nfrc r1, v0\nnrm r2, v0\n"
                  "m4x4 r3, v0, c4\nadd r0, r0.x, r1\nadd r0, r0, r2\nadd oPos, r0, r3\n");
  ASSERT_FALSE(text.empty());
  expect_lacks(text, {"OpDot", "Fract", "Fma"});
  EXPECT_NE(text.find("Floor"), std::string::npos);
}

TEST(CodegenSemantics, TexkillIsOpKillOrDemote) {
  const char* ps = "ps_2_0\ndcl t0\ntexkill t0\nmov oC0, t0\n";
  auto kill = build(ps);
  ASSERT_TRUE(kill);
  EXPECT_NE(dis(*kill).find("OpKill"), std::string::npos);
  EXPECT_TRUE(kill->uses_kill);
  codegen::CodegenOptions opt;
  opt.kill = codegen::KillMode::Demote;
  auto demote = build(ps, opt);
  ASSERT_TRUE(demote);
  const std::string text = dis(*demote);
  expect_contains(text, {"OpDemoteToHelperInvocation", "SPV_EXT_demote_to_helper_invocation"});
  EXPECT_EQ(text.find("OpKill"), std::string::npos);
}

TEST(CodegenSemantics, PositionFixUpIsSpecializable) {
  codegen::CodegenOptions opt;
  opt.pixel_offset_x = 0.25f; // 1/width of a 4-pixel-wide target
  const std::string text = disassembly("vs_1_1\ndcl_position v0\nmov oPos, v0\n", opt);
  ASSERT_FALSE(text.empty());
  expect_contains(text,
                  {"OpDecorate %flip_y SpecId 0", "OpDecorate %pixel_offset_x SpecId 1",
                   "OpDecorate %pixel_offset_y SpecId 2", "%flip_y = OpSpecConstant %float -1",
                   "%pixel_offset_x = OpSpecConstant %float 0.25", "BuiltIn Position"});
}

TEST(CodegenSemantics, Ps1xMaxValueIsASpecConstantWithTheConventionDefault) {
  codegen::CodegenOptions opt;
  opt.conventions.ps1x_max_value = 8.0f;
  const std::string text = disassembly("ps_1_4\ntexld r0, t0\nmul_x4 r0, r0, c0\n", opt);
  ASSERT_FALSE(text.empty());
  expect_contains(
      text, {"OpDecorate %ps1x_max_value SpecId 3", "%ps1x_max_value = OpSpecConstant %float 8"});
}

TEST(CodegenSemantics, FixedPointEmulationValidates) {
  codegen::CodegenOptions opt;
  opt.conventions.ps1x_fixed_bits = 8;
  auto m = build("ps_1_1\ntex t0\nmul r0, t0, v0\n", opt);
  ASSERT_TRUE(m);
  EXPECT_FALSE(results_of(dis(*m), "OpIsNan").empty());
}

TEST(CodegenSemantics, CoissuedHalvesReadBeforeEitherWrites) {
  const std::string text =
      disassembly("ps_1_1\ntex t0\nmov r0, t0\nmul r0.rgb, r0, v0\n+add r0.a, r0, v1\n");
  ASSERT_FALSE(text.empty());
  const size_t fn = text.find("%d3d_main = OpFunction");
  ASSERT_NE(fn, std::string::npos);
  // After `mov r0, t0` (first store to r0), both halves load r0 before the next store.
  const size_t first_store = text.find("OpStore %r0", fn);
  const size_t second_store = text.find("OpStore %r0", first_store + 1);
  ASSERT_NE(second_store, std::string::npos);
  int loads = 0;
  for (size_t p = text.find("OpLoad %v4float %r0", first_store); p < second_store;
       p = text.find("OpLoad %v4float %r0", p + 1))
    ++loads;
  EXPECT_EQ(loads, 2 + 1); // mul's r0, add's r0, then the first store's masked merge
}

TEST(CodegenSemantics, ResourceBindingsAndInterfaceOfListing2Style) {
  auto m = build("ps_2_0\ndcl t0\ndcl t3\ndcl v1\ndcl_2d s0\ndcl_cube s2\ndef c1, 1, 2, 3, 4\n"
                 "texld r0, t0, s0\ntexld r1, t3, s2\nmad r0, r0, c2, r1\nmul r0, r0, c1\n"
                 "mul r0, r0, v1\nmov oC0, r0\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->uniforms.binding, codegen::kPixelConstantsBinding);
  EXPECT_EQ(m->uniforms.float_count, 3u); // c2 is read from the block, c1 is a def
  EXPECT_EQ(m->uniforms.float_used, (std::vector<uint32_t>{2}));
  ASSERT_EQ(m->samplers.size(), 2u);
  EXPECT_EQ(m->samplers[0].binding, 2u);
  EXPECT_EQ(m->samplers[1].binding, 4u);
  EXPECT_EQ(m->samplers[1].type, ir::SamplerType::Cube);
  std::set<std::pair<uint32_t, std::string>> locs;
  for (const auto& iv : m->interface)
    if (iv.kind != codegen::InterfaceKind::BuiltIn)
      locs.insert(
          {iv.location, (iv.kind == codegen::InterfaceKind::Input ? "in " : "out ") + iv.name});
  const std::set<std::pair<uint32_t, std::string>> want{
      {0, "in t0"}, {3, "in t3"}, {9, "in v1"}, {0, "out oC0"}};
  EXPECT_EQ(locs, want);
  EXPECT_NE(dis(*m).find("%_ptr_UniformConstant_"), std::string::npos);
}

TEST(CodegenSemantics, RelativeAddressingSizesTheBlockToTheWholeRange) {
  auto m = build("vs_1_1\ndcl_position v0\nmov a0.x, v0.x\nmov oPos, c[a0.x + 3]\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->uniforms.float_count, 256u);
  EXPECT_EQ(m->uniforms.size_bytes, 256u * 16u);
}

TEST(CodegenSemantics, Vs20IntAndBoolMembersFollowTheFloats) {
  auto m = build("vs_2_0\ndcl_position v0\nmov r0, c3\nif b2\nadd r0, r0, v0\nendif\n"
                 "rep i1\nadd r0, r0, c1\nendrep\nmov oPos, r0\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->uniforms.float_count, 4u);
  EXPECT_EQ(m->uniforms.int_offset, 64u);
  EXPECT_EQ(m->uniforms.bool_offset, 64u + 256u);
  const std::string text = dis(*m);
  expect_contains(text, {"OpLoopMerge", "OpSelectionMerge"});
}

// The block layout is described once (codegen::uniform_block_layout): std140 with 16-byte
// elements, by hand. vs_2_0 with 3 float slots: i[16] at 48, b[16] at 48 + 256 = 304, size
// 304 + 256 = 560. ps_1_x with 1 slot: bumpenv at 16, two slots per stage, so stage 3's
// matrix at 16 + 3·32 = 112, its lscale at 128, loffset at 132; size 16 + 16·16 = 272.
// The module declares the offsets the layout gives (the device packs by the same struct).
TEST(CodegenSemantics, UniformLayoutByHand) {
  const codegen::UniformBlockInfo v = codegen::uniform_block_layout(3, true, false);
  EXPECT_EQ(v.int_offset, 48u);
  EXPECT_EQ(v.bool_offset, 304u);
  EXPECT_EQ(v.bump_offset, 0u);
  EXPECT_EQ(v.size_bytes, 560u);
  EXPECT_EQ(v.int_at(2, 3), 48u + 32u + 12u);
  EXPECT_EQ(v.bool_at(5), 304u + 80u);
  EXPECT_EQ(codegen::UniformBlockInfo::float_at(7, 2), 7u * 16u + 8u);
  const codegen::UniformBlockInfo p = codegen::uniform_block_layout(1, false, true);
  EXPECT_EQ(p.int_offset, 0u);
  EXPECT_EQ(p.bump_offset, 16u);
  EXPECT_EQ(p.size_bytes, 272u);
  EXPECT_EQ(p.bump_matrix_at(3, 1), 116u);
  EXPECT_EQ(p.bump_lscale_at(3), 128u);
  EXPECT_EQ(p.bump_loffset_at(3), 132u);

  auto m = build("ps_1_1\ntex t0\ntexbem t1, t0\nmov r0, t1\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->uniforms.bump_offset, 16u);
  EXPECT_EQ(m->uniforms.size_bytes, 272u);
  expect_contains(dis(*m), {"OpMemberDecorate %PsConstants 1 Offset 16"});
}

TEST(CodegenSemantics, SubroutinesBecomeFunctions) {
  const std::string text =
      disassembly("vs_2_0\ndcl_position v0\ndefb b0, true\nmov r0, v0\ncall l1\n"
                  "callnz l2, !b0\nmov oPos, r0\nret\nlabel l1\nadd r0, r0, c0\nret\n"
                  "label l2\nmul r0, r0, c1\nret\n");
  ASSERT_FALSE(text.empty());
  expect_contains(text, {"%l1 = OpFunction", "%l2 = OpFunction"});
  EXPECT_EQ(results_of(text, "OpFunctionCall").size(), 3u); // main → d3d_main, l1, l2
}

TEST(CodegenSemantics, ValidatorRejectsBrokenWords) {
  const std::vector<uint32_t> garbage{0x07230203, 0x00010300, 0, 10, 0, 0x00050000 | 1234};
  const ir::Status valid = codegen::validate(garbage);
  EXPECT_FALSE(valid);
  EXPECT_FALSE(valid.message().empty());
  const ir::Result<std::string> dis = codegen::disassemble({1, 2, 3});
  EXPECT_FALSE(dis);
  EXPECT_FALSE(dis.message().empty());
}

// validate() remembers the modules it passed: a module one word away from one it passed
// is still validated (and refused), not taken for it.
TEST(CodegenSemantics, ValidatorRemembersOnlyTheModulesItPassed) {
  const std::optional<codegen::ShaderModule> m = build("ps_2_0\nmov oC0, c0\n");
  ASSERT_TRUE(m);
  EXPECT_TRUE(codegen::validate(m->words));
  EXPECT_TRUE(codegen::validate(m->words)); // again: the same answer
  std::vector<uint32_t> broken = m->words;
  broken[3] = 1; // the id bound below every id the module uses
  EXPECT_FALSE(codegen::validate(broken));
  EXPECT_FALSE(codegen::validate(broken)); // a refusal is not remembered as a pass
}

// validate() checks a module without spirv-val's friendly names and a refused one again with
// them: the message of a refusal names its ids as spirv-dis does (%void, not a bare number).
TEST(CodegenSemantics, ValidatorMessagesKeepFriendlyNames) {
  const std::optional<codegen::ShaderModule> m = build("ps_2_0\nmov oC0, c0\n");
  ASSERT_TRUE(m);
  // The void type's id (OpTypeVoid: opcode 19, two words) becomes the result type of the
  // module's first OpLoad (opcode 61, four words: type, result, pointer).
  uint32_t void_id = 0;
  std::vector<uint32_t> broken = m->words;
  for (size_t i = 5; i < broken.size(); i += broken[i] >> 16) {
    const uint32_t op = broken[i] & 0xffffu;
    if (op == 19) void_id = broken[i + 1];
    if (op == 61 && void_id) {
      broken[i + 1] = void_id;
      break;
    }
    ASSERT_GT(broken[i] >> 16, 0u);
  }
  ASSERT_NE(void_id, 0u);
  const ir::Status valid = codegen::validate(broken);
  ASSERT_FALSE(valid);
  EXPECT_NE(valid.message().find(std::to_string(void_id) + "[%void]"), std::string::npos)
      << valid.message();
}

TEST(CodegenSemantics, BrokenFlowIsADiagnosticNotACrash) {
  ir::Program p;
  p.profile = ir::Profile::vs_2_0;
  ir::Instruction if_ins;
  if_ins.op = ir::Opcode::If;
  ir::SrcOperand b0;
  b0.file = ir::RegFile::ConstBool;
  if_ins.src.push_back(b0);
  p.code.push_back(if_ins);
  ir::DiagnosticSink diags;
  EXPECT_FALSE(codegen::compile(p, {}, diags));
  EXPECT_TRUE(diags.has_errors());

  ir::Program q;
  q.profile = ir::Profile::vs_2_0;
  ir::Instruction endloop;
  endloop.op = ir::Opcode::EndLoop;
  q.code.push_back(endloop);
  ir::Instruction call;
  call.op = ir::Opcode::Call;
  ir::SrcOperand l3;
  l3.file = ir::RegFile::Label;
  l3.index = 3;
  call.src.push_back(l3);
  ir::DiagnosticSink d2;
  EXPECT_FALSE(codegen::compile(q, {}, d2));
  EXPECT_TRUE(d2.has_errors());

  ir::Program r; // an arithmetic instruction missing its operands
  r.profile = ir::Profile::ps_2_0;
  ir::Instruction mad;
  mad.op = ir::Opcode::Mad;
  r.code.push_back(mad);
  ir::DiagnosticSink d3;
  EXPECT_FALSE(codegen::compile(r, {}, d3));
  EXPECT_TRUE(d3.has_errors());
}

TEST(CodegenSemantics, NestedFlowWithEarlyReturnValidates) {
  // ret inside if and inside a loop, a subroutine using aL called from a loop, nested ifs.
  auto m = build("vs_2_0\ndcl_position v0\ndefi i0, 4, 1, 2, 0\ndefb b1, false\n"
                 "mov r0, v0\nloop aL, i0\nif b0\nif b1\nadd r0, r0, c[aL]\nelse\n"
                 "call l3\nendif\nendif\nrep i2\nif b1\nret\nendif\nmul r0, r0, c1\nendrep\n"
                 "endloop\nif b0\nmov oPos, r0\nret\nendif\nmov oPos, -r0\nret\n"
                 "label l3\nadd r0, r0, c[aL + 7]\nret\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->uniforms.float_count, 256u); // relative addressing reaches the whole range
  const std::string text = dis(*m);
  EXPECT_EQ(results_of(text, "OpFunctionCall").size(), 2u);
}

TEST(CodegenSemantics, MalformedInstructionsNeverCrash) {
  // Every opcode, in every profile, with no operands at all, then with operands of the
  // wrong register files: the result is a diagnostic or a module that validates.
  for (const ir::OpInfo& info : ir::opcode_table()) {
    for (ir::Profile p : ir::kAllProfiles) {
      for (int variant = 0; variant < 2; ++variant) {
        ir::Program prog;
        prog.profile = p;
        ir::Instruction ins;
        ins.op = info.op;
        if (variant == 1) {
          ir::DstOperand d;
          d.file = ir::RegFile::Sampler;
          d.index = 70000;
          ins.dst = d;
          for (int i = 0; i < 4; ++i) {
            ir::SrcOperand s;
            s.file = i % 2 ? ir::RegFile::Label : ir::RegFile::Const;
            s.index = 0xFFFFFFF0u;
            ins.src.push_back(s);
          }
        }
        prog.code.push_back(ins);
        ir::DiagnosticSink diags;
        auto m = codegen::compile(prog, {}, diags);
        SCOPED_TRACE(std::string(info.mnemonic) + " " + std::string(ir::profile_name(p)));
        if (m) {
          const ir::Status valid = codegen::validate(m->words);
          EXPECT_TRUE(valid) << valid.message();
        } else {
          EXPECT_TRUE(diags.has_errors());
        }
      }
    }
  }
}

TEST(CodegenSemantics, PackUniformsFollowsTheStd140Layout) {
  auto vs = build("vs_2_0\ndcl_position v0\nmov r0, c1\nif b3\nadd r0, r0, v0\nendif\n"
                  "rep i2\nadd r0, r0, c0\nendrep\nmov oPos, r0\n");
  ASSERT_TRUE(vs);
  pass::ConstantBank v;
  v.f = {{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 9, 9, 9}};
  v.i[2] = {3, 0, 1, 0};
  v.b[3] = true;
  const auto words = vulkan::pack_uniforms(*vs, v, pass::Pass{});
  // float_count 2 (c0, c1): 32 bytes of floats, then i[16] (256 bytes), then b[16].
  ASSERT_EQ(words.size(), (32u + 256u + 256u) / 4u);
  EXPECT_EQ(std::bit_cast<float>(words[5]), 6.0f); // c1.y at byte 20
  EXPECT_EQ(words[(32 + 2 * 16) / 4], 3u);         // i2.x
  EXPECT_EQ(words[(32 + 256 + 3 * 16) / 4], 1u);   // b3
  EXPECT_EQ(words[(32 + 256 + 2 * 16) / 4], 0u);   // b2
  auto ps = build("ps_1_3\ntex t0\ntexbem t1, t0\nmov r0, t1\n");
  ASSERT_TRUE(ps);
  pass::Pass stages;
  stages.textures[1].stage.bumpenv_mat = {0.5f, 0.25f, -0.25f, 0.5f};
  stages.textures[1].stage.bumpenv_lscale = 2.0f;
  stages.textures[1].stage.bumpenv_loffset = 0.125f;
  const auto pw = vulkan::pack_uniforms(*ps, pass::ConstantBank{}, stages);
  const uint32_t base = ps->uniforms.bump_offset / 4;
  ASSERT_GT(base, 0u);
  EXPECT_EQ(std::bit_cast<float>(pw[base + 8 + 2]), -0.25f);  // stage 1 M10
  EXPECT_EQ(std::bit_cast<float>(pw[base + 12 + 1]), 0.125f); // stage 1 LOFFSET
}
