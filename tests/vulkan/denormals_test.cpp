// NUMERICS.md rule 13, measured: what lavapipe does with fp32 denormals, instruction by
// instruction, and that the CPU device's default convention (Rounding::Llvmpipe) does the same
// bit for bit. Every expected value below is derived by hand from the rule — an operation or a
// comparison reads a denormal as the zero of its sign and writes a denormal result as the zero
// of its sign (x86 DAZ + FTZ, which llvmpipe sets for its shader threads); data movement (mov,
// swizzles, negate/abs, the operand a select hands on, point-sampled texels, RGBA32F stores)
// keeps the bits; def constants load flushed — and was measured on lavapipe (Mesa 22.3,
// x86-64). Under Rounding::Exact the interpreter keeps denormals everywhere (IEEE).
#include <cstring>

#include "diff_harness.h"

namespace tierlift::vulkan::test {
namespace {

uint32_t bits(float x) {
  uint32_t u;
  std::memcpy(&u, &x, 4);
  return u;
}

constexpr float kD = 1e-40f;    // denormal, bits 0x000116c2
constexpr float kT = 0x1p-140f; // denormal, bits 0x00000200
constexpr float kM = FLT_MAX;
constexpr float kMin = FLT_MIN;           // 2^-126, the smallest normal
constexpr float kMin1 = 0x1.000002p-126f; // FLT_MIN + 2^-148

// The constants every case may read (vertex and pixel stage alike).
const std::vector<cpu::Vec4> kConsts = {
    {kD, -kD, kT, -kT},                        // c0: denormals of both signs
    {0x1p100f, 0x1p-70f, kMin, 0.0f},          // c1
    {-140.0f, -127.5f, -126.5f, 0.5f},         // c2: exp arguments with denormal results
    {0x1p-70f, -0x1p-70f, 0x1p-75f, 0x1p-60f}, // c3: products below 2^-126
    {kMin1, -kMin1, kMin, -kMin},              // c4: sums below 2^-126 with c8
    {1.0f, -1.0f, 2.0f, 0.5f},                 // c5
    {kD, kD, 0.0f, kD},                        // c6: lit
    {0, 0, 0, 0},                              // c7
    {-kMin, kMin, -kMin1, kMin1},              // c8
};

const char* kVsQuad = "vs_2_0\ndcl_position v0\ndcl_texcoord v3\nmov oPos, v0\nmov oT0, v3\n";
const char* kVsC0 = "vs_2_0\ndcl_position v0\nmov oPos, v0\nmov oT0, c0\n";
const char* kPsT0 = "ps_2_0\ndcl t0\nmov oC0, t0\n";
const char* kVs11 = "vs.1.1\ndcl_position v0\nmov oPos, v0\n";

struct Case {
  std::string name, vs, ps;
  cpu::Vec4 expect; // lavapipe and the interpreter under Rounding::Llvmpipe, bit for bit
  bool texture = false;
  cpu::Filter filter = cpu::Filter::Point;
  img::Format format = img::Format::RGBA32F;
  // The sign of a zero that interpolation produces is not compared: lavapipe's per-quad plane
  // evaluation gives −0 at some pixels for −0 and −denormal inputs alike, which the CPU
  // device's interpolation does not reproduce (a sign-of-zero matter, not a denormal one).
  bool zero_sign_free = false;
};

std::string ps(const std::string& body) {
  return "ps_2_0\n" + body + "\nmov oC0, r0\n";
}
std::string vs(const std::string& body) {
  return "vs_2_0\ndcl_position v0\nmov oPos, v0\n" + body + "\nmov oT0, r0\n";
}

// clang-format off
const std::vector<Case>& cases() {
  static const std::vector<Case> c = {
    // Data movement keeps the bits.
    {"mov", kVsQuad, "ps_2_0\nmov oC0, c0\n", {kD, -kD, kT, -kT}},
    {"negate", kVsQuad, ps("mov r0, -c0"), {-kD, kD, -kT, kT}},
    {"abs", kVsQuad, ps("abs r0, c0"), {kD, kD, kT, kT}},
    // Operands: −1e-40 + 0 is (−0) + (+0) = +0, so the input was flushed, not the result.
    {"add_zero", kVsQuad, ps("add r0, c0, c1.w"), {0, 0, 0, 0}},
    {"add_flt_min", kVsQuad, ps("add r0, c0, c1.z"), {kMin, kMin, kMin, kMin}},
    // Results: (FLT_MIN + 2^-148) − FLT_MIN = ±2^-148 becomes the zero of its sign.
    {"add_denormal_result", kVsQuad, ps("add r0, c4, c8"), {0, -0.0f, -0.0f, 0}},
    {"mul", kVsQuad, ps("mul r0, c0, c1.x"), {0, 0, 0, 0}},
    {"mul_denormal_result", kVsQuad, ps("mul r0, c3, c3.x"), {0, -0.0f, 0, 0}},
    // mad's product 2^-140 is flushed before the sum (not fused, rule 14).
    {"mad", kVsQuad, ps("mad r0, c3, c3.x, c1.z"), {kMin, kMin, kMin, kMin}},
    // The issue-16 cases: rcp/rsq/log of ±denormal are those of ±0 (rules 1, 3, 5).
    {"rcp", kVsQuad, ps("rcp r0.x, c0.x\nrcp r0.y, c0.y\nrcp r0.z, c0.z\nrcp r0.w, c0.w"), {kM, kM, kM, kM}},
    {"rsq", kVsQuad, ps("rsq r0.x, c0.x\nrsq r0.y, c0.y\nrsq r0.z, c0.z\nrsq r0.w, c0.w"), {kM, kM, kM, kM}},
    {"log", kVsQuad, ps("log r0.x, c0.x\nlog r0.y, c0.y\nlog r0.z, c0.z\nlog r0.w, c0.w"), {-kM, -kM, -kM, -kM}},
    {"exp", kVsQuad, ps("exp r0.x, c0.x\nexp r0.y, c2.x\nexp r0.z, c2.y\nexp r0.w, c2.z"), {1, 0, 0, 0}},
    {"pow", kVsQuad, ps("pow r0.x, c0.x, c2.w\npow r0.y, c0.y, c2.w\npow r0.z, c3.x, c1.w\npow r0.w, c0.x, c1.x"), {0, 0, 1, 0}},
    {"dp3", kVsQuad, ps("dp3 r0, c0, c1.x"), {0, 0, 0, 0}},
    // 2^-140 + 2^-140 + 2^-150 + 2^-120: every product below 2^-126 is flushed.
    {"dp4", kVsQuad, ps("dp4 r0.x, c0, c0\ndp4 r0.y, c3, c3\ndp4 r0.z, c3, -c3\ndp4 r0.w, c0.y, c1.w"), {0, 0x1p-120f, -0x1p-120f, 0}},
    {"cmp_condition", kVsQuad, ps("cmp r0, c0, c5.x, c5.y"), {1, 1, 1, 1}},
    {"cmp_passes_bits", kVsQuad, ps("cmp r0, c5.x, c0, c5.y"), {kD, -kD, kT, -kT}},
    {"cmp_self", kVsQuad, ps("def c10, -1, -1, -1, -1\ncmp r0, c0, c0, c10"), {kD, -kD, kT, -kT}},
    {"min_zero", kVsQuad, ps("min r0, c0, c1.w"), {0, 0, 0, 0}},
    {"min_passes_bits", kVsQuad, ps("min r0, c0, c5.x"), {kD, -kD, kT, -kT}},
    {"max_zero", kVsQuad, ps("max r0, c0, c1.w"), {kD, -kD, kT, -kT}},
    {"max_def", kVsQuad, ps("def c10, -1, -1, -1, -1\nmax r0, c0, c10"), {kD, -kD, kT, -kT}},
    // frc(−1e-40) is frc(−0) = 0, not the IEEE 1.0 of rule 22.
    {"frc", kVsQuad, ps("frc r0, c0"), {0, 0, 0, 0}},
    {"lrp", kVsQuad, ps("mov r1, c5.x\nlrp r0, r1, c0, c1.w"), {0, 0, 0, 0}},
    {"sat", kVsQuad, ps("mov_sat r0, c0"), {0, 0, 0, 0}},
    {"sincos", kVsQuad, ps("def c20, -1.5500992e-006, -2.1701389e-005, 0.0026041667, 0.00026041668\n"
                           "def c21, -0.020833334, -0.12500000, 1.0, 0.50000000\n"
                           "mov r0, c5.y\nmov r1, c0\nsincos r0.xy, r1.y, c20, c21"), {1, -0.0f, -1, -1}},
    {"dp2add", kVsQuad, ps("mov r1, c5.x\ndp2add r0, c0, r1, c1.w"), {0, 0, 0, 0}},
    {"store_rgba16f", kVsQuad, "ps_2_0\nmov oC0, c0\n", {0, -0.0f, 0, -0.0f}, false, cpu::Filter::Point, img::Format::RGBA16F},
    // def constants load flushed (rule 13; lavapipe would otherwise fold them unflushed).
    {"def_mov", kVsQuad, "ps_2_0\ndef c10, 1e-40, -1e-40, 0, 0\nmov oC0, c10\n", {0, -0.0f, 0, 0}},
    {"def_rcp", kVsQuad, ps("def c10, 1e-40, -1e-40, 0, 0\nmov r0, c5\nrcp r0.x, c10.x\nrcp r0.y, c10.y"), {kM, kM, 2, 0.5f}},
    {"def_rsq_log", kVsQuad, ps("def c10, 1e-40, -1e-40, 0, 0\nrsq r0.x, c10.x\nrsq r0.y, c10.y\nlog r0.z, c10.x\nlog r0.w, c10.y"), {kM, kM, -kM, -kM}},
    {"def_through_register", kVsQuad, ps("def c10, 1e-40, -1e-40, 0, 0\nmul r1, c10, c5.x\nmov r0, c5\nrcp r0.x, r1.x\nrcp r0.y, r1.y"), {kM, kM, 2, 0.5f}},
    // Textures (RGBA32F texels c0): point sampling moves bits, bilinear filtering computes.
    {"texel", kVsQuad, "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n", {kD, -kD, kT, -kT}, true},
    {"texel_mul", kVsQuad, "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmul r0, r0, c1.x\nmov oC0, r0\n", {0, 0, 0, 0}, true},
    {"texel_rcp", kVsQuad, "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r1, t0, s0\nrcp r0.x, r1.x\nrcp r0.y, r1.y\nrcp r0.z, r1.z\nrcp r0.w, r1.w\nmov oC0, r0\n", {kM, kM, kM, kM}, true},
    {"texel_bilinear", kVsQuad, "ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n", {0, 0, 0, 0}, true, cpu::Filter::Linear},
    // Interpolated inputs: the plane equation's arithmetic flushes (and −0 + 0 = +0).
    {"interpolated", kVsC0, kPsT0, {0, 0, 0, 0}, false, cpu::Filter::Point, img::Format::RGBA32F, true},
    {"interpolated_rcp", kVsC0, ps("dcl t0\nrcp r0.x, t0.x\nrcp r0.y, t0.y\nrcp r0.z, t0.z\nrcp r0.w, t0.w"), {kM, kM, kM, kM}},
    {"texkill", kVsC0, "ps_2_0\ndcl t0\ntexkill t0\nmov oC0, c5\n", {1, -1, 2, 0.5f}},
    // The vertex stage (results read through the interpolator).
    {"vs_rcp", vs("rcp r0.x, c0.x\nrcp r0.y, c0.y\nrcp r0.z, c0.z\nrcp r0.w, c0.w"), kPsT0, {kM, kM, kM, kM}},
    {"vs_slt", vs("slt r0, c0, c1.w"), kPsT0, {0, 0, 0, 0}},
    {"vs_sge", vs("sge r0, c0, c1.w"), kPsT0, {1, 1, 1, 1}},
    {"vs_slt_reversed", vs("slt r0, c1.w, c0"), kPsT0, {0, 0, 0, 0}},
    {"vs_sgn", vs("sgn r0, c0, r1, r2"), kPsT0, {0, 0, 0, 0}},
    {"vs_frc", vs("frc r0, c0"), kPsT0, {0, 0, 0, 0}},
    {"vs_lit", vs("lit r0, c6"), kPsT0, {1, 0, 0, 1}},
    {"vs_mova", vs("mova a0.x, c0.y\nmov r0, c[a0.x + 5]"), kPsT0, {1, -1, 2, 0.5f}},
    {"vs11_mov_a0", "vs_1_1\ndcl_position v0\nmov oPos, v0\nmov a0.x, c0.y\nmov r0, c[a0.x + 5]\nmov oT0, r0\n", kPsT0, {1, -1, 2, 0.5f}},
    {"vs11_expp", "vs_1_1\ndcl_position v0\nmov oPos, v0\nexpp r0, c0.y\nmov oT0, r0\n", kPsT0, {1, 0, 1, 1}},
    // ps_1_x: the constant clamp and the register range compile to min/max, which flush.
    {"ps11_mov", kVs11, "ps.1.1\nmov r0, c0\n", {0, -0.0f, 0, -0.0f}},
    {"ps11_add", kVs11, "ps.1.1\nadd r0, c0, c7\n", {0, 0, 0, 0}},
    {"ps14_mov", kVs11, "ps.1.4\nmov r0, c0\n", {0, -0.0f, 0, -0.0f}},
    {"ps14_cnd", kVs11, "ps.1.4\ncnd r0, c5.x, c0, c5.y\n", {0, -0.0f, 0, -0.0f}},
  };
  return c;
}
// clang-format on

img::Image draw_case(const Case& c, const std::function<bool(cpu::Pass&, img::Image&)>& draw,
                     ir::Rounding rounding) {
  cpu::Pass p;
  p.vertex_program = parse_listing(c.vs, c.name + ".vsh");
  p.pixel_program = parse_listing(c.ps, c.name + ".psh");
  img::Image out(2, 2, c.format);
  if (!p.vertex_program || !p.pixel_program) return out;
  p.vs_constants.f = kConsts;
  p.ps_constants.f = kConsts;
  cpu::set_full_screen_quad(p, 0);
  for (size_t i = 0; i < p.vertices.size(); ++i) p.vertices[i].v[3] = cpu::kQuadUV[i];
  if (c.texture) {
    auto t = std::make_shared<img::Image>(1, 1);
    t->rgba = {kD, -kD, kT, -kT};
    p.textures[0].image = t;
    p.textures[0].sampler.filter = c.filter;
    p.textures[0].sampler.address_u = p.textures[0].sampler.address_v = cpu::AddressMode::Clamp;
  }
  p.conventions.pixel_center = ir::PixelCenter::Modern;
  p.conventions.rounding = rounding;
  EXPECT_TRUE(draw(p, out)) << c.name;
  return out;
}

void expect_bits(const img::Image& im, const cpu::Vec4& want, const std::string& what,
                 bool zero_sign_free = false) {
  auto key = [&](float x) { return zero_sign_free && x == 0.0f ? 0u : bits(x); };
  for (size_t px = 0; px < 4; ++px)
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(key(im.rgba[px * 4 + k]), key(want[k]))
          << what << " pixel " << px << " channel " << k << ": got " << im.rgba[px * 4 + k]
          << ", want " << want[k];
}

TEST_F(VulkanTest, DenormalsOnLavapipeAndTheInterpreterBitForBit) {
  const bool lavapipe = dev->name().find("llvmpipe") != std::string::npos;
  for (const Case& c : cases()) {
    img::Image cpu_img = draw_case(
        c, [](cpu::Pass& p, img::Image& o) { return cpu::draw(p, o, 1).ok(); },
        ir::Rounding::Llvmpipe);
    expect_bits(cpu_img, c.expect, "interpreter " + c.name);
    if (!lavapipe) continue; // another driver may keep denormals (see the test below)
    img::Image vk_img = draw_case(
        c, [&](cpu::Pass& p, img::Image& o) { return dev->draw(p, o).ok(); },
        ir::Rounding::Llvmpipe);
    expect_bits(vk_img, c.expect, "lavapipe " + c.name, c.zero_sign_free);
  }
}

// Rounding::Exact is IEEE: denormals in and out, and rule 22's literal frc.
TEST(DenormalsExact, InterpreterKeepsDenormals) {
  auto run = [](const char* name) {
    for (const Case& c : cases())
      if (c.name == name)
        return draw_case(
            c, [](cpu::Pass& p, img::Image& o) { return cpu::draw(p, o, 1).ok(); },
            ir::Rounding::Exact);
    ADD_FAILURE() << name;
    return img::Image(1, 1);
  };
  volatile float d = kD; // keeps the compiler from folding the IEEE references
  expect_bits(run("add_zero"), {kD, -kD, kT, -kT}, "exact add");
  expect_bits(run("rcp"), {kM, -kM, kM, -kM}, "exact rcp"); // 1/±1e-40 overflows: rule 2
  expect_bits(run("rsq"), {1.0f / std::sqrt(d), 1.0f / std::sqrt(d), 0x1p70f, 0x1p70f},
              "exact rsq");
  expect_bits(run("frc"), {kD, 1, kT, 1}, "exact frc");
  expect_bits(run("def_mov"), {kD, -kD, 0, 0}, "exact def");
  expect_bits(run("texel_bilinear"), {kD, -kD, kT, -kT}, "exact bilinear");
  const img::Image lg = run("log");
  EXPECT_NEAR(lg.rgba[0], std::log2(1e-40), 1e-4);
  EXPECT_EQ(lg.rgba[2], -140.0f);
}

// The probe the differential harness uses agrees with the table above.
TEST_F(VulkanTest, DenormalProbeOfEachDevice) {
  if (dev->name().find("llvmpipe") != std::string::npos) {
    EXPECT_TRUE(flushes(*dev));
  }
}

} // namespace
} // namespace tierlift::vulkan::test
