// Differential tests, ps_1_1…1_4: the instruction and source modifiers (_x2 _x4 _x8 _d2 _d4
// _d8 _sat, _bias _bx2 _x2 1−x, negation), co-issue, cnd, the constant clamp to [−1, 1] and
// the register range clamp, over random texture, colour and constant inputs (outside the
// ps_1_x ranges too, with special values), on the CPU device and lavapipe.
#include "diff_harness.h"

namespace tierlift::vulkan::test {
namespace {

struct Ps1xCase {
  const char* name;
  const char* profile; // "ps.1.1" … "ps.1.4"
  const char* body;    // 1.1–1.3: t0..t2 sampled, v0/v1, c0..c7; 1.4: r0..r2 sampled. → r0
};

// clang-format off
const Ps1xCase kPs1xCases[] = {
    {"add_x2", "ps.1.1", "add_x2 r0, t0, t1"},
    {"add_x4", "ps.1.1", "add_x4 r0, t0, c0"},
    {"add_d2", "ps.1.1", "add_d2 r0, t0, t1"},
    {"mul_sat", "ps.1.1", "mul_sat r0, t0, c1"},
    {"mad_x2_sat", "ps.1.3", "mad_x2_sat r0, t0, t1, t2"},
    {"mad_x4_sat_neg", "ps.1.3", "mad_x4_sat r0, -t0, t1, c2"},
    {"bias", "ps.1.1", "add r0, t0_bias, t1"},
    {"bx2", "ps.1.1", "mul r0, t0_bx2, t1_bx2"},
    {"neg_bx2", "ps.1.2", "mad r0, -t0_bx2, c1, t2"},
    {"neg_bias", "ps.1.2", "add r0, -t0_bias, t2"},
    {"complement", "ps.1.1", "mul r0, 1-t0, t1"},
    {"negate", "ps.1.1", "add r0, -t0, c0"},
    {"dp3_bx2", "ps.1.1", "dp3 r0, t0_bx2, t1_bx2"},
    {"dp3_sat", "ps.1.1", "dp3_sat r0, t0, c3"},
    {"dp4", "ps.1.2", "dp4 r0, t0, t1"},
    {"lrp", "ps.1.1", "lrp r0, t0, t1, c2"},
    {"sub", "ps.1.1", "sub r0, t0, t1"},
    {"mov", "ps.1.1", "mov r0, t2"},
    {"cmp", "ps.1.2", "cmp r0, t0_bias, t1, t2"},
    {"cnd", "ps.1.1", "mov r0, t0\ncnd r0, r0.a, t1, t2"},
    {"coissue", "ps.1.1", "mul r0.rgb, t0, t1\n+add r0.a, t0, t2"},
    {"coissue_dp3", "ps.1.1", "dp3 r0.rgb, t0_bx2, c0\n+mov r0.a, 1-t1"},
    {"coissue_cnd", "ps.1.1", "mov r0, t2\nmul r0.rgb, t0, t1\n+cnd r0.a, r0.a, t1, c1"},
    {"const_clamp", "ps.1.1", "mov r0, c4"},
    {"const_clamp_mul", "ps.1.1", "mul r0, c5, c6"},
    {"range_clamp", "ps.1.3", "add_x4 r1, t0, t1\nmul r0, r1, c7"},
    {"colour_inputs", "ps.1.1", "mad r0, v0, t0, v1"},
    {"write_mask", "ps.1.1", "mov r0, c0\nmul_x2 r0.a, t0, t1"},
    {"ps14_cnd", "ps.1.4", "cnd r0, r1, r0, r2"},
    {"ps14_x8", "ps.1.4", "add_x8 r0, r0, r1"},
    {"ps14_d8", "ps.1.4", "mul_d8 r0, r0, c0"},
    {"ps14_d4_sat", "ps.1.4", "mad_d4_sat r0, r0_bx2, r1, c2"},
    {"ps14_src_x2", "ps.1.4", "add r0, r0_x2, -r1"},
    {"ps14_coissue", "ps.1.4", "mul r0.rgb, r0, r1\n+add r0.a, r1, r2"},
    {"ps14_cmp", "ps.1.4", "cmp r0, r0_bias, r1, r2"},
    {"ps14_const_clamp", "ps.1.4", "mad r0, c4, c5, r2"},
};
// clang-format on

std::string ps_text(const Ps1xCase& c) {
  std::string t = std::string(c.profile) + "\n";
  if (std::string(c.profile) == "ps.1.4")
    t += "texld r0, t0\ntexld r1, t0\ntexld r2, t0\n";
  else
    t += "tex t0\ntex t1\ntex t2\n";
  return t + c.body + "\n";
}

// vs_1_1: the quad's uv on oT0..oT2 and two constant colours (saturated per vertex).
const char* kVs11 = "vs.1.1\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\n"
                    "mov oT0, v3\nmov oT1, v3\nmov oT2, v3\nmov oD0, c0\nmov oD1, c1\n";

FamilyMax g_ps1x("ps_1_x modifiers");

class Ps1xDiff : public VulkanTest, public ::testing::WithParamInterface<Ps1xCase> {};

TEST_P(Ps1xDiff, CpuAndVulkanAgree) {
  const Ps1xCase& c = GetParam();
  for (uint64_t seed : {1, 2, 3}) {
    DiffSetup s;
    s.seed = seed;
    add_random_textures(s, 3, {-0.5f, 1.5f, 0.15f});
    s.ps_c = random_constants(seed * 100, 8, {-1.5f, 1.5f, 0.1f});
    s.vs_c = random_constants(seed * 1000, 2, {-0.25f, 1.25f, 0.0f});
    DiffResult r = run_diff(*dev, kVs11, ps_text(c), s);
    expect_agree(r, fmt::format("{} {} seed {}", c.profile, c.name, seed), g_ps1x);
  }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const Ps1xCase& c, std::ostream* os) {
  *os << c.name << " (" << c.profile << "): " << one_line(c.body);
}

INSTANTIATE_TEST_SUITE_P(Modifiers, Ps1xDiff, ::testing::ValuesIn(kPs1xCases),
                         [](const auto& info) { return std::string(info.param.name); });

// The register range follows Conventions::ps1x_max_value (a specialization constant on
// Vulkan): with max 8, _x4 results above 1 survive on both devices alike.
TEST_F(VulkanTest, Ps1xMaxValueConventionAgrees) {
  DiffSetup s;
  for (uint32_t k = 0; k < 3; ++k) s.textures.push_back(random_texture(40 + k, {0, 1, 0}));
  s.vs_c = {{0.5f, 0.5f, 0.5f, 1}, {0, 0, 0, 0}};
  cpu::Pass pass;
  pass.vertex_program = parse_listing(kVs11, "vs");
  pass.pixel_program = parse_listing("ps.1.3\ntex t0\ntex t1\nadd_x4 r0, t0, t1\n", "ps");
  ASSERT_TRUE(pass.vertex_program && pass.pixel_program);
  pass.vs_constants.f = s.vs_c;
  for (uint32_t k = 0; k < 3; ++k) {
    pass.textures[k].image = s.textures[k];
    pass.textures[k].sampler.address_u = pass.textures[k].sampler.address_v =
        cpu::AddressMode::Clamp;
  }
  set_geometry(pass, s);
  pass.conventions.pixel_center = ir::PixelCenter::Modern;
  pass.conventions.ps1x_max_value = 8;
  TwoWays t = draw_both(*dev, pass, kDiffW, kDiffH, img::Format::RGBA32F);
  ASSERT_TRUE(t.ok);
  ValueDiff d = compare_values(t.cpu, t.vk);
  EXPECT_LE(d.max_scaled, 1e-5) << d.first_bad;
  float biggest = 0;
  for (float v : t.vk.rgba) biggest = std::max(biggest, v);
  EXPECT_GT(biggest, 1.5f); // not clamped to 1
  EXPECT_LE(biggest, 8.0f);
}

} // namespace
} // namespace tierlift::vulkan::test
