// Differential tests, texture instructions: texld, texldp, texldb, texkill (ps_2_0), tex
// (plain and D3DTTFF_PROJECTED) and texcoord (ps_1_1), texld and texcrd (ps_1_4), with point
// and bilinear filtering and every address mode the Vulkan device maps, over coordinates
// that leave [0, 1], on the CPU device and lavapipe.
#include "diff_harness.h"

namespace tierlift::vulkan::test {
namespace {

struct TexCase {
  const char* name;
  const char* vs; // computes oT0 (and oT1) from v3 = quad uv and c0, c1
  const char* ps; // samples stage 0 (stage 1: a random texture for texkill)
  bool projected = false;
};

// oT0 = 2.5·uv − 0.75 ∈ [−0.75, 1.75]: texel-space fractions .25/.75 (no point-sampling
// ties); the projective variant carries w = 2 and divides back to the same.
const char* kVs20 = "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmad oT0, v3, c0, c1\n";
const char* kVs11 =
    "vs.1.1\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmul r0, v3, c0\nadd oT0, r0, c1\n";
const cpu::Vec4 kScale{2.5f, 2.5f, 0, 0}, kOffset{-0.75f, -0.75f, 0, 1};
const cpu::Vec4 kScaleQ{5.0f, 5.0f, 0, 0}, kOffsetQ{-1.5f, -1.5f, 0, 2};

// clang-format off
const TexCase kTexCases[] = {
    {"texld", kVs20, "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n"},
    {"texldp", kVs20, "ps_2_0\ndcl t0\ndcl_2d s0\ntexldp r0, t0, s0\nmov oC0, r0\n", true},
    {"texldb", kVs20, "ps_2_0\ndcl t0\ndcl_2d s0\ntexldb r0, t0, s0\nmul r0, r0, t0.x\nmov oC0, r0\n"},
    {"texkill", kVs20, "ps_2_0\ndcl t0\ndcl_2d s0\ndcl_2d s1\ntexld r1, t0, s1\ntexkill r1\n"
                       "texld r0, t0, s0\nmov oC0, r0\n"},
    // ps_3_0 texldl: lod w = 1 (from the vertex stage), then lod 8·u − 4 ∈ [−10, 10] per pixel:
    // one mip level, so every lod reads level 0 with the stage's filter.
    {"texldl", kVs20, "ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\ntexldl r0, v0, s0\nmov oC0, r0\n"},
    {"texldl_lod", kVs20, "ps_3_0\ndef c1, 8, -4, 0, 0\ndcl_texcoord0 v0\ndcl_2d s0\nmov r1, v0\n"
                          "mad r1.w, v0.x, c1.x, c1.y\ntexldl r0, r1, s0\nmov oC0, r0\n"},
    {"tex", kVs11, "ps.1.1\ntex t0\nmov r0, t0\n"},
    {"tex_projected", kVs11, "ps.1.1\ntex t0\nmov r0, t0\n", true},
    {"texcoord", kVs11, "ps.1.1\ntexcoord t0\nmov r0, t0\n"},
    {"ps14_texld", kVs11, "ps.1.4\ntexld r0, t0\nmul r0, r0, c0\n"},
    {"ps14_texcrd", kVs11, "ps.1.4\ntexcrd r0.rgb, t0\nmov r0.a, c0\n"},
};
// clang-format on

FamilyMax g_tex("texture instructions");

class TexDiff : public VulkanTest, public ::testing::WithParamInterface<TexCase> {};

TEST_P(TexDiff, CpuAndVulkanAgree) {
  const TexCase& c = GetParam();
  for (cpu::Filter filter : {cpu::Filter::Point, cpu::Filter::Linear})
    for (cpu::AddressMode mode : {cpu::AddressMode::Wrap, cpu::AddressMode::Mirror,
                                  cpu::AddressMode::Clamp, cpu::AddressMode::Border}) {
      DiffSetup s;
      s.textures.push_back(random_texture(5, {0, 1, 0}, 8, 8));
      // texkill's input: no special values, since bilinear filtering of ±inf/NaN is not
      // comparable across devices (inf·0 weights).
      s.textures.push_back(random_texture(6, {-1, 1, 0}));
      s.filter = filter;
      s.projected[0] = c.projected;
      bool q = c.projected;
      s.vs_c = {q ? kScaleQ : kScale, q ? kOffsetQ : kOffset};
      s.ps_c = {{0.75f, 0.5f, 0.25f, 1.0f}};
      // The address mode of every stage, set after the harness filled the bindings.
      DiffResult r = run_diff_with(*dev, c.vs, c.ps, s, [&](cpu::Pass& p) {
        for (auto& tb : p.textures) tb.sampler.address_u = tb.sampler.address_v = mode;
      });
      std::string what = fmt::format("{} filter {} address {}", c.name, int(filter), int(mode));
      expect_agree(r, what);
      g_tex.add(r.diff);
    }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const TexCase& c, std::ostream* os) {
  *os << c.name << (c.projected ? " (projected)" : "") << ": " << one_line(c.ps);
}

INSTANTIATE_TEST_SUITE_P(Ops, TexDiff, ::testing::ValuesIn(kTexCases),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace tierlift::vulkan::test
