// Differential tests, the ps_1_x texture-address instructions (docs/d3d9-rules.md §5.5, §5.6):
// texbem, texbeml, texm3x2pad/texm3x2tex, texm3x2depth, texm3x3pad with texm3x3,
// texm3x3tex, texm3x3spec and texm3x3vspec, texreg2ar/gb/rgb, texdp3, texdp3tex, texkill,
// texcoord (ps_1_1–1_3); texcrd, texld with _dz/_dw, bem, texdepth, texkill and `phase`
// (ps_1_4); over random RGBA32F textures (point-sampled, so every dependent read must pick
// the same texel) and four interpolated coordinate sets, on the CPU device and lavapipe.
// texm3x2depth and texdepth replace the depth, which neither device exposes without a depth
// test: their cases check the colour path around them.
#include <set>
#include <sstream>

#include "diff_harness.h"

namespace tierlift::vulkan::test {
namespace {

struct AddrCase {
  const char* name;
  const char* ps; // full listing; t0..t3 carry the coordinate sets below
};

// clang-format off
const AddrCase kAddrCases[] = {
    {"texbem", "ps.1.1\ntex t0\ntexbem t1, t0\nmov r0, t1\n"},
    {"texbeml", "ps.1.1\ntex t0\ntexbeml t1, t0\nmov r0, t1\n"},
    {"texbem_twice", "ps.1.3\ntex t0\ntexbem t1, t0\ntexbem t2, t1\nmov r0, t2\n"},
    {"texm3x2tex", "ps.1.1\ntex t0\ntexm3x2pad t1, t0\ntexm3x2tex t2, t0\nmov r0, t2\n"},
    {"texm3x2tex_bx2", "ps.1.1\ntex t0\ntexm3x2pad t1, t0_bx2\ntexm3x2tex t2, t0_bx2\nmov r0, t2\n"},
    {"texm3x2depth", "ps.1.3\ntex t0\ntexm3x2pad t1, t0\ntexm3x2depth t2, t0\nmul r0, t0, c0\n"},
    {"texm3x3", "ps.1.2\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3 t3, t0\nmov r0, t3\n"},
    {"texm3x3tex", "ps.1.1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3tex t3, t0\nmov r0, t3\n"},
    {"texm3x3spec", "ps.1.1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3spec t3, t0, c1\nmov r0, t3\n"},
    {"texm3x3vspec", "ps.1.1\ntex t0\ntexm3x3pad t1, t0\ntexm3x3pad t2, t0\ntexm3x3vspec t3, t0\nmov r0, t3\n"},
    {"texreg2ar", "ps.1.1\ntex t0\ntexreg2ar t1, t0\nmov r0, t1\n"},
    {"texreg2gb", "ps.1.1\ntex t0\ntexreg2gb t1, t0\nmov r0, t1\n"},
    {"texreg2rgb", "ps.1.2\ntex t0\ntexreg2rgb t1, t0\nmov r0, t1\n"},
    {"texdp3", "ps.1.2\ntex t0\ntexdp3 t1, t0\nmov r0, t1\n"},
    {"texdp3tex", "ps.1.2\ntex t0\ntexdp3tex t1, t0\nmov r0, t1\n"},
    {"texkill", "ps.1.1\ntexkill t1\ntex t0\nmov r0, t0\n"},
    {"texcoord", "ps.1.1\ntexcoord t1\ntexcoord t3\nadd r0, t1, t3\n"},
    {"ps14_texcrd", "ps.1.4\ntexcrd r0.rgb, t1\ntexcrd r1.rgb, t3.xyw\nadd r0.rgb, r0, r1\n+mov r0.a, c0\n"},
    {"ps14_texld_dz_dw", "ps.1.4\ntexcrd r2.rgb, t1\nphase\ntexld r0, t3_dw.xyw\ntexld r1, r2_dz\nadd r0, r0, r1\n"},
    {"ps14_bem", "ps.1.4\ntexld r2, t0\ntexcrd r3.rgb, t1\nbem r1.rg, r3, r2\nmov r1.b, c0\nphase\ntexld r1, r1\nmov r0, r1\n"},
    {"ps14_phase", "ps.1.4\ntexld r0, t0\ntexcrd r1.rgb, t1\nmad r2.rgb, r0, c0, r1\nphase\n"
                   "texld r3, r2\nadd r0.rgb, r3, r2\n+mov r0.a, r3\n"},
    {"ps14_texdepth", "ps.1.4\ntexcrd r5.rgb, t1\ntexcrd r2.rgb, t2\nphase\ntexdepth r5\ntexld r0, r2\n"},
    {"ps14_texkill", "ps.1.4\ntexcrd r1.rgb, t1\nphase\ntexkill r1\ntexld r0, t0\n"},
};
// clang-format on

// vs_1_1: four coordinate sets from the quad's uv (v3 = (u, v, 0, 1)) and c0..c7: t0 = uv,
// t1..t3 affine maps with distinct z and w (w carries texm3x3vspec's eye vector and the
// divisor of _dw).
const char* kVs = "vs.1.1\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n"
                  "mul r0, v3, c0\nadd oT1, r0, c1\nmul r0, v3.yxzw, c2\nadd oT2, r0, c3\n"
                  "mul r0, v3, c4\nadd oT3, r0, c5\n";
const std::vector<cpu::Vec4> kVsConsts = {
    {1.5f, -0.5f, 0.75f, 0.5f},   {-0.25f, 0.5f, 0.375f, 0.75f},
    {-1.0f, 0.75f, 0.5f, -0.25f}, {0.875f, -0.125f, -0.5f, 0.625f},
    {0.5f, 1.25f, 0.25f, 1.0f},   {0.125f, -0.375f, 0.625f, 0.5f}};

FamilyMax g_addr("ps_1_x texture addressing");

class AddrDiff : public VulkanTest, public ::testing::WithParamInterface<AddrCase> {};

TEST_P(AddrDiff, CpuAndVulkanAgree) {
  const AddrCase& c = GetParam();
  for (uint64_t seed : {1, 2, 3}) {
    DiffSetup s;
    s.seed = seed;
    // Signed data (bump offsets, normals) in [−1, 1]; no inf/NaN, which would make the
    // dependent coordinates themselves undefined.
    add_random_textures(s, 4, {-1, 1, 0}, 8, 8);
    s.vs_c = kVsConsts;
    s.ps_c = random_constants(seed * 100, 2, {-1, 1, 0});
    DiffResult r = run_diff_with(*dev, kVs, c.ps, s, [&](cpu::Pass& p) {
      for (uint32_t k = 0; k < 4; ++k) {
        auto& st = p.textures[k].stage;
        st.bumpenv_mat = {0.5f, -0.25f * float(seed), 0.25f, 0.75f};
        st.bumpenv_lscale = 0.75f;
        st.bumpenv_loffset = 0.125f * float(seed);
        p.textures[k].sampler.address_u = p.textures[k].sampler.address_v =
            seed == 2 ? cpu::AddressMode::Wrap : cpu::AddressMode::Clamp;
      }
    });
    expect_agree(r, fmt::format("{} seed {}", c.name, seed), g_addr);
    print_case_agreement(r, fmt::format("{} seed {}", c.name, seed));
    // Not a degenerate case: the pixels differ (dependent reads hit several texels; texkill
    // keeps some pixels and discards others).
    std::set<std::array<float, 4>> distinct;
    for (size_t i = 0; i + 3 < r.cpu.rgba.size(); i += 4)
      distinct.insert({r.cpu.rgba[i], r.cpu.rgba[i + 1], r.cpu.rgba[i + 2], r.cpu.rgba[i + 3]});
    EXPECT_GT(distinct.size(), 4u) << c.name;
  }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const AddrCase& c, std::ostream* os) {
  *os << c.name << ": " << one_line(c.ps);
}

INSTANTIATE_TEST_SUITE_P(TexAddr, AddrDiff, ::testing::ValuesIn(kAddrCases),
                         [](const auto& info) { return std::string(info.param.name); });

// Every texture-address opcode of ps_1_1…1_4 (and phase) has a case above.
TEST(AddrDiffCoverage, EveryTextureAddressOpcodeHasACase) {
  std::set<std::string> covered;
  for (const AddrCase& c : kAddrCases) add_mnemonics(covered, c.ps, " ");
  for (const char* m :
       {"texbem",     "texbeml",    "texm3x2pad",  "texm3x2tex",   "texm3x2depth", "texm3x3pad",
        "texm3x3",    "texm3x3tex", "texm3x3spec", "texm3x3vspec", "texreg2ar",    "texreg2gb",
        "texreg2rgb", "texdp3",     "texdp3tex",   "texkill",      "texcoord",     "texcrd",
        "texld",      "texdepth",   "bem",         "phase"})
    EXPECT_TRUE(covered.count(m)) << m;
}

} // namespace
} // namespace tierlift::vulkan::test
