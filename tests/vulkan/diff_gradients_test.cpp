// Gradients (dsx, dsy) on 2x2 quads, on the CPU device and lavapipe: against the closed form
// of a linear ramp and of a quadratic of vPos (NUMERICS.md rule F8: fine differences, right
// minus left on the pixel's own row, bottom minus top in its own column), on a full-screen
// quad and on a triangle whose edges cut quads, so that covered pixels take their gradients
// from helper pixels (rule F9); and the two devices bit-identical on gradients of texture
// values, with source modifiers, in loops and in flow that differs across a quad.
#include "diff_harness.h"
#include "tierlift/codegen/codegen.h"

namespace tierlift::vulkan::test {
namespace {

const char* kVs = "vs_3_0\ndcl_position v0\ndcl_texcoord v3\ndcl_position o0\n"
                  "dcl_texcoord0 o1\nmov o0, v0\nmov o1, v3\n";

// One triangle with edges at odd slopes: about half the quads it touches are cut by an edge.
// Its texcoord0 is (x_clip, y_clip), a linear ramp across the target.
void cut_triangle(cpu::Pass& p) {
  const cpu::Vec4 pos[3] = {{-0.95f, 0.9f, 0, 1}, {0.83f, 0.6f, 0, 1}, {-0.6f, -0.87f, 0, 1}};
  p.vertices.assign(3, cpu::VertexInput{});
  for (size_t k = 0; k < 3; ++k) {
    p.vertices[k].v[0] = pos[k];
    p.vertices[k].v[3] = {pos[k][0], pos[k][1], 0, 1};
  }
  p.triangles = {{0, 1, 2}};
}

// x²y of vPos and its fine gradients, and the gradients of vPos itself (a linear ramp):
// oC0 = (dsx x²y, dsy x²y, dsx x, dsy y).
const char* kVposQuadratic = "ps_3_0\ndcl vPos.xy\n"
                             "mul r0, vPos.x, vPos.x\nmul r0, r0, vPos.y\n"
                             "mov r0.z, vPos.x\nmov r0.w, vPos.y\n"
                             "dsx r1, r0\ndsy r2, r0\n"
                             "mov r3.x, r1.x\nmov r3.y, r2.x\nmov r3.z, r1.z\nmov r3.w, r2.w\n"
                             "mov oC0, r3\n";

// Pixel (x, y) in the quad whose top-left pixel is (x0, y0) = (x & ~1, y & ~1):
// dsx x²y = ((x0 + 1)² − x0²)·y = (2·x0 + 1)·y on the pixel's own row, dsy x²y = x² in its
// own column (coarse differences would give (2·x0 + 1)·y0 and x0²); both ramps step by 1.
cpu::Vec4 quadratic_closed_form(uint32_t x, uint32_t y) {
  const float x0 = float(x & ~1u);
  return {(2 * x0 + 1) * float(y), float(x) * float(x), 1.0f, 1.0f};
}

TEST_F(VulkanTest, DsxDsyOfVposMatchTheClosedForm) {
  for (bool triangle : {false, true}) {
    DiffResult r = run_diff_with(*dev, kVs, kVposQuadratic, DiffSetup{}, [&](cpu::Pass& p) {
      if (triangle) cut_triangle(p);
    });
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.diff.max_scaled, 0.0) << r.diff.first_bad;
    int covered = 0;
    for (const img::Image* im : {&r.cpu, &r.vk})
      for (uint32_t y = 0; y < kDiffH; ++y)
        for (uint32_t x = 0; x < kDiffW; ++x) {
          const float* px = im->rgba.data() + 4 * (size_t{y} * kDiffW + x);
          // Uncovered pixels keep the cleared target; every covered one has dsx x = 1.
          if (triangle && px[2] == 0.0f) continue;
          covered += im == &r.cpu;
          const cpu::Vec4 want = quadratic_closed_form(x, y);
          for (int c = 0; c < 4; ++c)
            ASSERT_EQ(px[c], want[size_t(c)])
                << (im == &r.cpu ? "cpu" : "vulkan") << " pixel " << x << "," << y << " ."
                << "xyzw"[c] << (triangle ? " (cut triangle)" : "");
        }
    if (triangle) {
      EXPECT_GT(covered, 40);
    }
  }
}

// The measurement behind rule F8: on lavapipe, OpDPdx/OpDPdy (which Vulkan lets a device make
// coarse or fine) and even OpDPdxCoarse/OpDPdyCoarse give the fine differences: the closed
// form of the fine ones holds on the quads' second row and column, where a coarse difference
// would give (2·x0 + 1)·y0 and x0². The module is the code generator's with its Fine opcodes
// rewritten.
std::vector<uint32_t> with_derivative_ops(std::vector<uint32_t> words, uint32_t dx, uint32_t dy) {
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xFFFFu;
    if (count == 0) break;
    if (op == 210 /* OpDPdxFine */) words[i] = (count << 16) | dx;
    if (op == 211 /* OpDPdyFine */) words[i] = (count << 16) | dy;
    i += count;
  }
  return words;
}

TEST_F(VulkanTest, LavapipeDerivativesAreFineWhateverTheVariant) {
  struct Variant {
    uint32_t dx, dy;
    const char* name;
  };
  for (const Variant v :
       {Variant{207, 208, "OpDPdx/OpDPdy"}, Variant{213, 214, "OpDPdxCoarse/OpDPdyCoarse"}}) {
    cpu::Pass pass;
    pass.vertex_program = parse_listing(kVs, "q.vsh");
    pass.pixel_program = parse_listing(kVposQuadratic, "q.psh");
    ASSERT_TRUE(pass.vertex_program && pass.pixel_program);
    set_geometry(pass, DiffSetup{});
    pass.conventions.pixel_center = ir::PixelCenter::Modern;
    codegen::CodegenOptions co;
    co.conventions = pass.conventions;
    ir::DiagnosticSink diags;
    auto pair = codegen::compile_pair(*pass.vertex_program, *pass.pixel_program, co, diags);
    ASSERT_TRUE(pair);
    pass.pixel_spirv = std::make_shared<const std::vector<uint32_t>>(
        with_derivative_ops(pair->ps.words, v.dx, v.dy));
    img::Image out(kDiffW, kDiffH, img::Format::RGBA32F);
    ir::Result<pass::DrawReport> r = dev->draw(pass, out);
    ASSERT_TRUE(r.ok()) << r.message();
    for (uint32_t y = 0; y < kDiffH; ++y)
      for (uint32_t x = 0; x < kDiffW; ++x) {
        const float* px = out.rgba.data() + 4 * (size_t{y} * kDiffW + x);
        const cpu::Vec4 want = quadratic_closed_form(x, y);
        ASSERT_EQ(px[0], want[0]) << v.name << " " << x << "," << y;
        ASSERT_EQ(px[1], want[1]) << v.name << " " << x << "," << y;
      }
  }
}

// The texcoord ramp u = x_clip, v = y_clip (the full-screen quad given the triangle's texcoord)
// steps by 2/16 per pixel in x and −2/16 in y, and
// u² by (u_right² − u_left²) on the pixel's row: within float rounding of the interpolation on
// both devices, at the cut triangle's edges too.
TEST_F(VulkanTest, DsxDsyOfInterpolatedRampAndSquareMatchTheClosedForm) {
  const char* ps = "ps_3_0\ndcl_texcoord0 v0.xy\n"
                   "mul r0.xy, v0, v0\nmov r0.zw, v0.xyxy\n"
                   "dsx r1, r0\ndsy r2, r0\n"
                   "mov r3.x, r1.x\nmov r3.y, r2.y\nmov r3.z, r1.z\nmov r3.w, r2.w\nmov oC0, r3\n";
  for (bool triangle : {false, true}) {
    DiffResult r = run_diff_with(*dev, kVs, ps, DiffSetup{}, [&](cpu::Pass& p) {
      if (triangle) cut_triangle(p);
      for (cpu::VertexInput& v : p.vertices) v.v[3] = {v.v[0][0], v.v[0][1], 0, 1};
    });
    ASSERT_TRUE(r.ok);
    EXPECT_EQ(r.diff.max_scaled, 0.0) << r.diff.first_bad;
    const double step = 2.0 / kDiffW;
    for (const img::Image* im : {&r.cpu, &r.vk})
      for (uint32_t y = 0; y < kDiffH; ++y)
        for (uint32_t x = 0; x < kDiffW; ++x) {
          const float* px = im->rgba.data() + 4 * (size_t{y} * kDiffW + x);
          if (triangle && px[2] == 0.0f) continue;
          // Pixel centres (Modern) at x + 0.5: u = (x + 0.5)·step − 1, v = 1 − (y + 0.5)·step.
          const double ul = (double(x & ~1u) + 0.5) * step - 1, ur = ul + step;
          const double vt = 1 - (double(y & ~1u) + 0.5) * step, vb = vt - step;
          const char* dev_name = im == &r.cpu ? "cpu" : "vulkan";
          EXPECT_NEAR(px[0], ur * ur - ul * ul, 2e-6) << dev_name << " " << x << "," << y;
          EXPECT_NEAR(px[1], vb * vb - vt * vt, 2e-6) << dev_name << " " << x << "," << y;
          EXPECT_NEAR(px[2], step, 2e-6) << dev_name << " " << x << "," << y;
          EXPECT_NEAR(px[3], -step, 2e-6) << dev_name << " " << x << "," << y;
        }
  }
}

struct GradientCase {
  const char* name;
  const char* body; // reads r0, r1, r2 (s0, s1, s2 at this pixel), c0..c7; writes r4
};

// clang-format off
const GradientCase kGradientCases[] = {
    {"dsx_texture", "dsx r4, r0"},
    {"dsy_texture", "dsy r4, r1"},
    {"dsx_negated_swizzle", "dsx r4, -r2.yxwz"},
    {"dsy_abs_sat_mask", "mov r4, c0\ndsy_sat r4.xz, r0_abs"},
    {"dsx_of_product", "mul r5, r0, r1\nmad r5, r5, r2, c1\ndsx r4, r5"},
    {"dsy_of_dsx", "dsx r5, r0\ndsy r4, r5"},
    {"dsx_in_place", "mov r4, r1\ndsx r4, r4"},
    {"dsx_predicated", "setp_gt p0, r0, r1\nmov r4, c2\n(p0) dsx r4, r2"},
    {"dsy_in_static_loop", "mov r4, r0\nrep i0\ndsy r5, r4\nmad r4, r5, c3, r4\nendrep"},
    // Flow that differs across the quad: the source was written before the branch, so every
    // lane holds it there (NUMERICS.md rule F8); the validator warns. After a texkill the
    // discarded lanes run on as helpers and their r5 enters their neighbours' dsx (rule F9).
    {"dsx_in_divergent_if", "mov r4, c4\nif_lt r0.x, r1.x\ndsx r4, r2\nelse\ndsy r4, r2\nendif"},
    {"dsx_after_texkill", "mov r6, -r1\nif_lt r0.x, c5.x\ntexkill r6\nendif\nmul r5, r0, r2\ndsx r4, r5"},
    {"texldd_level0", "dsx r5, v0\ndsy r6, v0\ntexldd r4, v0, s1, r5, r6\nadd r4, r4, r0"},
};
// clang-format on

std::string gradient_ps(const GradientCase& c) {
  return std::string("ps_3_0\ndefi i0, 3, 0, 0, 0\ndcl_texcoord0 v0\n"
                     "dcl_2d s0\ndcl_2d s1\ndcl_2d s2\n"
                     "texld r0, v0, s0\ntexld r1, v0, s1\ntexld r2, v0, s2\n") +
         c.body + "\nmov oC0, r4\n";
}

FamilyMax g_gradients("ps_3_0 gradients");

class GradientDiff : public VulkanTest, public ::testing::WithParamInterface<GradientCase> {};

// Random texel values make every lane of a quad differ, so a swapped row or column, a coarse
// difference or a helper pixel without its own values shows.
TEST_P(GradientDiff, CpuAndVulkanAgreeBitForBit) {
  const GradientCase& c = GetParam();
  for (uint64_t seed : {1, 2})
    for (bool triangle : {false, true}) {
      DiffSetup s;
      s.seed = seed;
      add_random_textures(s, 3, {});
      s.ps_c = random_constants(seed * 100, 8, {-2, 2, 0.2f});
      DiffResult r = run_diff_with(*dev, kVs, gradient_ps(c), s, [&](cpu::Pass& p) {
        if (triangle) cut_triangle(p);
      });
      const std::string what = fmt::format("{} seed {}{}", c.name, seed, triangle ? " cut" : "");
      expect_agree(r, what, g_gradients);
      EXPECT_EQ(r.diff.max_scaled, 0.0) << what << ": " << r.diff.first_bad;
    }
}

// How a case prints in test listings (GetParam): its name and listing, not its bytes.
void PrintTo(const GradientCase& c, std::ostream* os) {
  *os << c.name << ": " << one_line(c.body);
}

INSTANTIATE_TEST_SUITE_P(Quads, GradientDiff, ::testing::ValuesIn(kGradientCases),
                         [](const auto& info) { return std::string(info.param.name); });

// NUMERICS.md rule F10: texldd reads level 0 whatever its gradients, on both devices and under
// both filters: texldd − texld is 0 at every pixel, with gradients from zero to far beyond the
// texture (a level far down the chain once textures have levels).
TEST_F(VulkanTest, TexlddReadsLevelZeroWhateverTheGradients) {
  const char* ps = "ps_3_0\ndcl_texcoord0 v0\ndcl_2d s0\n"
                   "texld r0, v0, s0\ntexldd r1, v0, s0, c0, c1\nadd oC0, r1, -r0\n";
  for (cpu::Filter filter : {cpu::Filter::Point, cpu::Filter::Linear})
    for (float g : {0.0f, 1.0f / kDiffW, 40.0f}) {
      DiffSetup s;
      add_random_textures(s, 1, {0, 1, 0}); // finite texels: texld − texld is 0
      s.filter = filter;
      s.ps_c = {{g, 0, 0, 0}, {0, g, 0, 0}};
      DiffResult r = run_diff(*dev, kVs, ps, s);
      ASSERT_TRUE(r.ok);
      for (const img::Image* im : {&r.cpu, &r.vk})
        for (size_t k = 0; k < im->rgba.size(); ++k)
          ASSERT_EQ(im->rgba[k], 0.0f)
              << (im == &r.cpu ? "cpu" : "vulkan") << " value " << k << " gradient " << g;
    }
}

} // namespace
} // namespace tierlift::vulkan::test
