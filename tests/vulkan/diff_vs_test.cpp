// Differential tests, vertex shaders: every arithmetic instruction legal in vs_2_0 (and the
// vs_1_1 subset in vs_1_1), over random vertex inputs with special values, written to oT0
// (or oD0, saturated) and passed through a pixel shader, on the CPU device and lavapipe.
#include <set>
#include <sstream>

#include "diff_harness.h"
#include "tierlift/ir/opcodes.h"

namespace tierlift::vulkan::test {
namespace {

struct VsCase {
  const char* name;
  const char* body; // reads r0, r1, r2, r4 (v1..v4), c0..c15; writes r3
  bool vs11 = true; // also run as vs_1_1 (only opcodes legal there)
  bool vs20 = true; // run as vs_2_0
};

// clang-format off
const VsCase kVsCases[] = {
    {"abs", "abs r3, r0", false},
    {"add", "add r3, r0, r1"},
    {"crs", "mov r3, c0\ncrs r3.xyz, r0, r1", false},
    {"dp3", "dp3 r3, r0, r1"},
    {"dp4", "dp4 r3, r0, r1"},
    {"dst", "dst r3, r0, r1"},
    {"exp", "exp r3, r0.x"},
    {"expp", "expp r3, r0.y"},
    {"frc", "mov r3, c0\nfrc r3.xy, r0"},
    {"lit", "lit r3, r0"},
    {"log", "log r3, r0.z"},
    {"logp", "logp r3, r0.w"},
    {"lrp", "lrp r3, r0, r1, r2", false},
    {"m3x2", "mov r3, c0\nm3x2 r3.xy, r0, c1"},
    {"m3x3", "mov r3, c0\nm3x3 r3.xyz, r0, c1"},
    {"m3x4", "m3x4 r3, r0, c1"},
    {"m4x3", "mov r3, c0\nm4x3 r3.xyz, r0, c1"},
    {"m4x4", "m4x4 r3, r0, c1"},
    {"mad", "mad r3, r0, r1, r2"},
    {"max", "max r3, r0, r1"},
    {"min", "min r3, r0, r1"},
    {"mov", "mov r3, r0"},
    {"mova", "mova a0.x, r4.x\nmov r3, c[a0.x + 2]", false},
    {"mov_a0", "mov a0.x, r4.y\nmov r3, c[a0.x + 3]", true, false},
    {"mul", "mul r3, r0, r1"},
    {"nop", "mov r3, r1\nnop"},
    {"nrm", "mov r3, c0\nnrm r3.xyz, r0", false},
    {"pow", "pow r3, r0.x, r1.y", false},
    {"rcp", "rcp r3, r0.x"},
    {"rsq", "rsq r3, r0.y"},
    {"sge", "sge r3, r0, r1"},
    {"sgn", "sgn r3, r0, r5, r6", false},
    {"sincos", "mov r3, c0\nsincos r3.xy, r4.w, c20, c21", false},
    {"slt", "slt r3, r0, r1"},
    {"sub", "sub r3, r0, r1"},
    {"neg_swizzle", "mad r3, -r0.wzyx, r1.xxyy, -r2"},
    {"mask", "mov r3, c4\nadd r3.yw, r0, -r1"},
};
// clang-format on

std::string vs_text(const VsCase& c, bool vs11, const char* out) {
  std::string t = vs11 ? "vs_1_1\n" : "vs_2_0\n";
  t += "def c20, -1.5500992e-006, -2.1701389e-005, 0.0026041667, 0.00026041668\n"
       "def c21, -0.020833334, -0.12500000, 1.0, 0.50000000\n"
       "dcl_position v0\ndcl_texcoord0 v1\ndcl_texcoord1 v2\ndcl_texcoord2 v3\n"
       "dcl_texcoord3 v4\n"
       "mov oPos, v0\nmov r0, v1\nmov r1, v2\nmov r2, v3\nmov r4, v4\n";
  return t + c.body + "\nmov " + out + ", r3\n";
}

const char* kPsFromT0 = "ps_2_0\ndcl t0\nmov oC0, t0\n";
const char* kPsFromV0 = "ps_2_0\ndcl v0\nmov oC0, v0\n";

FamilyMax g_vs20("vs_2_0 arithmetic"), g_vs11("vs_1_1 arithmetic"), g_vsd0("vs oD0 output");

DiffSetup vs_setup(uint64_t seed) {
  DiffSetup s;
  s.seed = seed;
  s.per_pixel_vertices = true;
  s.vertex_range = {-4, 4, 0.25f};
  s.vs_c = random_constants(seed * 100, 16, {-2, 2, 0.2f});
  // v4.x feeds mova/sincos: addresses and angles in range ([−π, π]); v4.y mov a0 (floor).
  return s;
}

class VsDiff : public VulkanTest, public ::testing::WithParamInterface<VsCase> {};

TEST_P(VsDiff, CpuAndVulkanAgree) {
  const VsCase& c = GetParam();
  for (uint64_t seed : {1, 2}) {
    DiffSetup s = vs_setup(seed);
    if (std::string(c.name) == "sincos") s.vertex_range = {-3.14159f, 3.14159f, 0};
    DiffResult r;
    if (c.vs20) {
      r = run_diff(*dev, vs_text(c, false, "oT0"), kPsFromT0, s);
      expect_agree(r, fmt::format("vs_2_0 {} seed {}", c.name, seed), g_vs20);
    }
    if (c.vs11) {
      r = run_diff(*dev, vs_text(c, true, "oT0"), kPsFromT0, s);
      expect_agree(r, fmt::format("vs_1_1 {} seed {}", c.name, seed), g_vs11);
    }
    // Through oD0: saturated per vertex, then read as v0 (saturated again) by the pixel shader.
    r = run_diff(*dev, vs_text(c, !c.vs20, "oD0"), kPsFromV0, s);
    expect_agree(r, fmt::format("{} via oD0 seed {}", c.name, seed), g_vsd0);
  }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const VsCase& c, std::ostream* os) {
  *os << c.name << (c.vs11 ? " vs_1_1" : "") << (c.vs20 ? " vs_2_0" : "") << ": "
      << one_line(c.body);
}

INSTANTIATE_TEST_SUITE_P(Ops, VsDiff, ::testing::ValuesIn(kVsCases),
                         [](const auto& info) { return std::string(info.param.name); });

// Every arithmetic row legal in vs_2_0 has a case (and every vs_1_1 row a vs_1_1 run).
TEST(VsDiffCoverage, EveryArithmeticOpcodeHasACase) {
  std::set<std::string> covered20, covered11;
  for (const VsCase& c : kVsCases) {
    std::istringstream in(c.body);
    std::string line;
    while (std::getline(in, line)) {
      std::string m = line.substr(0, line.find_first_of(" _"));
      if (c.vs20) covered20.insert(m);
      if (c.vs11) covered11.insert(m);
    }
  }
  for (const ir::OpInfo& row : ir::opcode_table()) {
    if (row.cls != ir::OpClass::Arith) continue;
    if (ir::legal_in(row, ir::Profile::vs_2_0)) {
      EXPECT_TRUE(covered20.count(std::string(row.mnemonic))) << row.mnemonic;
    }
    if (ir::legal_in(row, ir::Profile::vs_1_1)) {
      EXPECT_TRUE(covered11.count(std::string(row.mnemonic))) << "vs_1_1 " << row.mnemonic;
    }
  }
}

} // namespace
} // namespace tierlift::vulkan::test
