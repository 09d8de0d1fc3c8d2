// Differential tests, vs_2_0 static flow control (docs/d3d9-rules.md §5.3): loop with aL-relative
// constant reads (start, step and count from defi and from the constant bank), rep (count 0
// too), if/else on defb and on bank booleans, call/ret/label, callnz with b# and !b#, and
// their legal nestings (if inside a loop, a call from a loop whose subroutine reads c[aL]),
// over random vertex inputs with special values, on the CPU device and lavapipe. vs_2_0 has
// no if_comp, break, break_comp or breakp (vs_2_x); the validator rejects them there.
#include "diff_harness.h"

namespace tierlift::vulkan::test {
namespace {

struct FlowCase {
  const char* name;
  // Runs after r0..r2, r4 = v1..v4 and r3 = r0; leaves its result in r3. Subroutines go in
  // `subs` (after the main program's ret).
  const char* body;
  const char* subs = "";
};

// clang-format off
const FlowCase kFlowCases[] = {
    {"loop_al_relative", "loop aL, i0\nadd r3, r3, c[aL]\nendloop"},
    {"loop_al_offset_step", "loop aL, i1\nmad r3, r3, c[aL + 1], r1\nendloop"},
    {"loop_bank_counts", "loop aL, i4\nadd r3, r3, c[aL + 2]\nmul r3, r3, c15\nendloop"},
    {"loop_zero_count", "mov r3, r1\nloop aL, i2\nadd r3, r3, c[aL]\nendloop"},
    {"loop_al_with_a0", "mova a0.x, r4.x\nloop aL, i0\nadd r3, r3, c[aL]\nadd r3, r3, c[a0.x + 4]\nendloop"},
    {"rep", "rep i3\nmad r3, r3, c14, r1\nendrep"},
    {"rep_zero", "mov r3, r2\nrep i2\nadd r3, r3, r1\nendrep"},
    {"rep_bank_count", "rep i5\nadd r3, r3, r1\nmul r3, r3, c15\nendrep"},
    {"if_true", "if b0\nadd r3, r0, r1\nelse\nmul r3, r0, r1\nendif"},
    {"if_false", "if b1\nadd r3, r0, r1\nelse\nmul r3, r0, r1\nendif"},
    {"if_bank", "if b4\nadd r3, r0, r1\nelse\nmul r3, r0, r1\nendif\nif b5\nsub r3, r3, r2\nendif"},
    {"if_nested", "if b0\nif b1\nmov r3, r1\nelse\nif b4\nmad r3, r0, r1, r2\nendif\nendif\nendif"},
    {"if_in_loop", "loop aL, i0\nif b0\nadd r3, r3, c[aL + 2]\nelse\nsub r3, r3, c[aL]\nendif\nendloop"},
    {"loop_in_if", "if b4\nloop aL, i1\nadd r3, r3, c[aL]\nendloop\nelse\nrep i3\nadd r3, r3, r1\nendrep\nendif"},
    {"call", "call l0\nadd r3, r3, r2", "label l0\nmul r3, r3, r1\nret\n"},
    {"call_twice", "call l1\ncall l1", "label l1\nmad r3, r3, r1, r2\nret\n"},
    {"callnz_true", "callnz l0, b0\ncallnz l2, b1", "label l0\nmul r3, r3, r1\nret\nlabel l2\nadd r3, r3, r2\nret\n"},
    {"callnz_not", "callnz l0, !b1\ncallnz l2, !b0", "label l0\nmul r3, r3, r1\nret\nlabel l2\nadd r3, r3, r2\nret\n"},
    {"callnz_bank", "callnz l0, b4\ncallnz l2, !b5", "label l0\nmul r3, r3, r1\nret\nlabel l2\nadd r3, r3, r2\nret\n"},
    {"call_in_loop_al", "loop aL, i0\ncall l3\nendloop", "label l3\nadd r3, r3, c[aL + 1]\nret\n"},
    {"call_in_rep_if", "rep i3\nif b0\ncall l0\nendif\nendrep", "label l0\nmad r3, r3, c14, r2\nret\n"},
    {"sub_with_loop", "call l1", "label l1\nloop aL, i1\nadd r3, r3, c[aL]\nendloop\nret\n"},
};
// clang-format on

std::string flow_text(const FlowCase& c) {
  std::string t = "vs_2_0\n"
                  "defi i0, 4, 0, 1, 0\n" // aL = 0, 1, 2, 3
                  "defi i1, 3, 2, 3, 0\n" // aL = 2, 5, 8
                  "defi i2, 0, 0, 0, 0\n" // count 0: the body never runs
                  "defi i3, 5, 0, 0, 0\n" // rep 5
                  "defb b0, true\n"
                  "defb b1, false\n"
                  "dcl_position v0\ndcl_texcoord0 v1\ndcl_texcoord1 v2\ndcl_texcoord2 v3\n"
                  "dcl_texcoord3 v4\n"
                  "mov oPos, v0\nmov r0, v1\nmov r1, v2\nmov r2, v3\nmov r4, v4\nmov r3, r0\n";
  t += std::string(c.body) + "\nmov oT0, r3\nret\n" + c.subs;
  return t;
}

const char* kPsFromT0 = "ps_2_0\ndcl t0\nmov oC0, t0\n";

FamilyMax g_flow("vs_2_0 flow control");

class FlowDiff : public VulkanTest, public ::testing::WithParamInterface<FlowCase> {};

TEST_P(FlowDiff, CpuAndVulkanAgree) {
  const FlowCase& c = GetParam();
  for (uint64_t seed : {1, 2}) {
    DiffSetup s;
    s.seed = seed;
    s.per_pixel_vertices = true;
    s.vertex_range = {-2, 2, 0.1f};
    s.vs_c = random_constants(seed * 100, 16, {-2, 2, 0.1f});
    // v4.x feeds mova: small offsets so c[a0.x + 4] stays mostly in range.
    DiffResult r = run_diff_with(*dev, flow_text(c), kPsFromT0, s, [&](cpu::Pass& p) {
      for (auto& v : p.vertices) v.v[4][0] = std::floor(v.v[4][0]);
      p.vs_constants.i[4] = {3, 1, 2, 0}; // aL = 1, 3, 5 (from the bank, not defi)
      p.vs_constants.i[5] = {static_cast<int32_t>(seed) + 1, 0, 0, 0};
      p.vs_constants.b[4] = seed == 1;
      p.vs_constants.b[5] = seed != 1;
    });
    expect_agree(r, fmt::format("{} seed {}", c.name, seed), g_flow);
    print_case_agreement(r, fmt::format("{} seed {}", c.name, seed));
  }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const FlowCase& c, std::ostream* os) {
  *os << c.name << ": " << one_line(c.body) << (*c.subs ? "; " : "") << one_line(c.subs);
}

INSTANTIATE_TEST_SUITE_P(Flow, FlowDiff, ::testing::ValuesIn(kFlowCases),
                         [](const auto& info) { return std::string(info.param.name); });

// Each case takes the path it was written for: the CPU device's result differs from the
// plain `mov r3, r0` (no flow taken) — a case whose branches were all skipped would prove
// nothing.
TEST(FlowDiffCoverage, EveryCaseChangesTheResult) {
  cpu::ConstantBank k;
  k.f = random_constants(100, 16, {-2, 2, 0});
  k.i[4] = {3, 1, 2, 0};
  k.i[5] = {2, 0, 0, 0};
  k.b[4] = true;
  cpu::VertexInput in;
  for (int r = 1; r <= 4; ++r) in.v[r] = {0.75f * r, -1.25f + r, 1.5f / r, 0.5f + r};
  for (const FlowCase& c : kFlowCases) {
    auto prog = parse_listing(flow_text(c), c.name);
    ASSERT_TRUE(prog) << c.name;
    ir::Result<cpu::ShaderVM> made = cpu::ShaderVM::create(*prog, {});
    ASSERT_TRUE(made) << c.name << ": " << made.message();
    const cpu::ShaderVM& vm = *made;
    cpu::VertexOutput o = vm.run_vertex(in, k);
    const bool zero_count = std::string(c.name).find("zero") != std::string::npos;
    const cpu::Vec4 unchanged = zero_count ? in.v[2 + (c.name[0] == 'r')] : in.v[1];
    EXPECT_EQ(o.tex[0] == unchanged, zero_count) << c.name;
  }
}

} // namespace
} // namespace tierlift::vulkan::test
