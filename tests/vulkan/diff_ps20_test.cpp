// Differential tests, ps_2_0: every arithmetic instruction legal in ps_2_0, and its
// modifiers, over random texture inputs with special values, on the CPU device and lavapipe.
#include <set>
#include <sstream>

#include "diff_harness.h"
#include "tierlift/ir/opcodes.h"

namespace tierlift::vulkan::test {
namespace {

struct OpCase {
  const char* name;
  const char* body; // reads r0, r1, r2 (s0, s1, s2 at this pixel), c0..c7; writes r3
};

// clang-format off
const OpCase kPs20Cases[] = {
    {"abs", "abs r3, r0"},
    {"add", "add r3, r0, r1"},
    {"cmp", "cmp r3, r0, r1, r2"},
    {"crs", "mov r3, c0\ncrs r3.xyz, r0, r1"},
    {"dp2add", "dp2add r3, r0, r1, r2.x"},
    {"dp3", "dp3 r3, r0, r1"},
    {"dp4", "dp4 r3, r0, r1"},
    {"exp", "exp r3, r0.x"},
    {"frc", "frc r3, r0"},
    {"log", "log r3, r0.y"},
    {"lrp", "lrp r3, r0, r1, r2"},
    {"m3x2", "mov r3, c0\nm3x2 r3.xy, r0, c1"},
    {"m3x3", "mov r3, c0\nm3x3 r3.xyz, r0, c1"},
    {"m3x4", "m3x4 r3, r0, c1"},
    {"m4x3", "mov r3, c0\nm4x3 r3.xyz, r0, c1"},
    {"m4x4", "m4x4 r3, r0, c1"},
    {"mad", "mad r3, r0, r1, r2"},
    {"max", "max r3, r0, r1"},
    {"min", "min r3, r0, r1"},
    {"mov", "mov r3, r0"},
    {"mul", "mul r3, r0, r1"},
    {"nop", "mov r3, r1\nnop"},
    {"nrm", "mov r3, c0\nnrm r3.xyz, r0"},
    {"pow", "pow r3, r0.x, r1.y"},
    {"rcp", "rcp r3, r0.x"},
    {"rsq", "rsq r3, r0.z"},
    {"sincos", "mov r3, c0\nsincos r3.xy, r4.x, c8, c9"},
    {"sub", "sub r3, r0, r1"},
    // Modifiers of ps_2_0: _sat, source negation, swizzles, write masks.
    {"add_sat", "add_sat r3, -r0, r1"},
    {"mad_sat_neg", "mad_sat r3, r0, -r1, r2"},
    {"mul_swizzle", "mul r3, r0.wzyx, -r1.yzxw"},
    {"mov_mask", "mov r3, c2\nmov r3.xz, -r0"},
    {"rcp_neg_w", "rcp r3, -r0.w"},
    {"dp3_sat", "dp3_sat r3, r0, c3"},
    {"constants", "mad r3, c4, c5, r0"},
    // Denormals through def (c11) and through the constant bank (c6 = ±1e-40, ±2^-140).
    {"def_denormals", "rcp r3.x, c11.y\nrsq r3.y, c11.x\nlog r3.z, c11.w\nmad r3.w, r0.w, c11.x, c11.y"},
    {"const_denormals", "rcp r3.x, c6.y\nrsq r3.y, c6.x\nlog r3.z, c6.w\ncmp r3.w, c6.y, r0.w, r1.w"},
    {"def_denormals_select", "cmp r3, c11, r0, r1\nmin r3, r3, c11\nmax r3, r3, -c11"},
};
// clang-format on

std::string ps_text(const std::string& body) {
  return "ps_2_0\n"
         "def c8, -1.5500992e-006, -2.1701389e-005, 0.0026041667, 0.00026041668\n"
         "def c9, -0.020833334, -0.12500000, 1.0, 0.50000000\n"
         "def c10, 3.14159265, 0.5, 0, 0\n"
         "def c11, 1e-40, -1e-40, 7.1746481e-43, -7.1746481e-43\n"
         "dcl t0\ndcl_2d s0\ndcl_2d s1\ndcl_2d s2\ndcl_2d s3\n"
         "texld r0, t0, s0\ntexld r1, t0, s1\ntexld r2, t0, s2\ntexld r4, t0, s3\n" +
         body + "\nmov oC0, r3\n";
}

const char* kQuadVs = "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n";

FamilyMax g_ps20("ps_2_0 arithmetic");

class Ps20Diff : public VulkanTest, public ::testing::WithParamInterface<OpCase> {};

TEST_P(Ps20Diff, CpuAndVulkanAgree) {
  const OpCase& c = GetParam();
  for (uint64_t seed : {1, 2}) {
    DiffSetup s;
    s.seed = seed;
    add_random_textures(s, 3, {});
    // s3 feeds sincos, whose input must lie in [−π, π] (docs/d3d9-rules.md §5.1).
    s.textures.push_back(random_texture(seed * 10 + 3, {-3.14159f, 3.14159f, 0.0f}));
    s.ps_c = random_constants(seed * 100, 8, {-2, 2, 0.2f});
    s.ps_c[6] = {1e-40f, -1e-40f, 0x1p-140f, -0x1p-140f};
    DiffResult r = run_diff(*dev, kQuadVs, ps_text(c.body), s);
    expect_agree(r, fmt::format("{} seed {}", c.name, seed), g_ps20);
  }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const OpCase& c, std::ostream* os) {
  *os << c.name << ": " << one_line(c.body);
}

INSTANTIATE_TEST_SUITE_P(Ops, Ps20Diff, ::testing::ValuesIn(kPs20Cases),
                         [](const auto& info) { return std::string(info.param.name); });

// Every arithmetic row of the opcode table legal in ps_2_0 has a case above.
TEST(Ps20DiffCoverage, EveryArithmeticOpcodeHasACase) {
  std::set<std::string> covered;
  for (const OpCase& c : kPs20Cases) add_mnemonics(covered, c.body, " _");
  for (const ir::OpInfo& row : ir::opcode_table())
    if (row.cls == ir::OpClass::Arith && ir::legal_in(row, ir::Profile::ps_2_0)) {
      EXPECT_TRUE(covered.count(std::string(row.mnemonic))) << row.mnemonic;
    }
}

} // namespace
} // namespace tierlift::vulkan::test
