// Differential tests, shader models 2.x and 3.0: dynamic flow control per pixel (if_comp,
// break, break_comp, breakp, loops with aL-indexed constants, nested loops, subroutines
// called on p0, texkill inside flow), setp and predicated writes, sincos's one-source form,
// vs_3_0 loops, over random texture and vertex inputs with special values, on the CPU device
// and lavapipe; and vPos / vFace against their closed forms on both devices. Each listing
// links a vs_3_0 and a ps_3_0 by semantic (o1 texcoord0 → v0 texcoord0); normal0 and
// tangent0, which the 2.0 interface has no register for, link through free texcoord slots.
#include <set>

#include "diff_harness.h"
#include "tierlift/ir/opcodes.h"

namespace tierlift::vulkan::test {
namespace {

struct Sm3Case {
  const char* name;
  // Reads r0, r1, r2 (s0, s1, s2 at this pixel), c0..c15, i0..i3; writes r4 (zero first).
  const char* body;
  const char* profile = "ps_3_0";
};

// clang-format off
const Sm3Case kSm3Cases[] = {
    {"loop_sum_al", "loop aL, i0\nmad r4, r0, c[aL], r4\nendloop"},
    {"loop_nested_al", "loop aL, i0\nadd r4, r4, c[aL]\nloop aL, i1\nmad r4, r4, c[aL], r0\nendloop\nendloop"},
    {"rep_break_comp", "rep i2\nadd r4, r4, r1\nbreak_gt r4.x, r2.x\nendrep"},
    {"rep_break_in_if", "rep i2\nadd r4, r4, r0\nif_lt r4.y, r1.y\nbreak\nendif\nmul r4, r4, c3\nendrep"},
    {"loop_breakp", "setp_ge p0, r0, r1\nloop aL, i0\nadd r4, r4, c[aL]\nbreakp !p0.z\nendloop"},
    {"if_comp_else", "if_ge r0.x, r1.x\nadd r4, r0, r2\nelse\nmul r4, r1, r2\nendif"},
    {"if_comp_nested", "if_ne r0.z, r1.z\nif_le r0.w, r2.w\nmov r4, r1\nelse\nmov r4, r2\nendif\nelse\nmov r4, r0\nendif"},
    {"if_eq_nan", "if_eq r0.x, r0.x\nmov r4, c1\nelse\nmov r4, c2\nendif"},
    {"if_predicate", "setp_lt p0, r0, r1\nif p0.y\nmov r4, r2\nendif\nif !p0.w\nadd r4, r4, r0\nendif"},
    {"setp_predicated", "setp_gt p0, r0, r1\n(p0) mov r4, r2\n(!p0.y) add r4, r4, r0"},
    {"setp_all", "setp_eq p0.x, r0, r1\nsetp_ne p0.y, r0, r1\nsetp_le p0.z, r0, r1\nsetp_lt p0.w, r0, r1\n(p0) mov r4, c1\n(!p0) mov r4, c2"},
    {"predicated_setp", "setp_ge p0, r0, c0\n(p0.x) setp_lt p0.yz, r1, r2\n(p0) mov r4, r1"},
    {"callnz_predicate", "setp_gt p0, r0, r1\ncallnz l0, p0.x\ncallnz l1, !p0.y", "ps_3_0"},
    {"sincos_one_source", "frc r5.x, r0.x\nsincos r4.xy, r5.x"},
    {"texkill_in_if", "if_lt r0.x, r1.x\ntexkill r2\nendif\nmov r4, r2"},
    {"texkill_predicated", "setp_gt p0, r0, r1\nadd r5, r2, -r0\n(p0) texkill r5\n(!p0.z) texkill r1\nmov r4, r2"},
    {"loop_budget_rep", "rep i3\nrep i3\nrep i3\nadd r4, r4, c1\nendrep\nendrep\nendrep"},
    {"ps2x_break_predicate", "rep i2\nadd r4, r4, r1\nsetp_gt p0.x, r4.x, r2.x\nbreakp p0.x\nendrep\n(p0.x) mul r4, r4, r0", "ps_2_x"},
};
// clang-format on

std::string ps_text(const Sm3Case& c) {
  const bool sm3 = std::string(c.profile) == "ps_3_0";
  std::string t = std::string(c.profile) +
                  "\n"
                  "defi i0, 4, 2, 3, 0\n" // aL = 2, 5, 8, 11
                  "defi i1, 3, 1, 2, 0\n" // aL = 1, 3, 5
                  "defi i2, 6, 0, 0, 0\n" +
                  (sm3 ? "dcl_texcoord0 v0\n" : "dcl t0\n") + "dcl_2d s0\ndcl_2d s1\ndcl_2d s2\n";
  const char* uv = sm3 ? "v0" : "t0";
  t += fmt::format("texld r0, {0}, s0\ntexld r1, {0}, s1\ntexld r2, {0}, s2\nmov r4, c0\n", uv);
  t += std::string(c.body) + "\nmov oC0, r4\n";
  if (std::string(c.name) == "callnz_predicate")
    t += "ret\nlabel l0\nadd r4, r4, r2\nret\nlabel l1\nmul r4, r4, r1\nret\n";
  return t;
}

// vs_3_0 → ps_3_0 by semantic; ps_2_x reads t0, so the vertex shader writes texcoord0 too.
const char* kQuadVs3 = "vs_3_0\ndcl_position v0\ndcl_texcoord v3\ndcl_position o0\n"
                       "dcl_texcoord0 o1\nmov o0, v0\nmov o1, v3\n";

FamilyMax g_sm3("ps_3_0/ps_2_x flow");

class Sm3Diff : public VulkanTest, public ::testing::WithParamInterface<Sm3Case> {};

TEST_P(Sm3Diff, CpuAndVulkanAgree) {
  const Sm3Case& c = GetParam();
  for (uint64_t seed : {1, 2}) {
    DiffSetup s;
    s.seed = seed;
    add_random_textures(s, 3, {});
    s.ps_c = random_constants(seed * 100, 16, {-2, 2, 0.2f});
    DiffResult r = run_diff_with(*dev, kQuadVs3, ps_text(c), s, [&](cpu::Pass& p) {
      p.ps_constants.i[3] = {255, 0, 0, 0}; // 255³ iterations: the budget ends them
    });
    expect_agree(r, fmt::format("{} seed {}", c.name, seed), g_sm3);
    // Flow and predication only choose among fp32 operations both devices run alike: the
    // same values exactly (sincos too: the interpreter's sine is lavapipe's, rule 39).
    EXPECT_EQ(r.diff.max_scaled, 0.0) << c.name << " seed " << seed << ": " << r.diff.first_bad;
  }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const Sm3Case& c, std::ostream* os) {
  *os << c.name << " (" << c.profile << "): " << one_line(c.body);
}

INSTANTIATE_TEST_SUITE_P(Flow, Sm3Diff, ::testing::ValuesIn(kSm3Cases),
                         [](const auto& info) { return std::string(info.param.name); });

// Every flow and predication row of 3.0 that runs has a case above.
TEST(Sm3DiffCoverage, EveryDynamicFlowOpcodeHasACase) {
  std::set<std::string> covered;
  for (const Sm3Case& c : kSm3Cases) add_mnemonics(covered, c.body, " ");
  for (const char* m : {"break", "break_gt", "breakp", "if_ge", "if_ne", "if_le", "if_lt", "if_eq",
                        "setp_gt", "setp_eq", "setp_ne", "setp_le", "setp_lt", "setp_ge", "callnz",
                        "loop", "rep", "sincos", "texkill"})
    EXPECT_TRUE(covered.count(m)) << m;
}

// The case table's hand-checked anchor: loop_sum_al with s0 = 1 everywhere is
// c2 + c5 + c8 + c11 (+ c0, r4's start) on both devices.
TEST_F(VulkanTest, Sm3LoopSumMatchesTheClosedForm) {
  DiffSetup s;
  auto one = std::make_shared<img::Image>(kDiffW, kDiffH);
  std::fill(one->rgba.begin(), one->rgba.end(), 1.0f);
  s.textures = {one, one, one};
  s.ps_c.assign(16, cpu::Vec4{0, 0, 0, 0});
  for (int k = 0; k < 16; ++k) s.ps_c[static_cast<size_t>(k)] = {float(k), 0, 0, 1};
  DiffResult r = run_diff(*dev, kQuadVs3, ps_text(kSm3Cases[0]), s);
  ASSERT_TRUE(r.ok);
  for (const img::Image* im : {&r.cpu, &r.vk})
    for (size_t p = 0; p < im->rgba.size() / 4; ++p) {
      ASSERT_EQ(im->rgba[p * 4 + 0], 0.0f + 2 + 5 + 8 + 11) << p;
      ASSERT_EQ(im->rgba[p * 4 + 3], 1.0f + 4) << p;
    }
}

// vs_3_0 flow per vertex: a loop with aL-indexed constants and a break_comp, written to a
// texcoord by semantic, seen flat by a ps_2_0.
TEST_F(VulkanTest, Vs3LoopAndBreakAgree) {
  const std::string vs = "vs_3_0\ndefi i0, 5, 1, 2, 0\n"
                         "dcl_position v0\ndcl_texcoord0 v1\ndcl_texcoord1 v2\n"
                         "dcl_position o0\ndcl_texcoord0 o1\n"
                         "mov o0, v0\nmov r3, v1\nloop aL, i0\nmad r3, r3, c[aL], v2\n"
                         "break_lt r3.x, c0.x\nendloop\nmov o1, r3\n";
  for (uint64_t seed : {1, 2}) {
    DiffSetup s;
    s.seed = seed;
    s.per_pixel_vertices = true;
    s.vertex_range = {-2, 2, 0.1f};
    s.vs_c = random_constants(seed * 100, 16, {-2, 2, 0.1f});
    DiffResult r = run_diff(*dev, vs, "ps_2_0\ndcl t0\nmov oC0, t0\n", s);
    expect_agree(r, fmt::format("vs_3_0 loop seed {}", seed), g_sm3);
  }
}

// vPos: pixel (x, y) reads (x, y, 0, 0) on both devices, with D3D9 pixel centres and with
// modern ones alike (NUMERICS.md "vPos": the pixel's integer coordinates, not x + 0.5).
TEST_F(VulkanTest, VposIsThePixelsIntegerCoordinates) {
  for (ir::PixelCenter centre : {ir::PixelCenter::D3D9, ir::PixelCenter::Modern}) {
    DiffResult r = run_diff_with(
        *dev, kQuadVs3, "ps_3_0\ndcl vPos.xy\nmov r0, c0\nmov r0.xy, vPos\nmov oC0, r0\n",
        DiffSetup{}, [&](cpu::Pass& p) { p.conventions.pixel_center = centre; });
    ASSERT_TRUE(r.ok);
    for (const img::Image* im : {&r.cpu, &r.vk})
      for (uint32_t y = 0; y < kDiffH; ++y)
        for (uint32_t x = 0; x < kDiffW; ++x) {
          const float* px = im->rgba.data() + 4 * (size_t{y} * kDiffW + x);
          ASSERT_EQ(px[0], float(x + 0)) << (im == &r.cpu ? "cpu" : "vulkan") << " " << x;
          ASSERT_EQ(px[1], float(y + 0)) << (im == &r.cpu ? "cpu" : "vulkan") << " " << y;
          ASSERT_EQ(px[2], 0.0f);
          ASSERT_EQ(px[3], 0.0f);
        }
  }
}

// vFace: +1 on a triangle clockwise on screen (Direct3D 9's front face), −1 on one
// counter-clockwise, on both devices. The left half of the target is one triangle pair
// wound clockwise, the right half the same pair wound the other way.
// Left half clockwise, right half counter-clockwise on screen; vFace on both devices with
// `front` as the pass's front face.
DiffResult draw_both_windings(vulkan::Device& dev, pass::FrontFace front) {
  return run_diff_with(
      dev, "vs_3_0\ndcl_position v0\ndcl_position o0\nmov o0, v0\n",
      "ps_3_0\ndcl vFace\nmov oC0, vFace\n", DiffSetup{}, [&](cpu::Pass& p) {
        p.vertices.assign(8, cpu::VertexInput{});
        // Clip space: y up. Left half x in [-1, 0], right half [0, 1].
        const float xs[2][2] = {{-1, 0}, {0, 1}};
        for (int h = 0; h < 2; ++h) {
          const float x0 = xs[h][0], x1 = xs[h][1];
          const cpu::Vec4 tl{x0, 1, 0, 1}, tr{x1, 1, 0, 1}, bl{x0, -1, 0, 1}, br{x1, -1, 0, 1};
          for (int k = 0; k < 4; ++k)
            p.vertices[static_cast<size_t>(4 * h + k)].v[0] = std::array{tl, tr, br, bl}[k];
        }
        // tl → tr → br is clockwise on screen; the right half lists it backwards.
        p.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6}};
        p.front_face = front;
      });
}

void expect_face_signs(const DiffResult& r, float left) {
  for (const img::Image* im : {&r.cpu, &r.vk})
    for (uint32_t y = 0; y < kDiffH; ++y)
      for (uint32_t x = 0; x < kDiffW; ++x) {
        const float want = x < kDiffW / 2 ? left : -left;
        ASSERT_EQ(im->rgba[4 * (size_t{y} * kDiffW + x)], want)
            << (im == &r.cpu ? "cpu" : "vulkan") << " pixel " << x << "," << y;
      }
}

TEST_F(VulkanTest, VfaceIsTheSignOfTheWinding) {
  DiffResult r = draw_both_windings(*dev, pass::FrontFace::Clockwise);
  ASSERT_TRUE(r.ok);
  expect_face_signs(r, 1.0f);
}

// Pass::front_face (`tierlift run --front-face ccw`): the counter-clockwise half is the front.
TEST_F(VulkanTest, VfaceFollowsTheFrontFaceSetting) {
  DiffResult r = draw_both_windings(*dev, pass::FrontFace::CounterClockwise);
  ASSERT_TRUE(r.ok);
  expect_face_signs(r, -1.0f);
}

// NUMERICS.md F6: normal0 and tangent0 have no 2.0 register; each stage carries them in the
// texcoord slots it leaves free (t7 is texcoord7's here, so normal0 → t6, tangent0 → t5),
// whatever o#/v# the two programs chose. Flat values, so the closed form is the constants.
TEST_F(VulkanTest, ExtraSemanticsLinkAcrossStages) {
  const std::string vs = "vs_3_0\ndef c0, 0.25, 0, 0, 1\ndef c1, 0, 0.75, 0, 0\n"
                         "def c2, 0, 0, 0.5, 0\ndcl_position v0\ndcl_position o0\n"
                         "dcl_normal o1\ndcl_texcoord7 o2\ndcl_tangent o3\n"
                         "mov o0, v0\nmov o1, c0\nmov o2, c2\nmov o3, c1\n";
  const std::string ps = "ps_3_0\ndcl_tangent v2\ndcl_texcoord7 v4\ndcl_normal v7\n"
                         "mov r0, v7\nmov r0.y, v2.y\nmov r0.z, v4.z\nmov oC0, r0\n";
  DiffResult r = run_diff(*dev, vs, ps, DiffSetup{});
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.diff.max_scaled, 0.0) << r.diff.first_bad;
  for (const img::Image* im : {&r.cpu, &r.vk})
    for (size_t p = 0; p < im->rgba.size() / 4; ++p) {
      ASSERT_NEAR(im->rgba[p * 4 + 0], 0.25f, 1e-6f) << p;
      ASSERT_NEAR(im->rgba[p * 4 + 1], 0.75f, 1e-6f) << p;
      ASSERT_NEAR(im->rgba[p * 4 + 2], 0.5f, 1e-6f) << p;
      ASSERT_NEAR(im->rgba[p * 4 + 3], 1.0f, 1e-6f) << p;
    }
  // Without tangent0 in the vertex program, the pixel program's tangent0 (t5 there) would
  // read nothing while normal0 sits in t6 on both sides: a pair both devices refuse
  // when its slots disagree (here the vertex program puts normal0 where ps reads tangent0).
  cpu::Pass pass;
  pass.vertex_program = parse_listing("vs_3_0\ndcl_position v0\ndcl_position o0\n"
                                      "dcl_normal o1\nmov o0, v0\nmov o1, v0\n",
                                      "n.vsh");
  pass.pixel_program = parse_listing("ps_3_0\ndcl_tangent v0\nmov oC0, v0\n", "t.psh");
  ASSERT_TRUE(pass.vertex_program && pass.pixel_program);
  cpu::set_full_screen_quad(pass, 0);
  img::Image cpu_out(kDiffW, kDiffH), vk_out(kDiffW, kDiffH);
  ir::Result<cpu::DrawStats> st = cpu::draw(pass, cpu_out, 1);
  ir::Result<pass::DrawReport> vk = dev->draw(pass, vk_out);
  ASSERT_FALSE(st.ok());
  ASSERT_FALSE(vk.ok());
  for (const std::string& m : {st.message(), vk.message()})
    EXPECT_NE(m.find("reads tangent0 from texcoord slot t7, where the vertex program puts "
                     "normal0"),
              std::string::npos)
        << m;
}

// NUMERICS.md F6: fog0 is a vector semantic in shader model 3, carried like any extra
// semantic in a free texcoord slot and not clamped (bgfx's shadow volume shaders pass ±1 and
// ±2 through it). Flat values, so the closed form is the constants.
TEST_F(VulkanTest, Fog0LinksBySemanticUnclamped) {
  const std::string vs = "vs_3_0\ndef c0, -1.5, 2.5, 7, 9\ndcl_position v0\ndcl_position o0\n"
                         "dcl_fog o1.xy\nmov o0, v0\nmov o1.xy, c0\n";
  const std::string ps = "ps_3_0\ndef c0, 0, 0, 0.5, 1\ndcl_fog v3.xy\nmov r0, c0\n"
                         "mov r0.xy, v3\nmov oC0, r0\n";
  DiffResult r = run_diff(*dev, vs, ps, DiffSetup{});
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.diff.max_scaled, 0.0) << r.diff.first_bad;
  for (const img::Image* im : {&r.cpu, &r.vk})
    for (size_t p = 0; p < im->rgba.size() / 4; ++p) {
      ASSERT_EQ(im->rgba[p * 4 + 0], -1.5f) << p;
      ASSERT_EQ(im->rgba[p * 4 + 1], 2.5f) << p;
      ASSERT_EQ(im->rgba[p * 4 + 2], 0.5f) << p;
    }
}

// NUMERICS.md F6: a vs_2_0 before a ps_3_0 that reads fog0: the pixel program reads
// (saturate(oFog), 0, 0, 0), as Direct3D 9 hands a 2.0 stage's fog to a 3.0 one.
TEST_F(VulkanTest, Fog0ReadsTheScalarOfAVs20) {
  const std::string ps = "ps_3_0\ndcl_fog v0\nmov oC0, v0\n";
  for (const auto& [fog, want] : {std::pair{0.375f, 0.375f}, {1.75f, 1.0f}, {-2.0f, 0.0f}}) {
    const std::string vs = "vs_2_0\ndef c0, " + std::to_string(fog) +
                           ", 5, 6, 7\ndcl_position v0\nmov oPos, v0\nmov oFog, c0.x\n";
    DiffResult r = run_diff(*dev, vs, ps, DiffSetup{});
    ASSERT_TRUE(r.ok) << fog;
    EXPECT_EQ(r.diff.max_scaled, 0.0) << r.diff.first_bad;
    for (const img::Image* im : {&r.cpu, &r.vk})
      for (size_t p = 0; p < im->rgba.size() / 4; ++p) {
        ASSERT_EQ(im->rgba[p * 4 + 0], want) << fog << " pixel " << p;
        for (int c = 1; c < 4; ++c) ASSERT_EQ(im->rgba[p * 4 + c], 0.0f) << fog << " pixel " << p;
      }
  }
}

// NUMERICS.md F6 and rule 26: a colour is clamped to [0, 1] only where a stage before 3.0
// holds it: a vs_2_0 writes oD0 saturated, a ps_2_0 reads v0 saturated, a vs_3_0 → ps_3_0
// pair passes it as it is. The vertex program writes the flat colour (−0.5, 2, 0.25, 1), so
// every pixel holds the closed form on both devices.
TEST_F(VulkanTest, ColourIsClampedOnlyWhereAStageBefore30HoldsIt) {
  const std::string vs30 = "vs_3_0\ndef c0, -0.5, 2, 0.25, 1\ndcl_position v0\ndcl_position o0\n"
                           "dcl_color0 o1\nmov o0, v0\nmov o1, c0\n";
  const std::string vs20 =
      "vs_2_0\ndef c0, -0.5, 2, 0.25, 1\ndcl_position v0\nmov oPos, v0\nmov oD0, c0\n";
  const std::string ps30 = "ps_3_0\ndcl_color0 v0\nmov oC0, v0\n";
  const std::string ps20 = "ps_2_0\ndcl v0\nmov oC0, v0\n";
  struct Pair {
    const std::string* vs;
    const std::string* ps;
    std::array<float, 4> want;
  };
  const Pair pairs[] = {{&vs30, &ps30, {-0.5f, 2, 0.25f, 1}},
                        {&vs20, &ps30, {0, 1, 0.25f, 1}},
                        {&vs30, &ps20, {0, 1, 0.25f, 1}},
                        {&vs20, &ps20, {0, 1, 0.25f, 1}}};
  for (const Pair& pair : pairs) {
    const std::string what = pair.vs->substr(0, 6) + " -> " + pair.ps->substr(0, 6);
    DiffResult r = run_diff(*dev, *pair.vs, *pair.ps, DiffSetup{});
    ASSERT_TRUE(r.ok) << what;
    EXPECT_EQ(r.diff.max_scaled, 0.0) << what << ": " << r.diff.first_bad;
    for (const img::Image* im : {&r.cpu, &r.vk})
      for (size_t p = 0; p < im->rgba.size() / 4; ++p)
        for (int c = 0; c < 4; ++c)
          ASSERT_EQ(im->rgba[p * 4 + c], pair.want[c]) << what << " pixel " << p << " ." << c;
  }
}

// NUMERICS.md F13: a ps_3_0's v[aL + n] indexes its declared inputs by v# number. The first
// loop (aL = 0..3) reads v0 = texcoord0 (u), v1 = color0 ((−0.5, 2, 0, 1), unclamped between
// 3.0 stages), v2 = texcoord3 (8v) and v3, undeclared: 0. The second (aL = 9, 10) reads v9 =
// texcoord5 (4, 4, 4, 4) and v10, beyond ps_3_0's ten: 0. At pixel (x, y) u = (x + ½)/16 and
// v = (y + ½)/16, so oC0 = (u + 8v + 4) + (−0.5, 2, 0, 1) on both devices.
TEST_F(VulkanTest, RelativeInputReadsIndexTheDeclaredInputsByNumber) {
  const std::string vs = "vs_3_0\ndef c0, -0.5, 2, 0, 1\ndef c1, 8, 8, 8, 8\n"
                         "def c2, 4, 4, 4, 4\ndcl_position v0\ndcl_texcoord v3\n"
                         "dcl_position o0\ndcl_texcoord0 o1\ndcl_color0 o2\ndcl_texcoord3 o3\n"
                         "dcl_texcoord5 o4\nmov o0, v0\nmov o1, v3.x\nmov o2, c0\n"
                         "mul o3, v3.y, c1\nmov o4, c2\n";
  const std::string ps = "ps_3_0\ndefi i0, 4, 0, 1, 0\ndefi i1, 2, 9, 1, 0\n"
                         "def c0, 0, 0, 0, 0\ndcl_texcoord0 v0\ndcl_color0 v1\n"
                         "dcl_texcoord3 v2\ndcl_texcoord5 v9\nmov r0, c0\nloop aL, i0\n"
                         "add r0, r0, v0[aL]\nendloop\nloop aL, i1\nadd r0, r0, v[aL]\n"
                         "endloop\nmov oC0, r0\n";
  DiffResult r = run_diff(*dev, vs, ps, DiffSetup{});
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.diff.max_scaled, 0.0) << r.diff.first_bad;
  // Exact: u, v are multiples of 1/32 and every partial sum stays below 16, so each value
  // needs at most 9 significant bits and no float addition rounds.
  for (const img::Image* im : {&r.cpu, &r.vk})
    for (uint32_t y = 0; y < kDiffH; ++y)
      for (uint32_t x = 0; x < kDiffW; ++x) {
        const float u = (x + 0.5f) / kDiffW, v = (y + 0.5f) / kDiffH;
        const float base = u + 8 * v + 4;
        const float want[4] = {base - 0.5f, base + 2, base, base + 1};
        const float* px = &im->rgba[(size_t{y} * kDiffW + x) * 4];
        for (int c = 0; c < 4; ++c)
          ASSERT_EQ(px[c], want[c]) << "pixel (" << x << ", " << y << ") ." << c;
      }
}

// NUMERICS.md F13: a vs_3_0's o[aL + n] writes the output declared as o# n + aL, wherever
// its semantic lands. o3, o4, o5 are texcoord2, texcoord0, color0: aL = 3, 4, 5 writes r0 =
// c0 + u, then + c1, then + 2·c1 into them: texcoord2 = (1, 2, 3, 4) + u, texcoord0 = (11,
// 22, 33, 44) + u, color0 = (21, 42, 63, 84) + u (unclamped, 3.0 to 3.0). Writes on o6
// (undeclared, aL = 6), o[a0.x] with a0.x = 12 and -1 (outside o0-o11) write nothing. The
// pixel stage adds texcoord2 + 2·texcoord0 + 4·color0 = (107, 214, 321, 428) + 7u.
TEST_F(VulkanTest, RelativeOutputWritesIndexTheDeclaredOutputsByNumber) {
  const std::string vs = "vs_3_0\ndefi i0, 3, 3, 1, 0\ndefi i1, 1, 6, 1, 0\n"
                         "def c0, 1, 2, 3, 4\ndef c1, 10, 20, 30, 40\ndef c2, 12, -1, 0, 0\n"
                         "def c3, 1000, 1000, 1000, 1000\ndcl_position v0\ndcl_texcoord v3\n"
                         "dcl_position o0\ndcl_texcoord2 o3\ndcl_texcoord0 o4\n"
                         "dcl_color0 o5\nmov o0, v0\nadd r0, c0, v3.x\nloop aL, i0\n"
                         "mov o[aL], r0\nadd r0, r0, c1\nendloop\nloop aL, i1\n"
                         "mov o[aL], c3\nendloop\nmova a0.xy, c2\nmov o[a0.x], c3\n"
                         "mov o[a0.y], c3\n";
  const std::string ps = "ps_3_0\ndef c0, 2, 4, 0, 0\ndcl_texcoord0 v0\ndcl_texcoord2 v1\n"
                         "dcl_color0 v2\nmov r1, v1\nmad r0, v0, c0.x, r1\nmad oC0, v2, c0.y, r0\n";
  DiffResult r = run_diff(*dev, vs, ps, DiffSetup{});
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.diff.max_scaled, 0.0) << r.diff.first_bad;
  // Exact: u is a multiple of 1/32 and every partial sum stays below 512, so each value needs
  // at most 14 significant bits and no float operation (the mads included) rounds.
  for (const img::Image* im : {&r.cpu, &r.vk})
    for (uint32_t y = 0; y < kDiffH; ++y)
      for (uint32_t x = 0; x < kDiffW; ++x) {
        const float u = (x + 0.5f) / kDiffW;
        const float want[4] = {107 + 7 * u, 214 + 7 * u, 321 + 7 * u, 428 + 7 * u};
        const float* px = &im->rgba[(size_t{y} * kDiffW + x) * 4];
        for (int c = 0; c < 4; ++c)
          ASSERT_EQ(px[c], want[c]) << "pixel (" << x << ", " << y << ") ." << c;
      }
}

// NUMERICS.md F12: without multisampling `_centroid` samples where a plain input does, the
// pixel centre (a covered pixel's one sample), on both devices: the interpolated texcoord is
// the same image bit for bit with and without it.
TEST_F(VulkanTest, CentroidWithOneSampleIsThePixelCentre) {
  const std::string vs = "vs_3_0\ndcl_position v0\ndcl_texcoord v3\ndcl_position o0\n"
                         "dcl_texcoord0 o1\nmov o0, v0\nmov o1, v3\n";
  DiffResult plain = run_diff(*dev, vs, "ps_3_0\ndcl_texcoord0 v0\nmov oC0, v0\n", DiffSetup{});
  DiffResult centroid =
      run_diff(*dev, vs, "ps_3_0\ndcl_texcoord0_centroid v0\nmov oC0, v0\n", DiffSetup{});
  ASSERT_TRUE(plain.ok && centroid.ok);
  EXPECT_EQ(centroid.diff.max_scaled, 0.0) << centroid.diff.first_bad;
  EXPECT_EQ(centroid.cpu.rgba, plain.cpu.rgba);
  EXPECT_EQ(centroid.vk.rgba, plain.vk.rgba);
  // The quad-uv at pixel (3, 0): the harness samples at pixel centres (x + ½) / W.
  EXPECT_NEAR(centroid.cpu.rgba[4 * 3], 3.5f / kDiffW, 1e-6f);
}

} // namespace
} // namespace tierlift::vulkan::test
