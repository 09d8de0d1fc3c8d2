// NUMERICS.md rule 38: the differential stage leaves out what Direct3D 9 leaves undefined, a
// pixel program that samples at a non-finite coordinate, and nothing else.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "loaded_listing.h"
#include "skip_policy.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/corpus/undefined_reads.h"
#include "tierlift/vulkan/device.h"
#include "tierlift/vulkan/process_device.h"

namespace tierlift::corpus {
namespace {

std::shared_ptr<const ir::Program> program(const std::string& text) {
  test::LoadedListing l = test::load_bytes(text, "p.psh");
  EXPECT_TRUE(l.r().program) << l.rendered;
  return std::make_shared<const ir::Program>(*l.r().program);
}

// texldp divides t0 by its w: w = 0 makes (0.5/0, 0.25/0) = (inf, inf); 0/0 makes NaN.
pass::Pass projected_pass(float x, float w) {
  pass::Pass p;
  p.pixel_program = program("ps_2_0\ndcl t0\ndcl_2d s0\ntexldp r0, t0, s0\nmov oC0, r0\n");
  p.constant_inputs.tex[0] = {x, 0.25f, 0.0f, w};
  auto im = std::make_shared<img::Image>(4, 4, img::Format::RGBA32F);
  p.textures[0].image = im;
  return p;
}

TEST(UndefinedReads, NonFiniteCoordinateIsNamed) {
  EXPECT_EQ(non_finite_read(projected_pass(0.5f, 0.0f)), "s0 at (inf, inf)");
  EXPECT_EQ(non_finite_read(projected_pass(0.0f, 0.0f)), "s0 at (nan, inf)");
}

// A cube read in direction (0, 0, 0) has no face (NUMERICS.md rule T7); any other finite
// direction, −0 components included, is defined.
TEST(UndefinedReads, ZeroCubeDirectionIsNamed) {
  auto cube_pass = [&](pass::Vec4 dir) {
    pass::Pass p;
    p.pixel_program = program("ps_2_0\ndcl t0\ndcl_cube s0\ntexld r0, t0, s0\nmov oC0, r0\n");
    p.constant_inputs.tex[0] = dir;
    std::vector<std::shared_ptr<const img::Image>> faces(6, std::make_shared<img::Image>(2, 2));
    p.textures[0] = *pass::layered_binding(pass::TextureShape::Cube, faces);
    return p;
  };
  EXPECT_EQ(non_finite_read(cube_pass({0, -0.0f, 0, 1})), "s0 at (0, -0, 0)");
  EXPECT_EQ(non_finite_read(cube_pass({0, 0, 1e-30f, 1})), "");
  EXPECT_EQ(non_finite_read(cube_pass({-0.0f, 2, 0, 0})), "");
}

TEST(UndefinedReads, FiniteCoordinatesAndNoReadsAreDefined) {
  EXPECT_EQ(non_finite_read(projected_pass(0.5f, 2.0f)), "");
  EXPECT_EQ(non_finite_read(projected_pass(1e30f, 1e-30f)), "s0 at (inf, 2.5e+29)");
  pass::Pass plain;
  plain.pixel_program = program("ps_2_0\nmov oC0, c0\n");
  EXPECT_EQ(non_finite_read(plain), "");
}

// A vertex program alone (the differential run's pass of a vs_3_0) is judged at each of its
// vertices: texldl of a vertex sampler at a NaN u is named, a finite one is not.
TEST(UndefinedReads, VertexTextureFetchAtANonFiniteCoordinateIsNamed) {
  auto vertex_pass = [&](float u) {
    pass::Pass p;
    p.vertex_program = program("vs_3_0\ndcl_position v0\ndcl_2d s0\ndcl_position o0\n"
                               "dcl_texcoord0 o1\nmov o0, v0\ntexldl r0, c0, s0\nmov o1, r0\n");
    p.vs_constants.f = {{u, 1, 0, 0}};
    pass::set_full_screen_quad(p, 0);
    p.vertex_textures[0].image = std::make_shared<img::Image>(4, 4, img::Format::RGBA32F);
    return p;
  };
  EXPECT_EQ(non_finite_read(vertex_pass(std::nanf(""))), "vertex s0 at (nan, 1)");
  EXPECT_EQ(non_finite_read(vertex_pass(0.5f)), "");
}

// The interpolated case is outside the rule: a pass with a vertex program excludes nothing.
TEST(UndefinedReads, InterpolatedInputsAreNotJudged) {
  pass::Pass p = projected_pass(0.5f, 0.0f);
  p.vertex_program = program("vs_2_0\ndcl_position v0\nmov oPos, v0\n");
  EXPECT_EQ(non_finite_read(p), "");
}

// sincos outside [−π, π]: the largest |argument| is named, in a pixel program (at its
// constant inputs) and in a vertex program (at each vertex, a subroutine after main's ret).
pass::Pass sincos_pixel_pass(float x) {
  pass::Pass p;
  p.pixel_program = program("ps_2_0\ndef c6, -1.5500992e-06, -2.170139e-05, 0.0026041667, "
                            "0.00026041668\ndef c7, -0.020833334, -0.125, 1, 0.5\n"
                            "mov r0, c6\nmov r1, c1\nsincos r0.xy, r1.y, c6, c7\nmov oC0, r0\n");
  p.ps_constants.f = {{0, 0, 0, 0}, {0, x, 0, 0}};
  return p;
}

TEST(UndefinedReads, SincosOutsideMinusPiToPiIsNamed) {
  EXPECT_EQ(sincos_out_of_range(sincos_pixel_pass(3.0f)), "");
  EXPECT_EQ(sincos_out_of_range(sincos_pixel_pass(-3.14159274f)), ""); // fl32(π): in range
  EXPECT_EQ(sincos_out_of_range(sincos_pixel_pass(4.0f)), "sincos of 4");
  EXPECT_EQ(sincos_out_of_range(sincos_pixel_pass(-1e30f)), "sincos of 1e+30");
  EXPECT_EQ(sincos_out_of_range(sincos_pixel_pass(std::nanf(""))), "sincos of nan");

  pass::Pass v;
  v.vertex_program = program("vs_2_0\ndcl_position v0\ndcl_normal v1\n"
                             "def c6, -1.5500992e-06, -2.170139e-05, 0.0026041667, 0.00026041668\n"
                             "def c7, -0.020833334, -0.125, 1, 0.5\ncall l0\nmov oPos, v0\n"
                             "mov oD0, r5\nret\nlabel l0\nmov r5, c0\n"
                             "sincos r5.xy, v1.x, c6, c7\nret\n");
  v.vertices.resize(3);
  EXPECT_EQ(sincos_out_of_range(v), "");
  v.vertices[1].v[1] = {65504.0f, 0, 0, 0};
  EXPECT_EQ(sincos_out_of_range(v), "sincos of 65504");
}

// Shader model 3's sincos takes one source (a row of its own, SinCos3); the probe missed it,
// and a vs_3_0 writes only declared o#, so its copy declares a spare one as texcoord7 (oT7).
// Generated vs_3_0 case 00201 of `tierlift test --generate 500 --profile vs_3_0 --seed 1`,
// reduced: sin(−1e30) disagreed (interpreter 1, lavapipe 0.79) instead of being left out.
TEST(UndefinedReads, SincosOfShaderModel3IsNamedInBothStages) {
  pass::Pass ps;
  ps.pixel_program = program("ps_3_0\nmov r0, c0\nmov r1, c1\nsincos r0.xy, r1.y\nmov oC0, r0\n");
  ps.ps_constants.f = {{0, 0, 0, 0}, {0, -1e30f, 0, 0}};
  EXPECT_EQ(sincos_out_of_range(ps), "sincos of 1e+30");
  ps.ps_constants.f = {{0, 0, 0, 0}, {0, 2.5f, 0, 0}};
  EXPECT_EQ(sincos_out_of_range(ps), "");

  pass::Pass vs;
  vs.vertex_program = program("vs_3_0\ndcl_position v0\ndcl_normal v1\ndcl_position o0\n"
                              "dcl_color o1\nmov o0, v0\nsincos r6.xy, v1.x\nmov o1, r6.y\n");
  vs.vertices.resize(3);
  EXPECT_EQ(sincos_out_of_range(vs), "");
  vs.vertices[2].v[1] = {-1e30f, 0, 0, 0};
  EXPECT_EQ(sincos_out_of_range(vs), "sincos of 1e+30");
}

vulkan::Device* lavapipe() {
  ir::Result<vulkan::Device*> d = vulkan::process_device({});
  return d ? *d : nullptr;
}

// Generated case 00020 of `tierlift test --generate 500 --profile ps_2_0 --seed 1`, reduced: nrm
// of an infinite vector gives w = 0, which lavapipe's compiler folds into a division by a
// constant zero whose result differs pixel by pixel. Without rule 38 the stage fails.
constexpr const char* kDivideByFoldedZero = R"(ps_2_0
dcl_2d s2
def c2, inf, -inf, 0x7fc00000, 0.5
abs r7, c0
nrm r7.w, c2.x
texldp r6, r7, s2
frc r4, r6
mov oC0, r4
)";

TEST(UndefinedReads, DifferentialStageLeavesTheUndefinedSetsOut) {
  vulkan::Device* device = lavapipe();
  if (!device) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  StageOptions o;
  o.device = device;
  // Modules specialised per input set, c2 a SPIR-V constant: the folding this case was found
  // with. (With one module for all sets the def is read from the uniform block, nothing is
  // folded, and the images agree: below.)
  o.one_pipeline_per_case = false;
  const CaseResult r = run_listing("generated/ps_2_0/seed1/00020", "x.psh", kDivideByFoldedZero, o);
  ASSERT_EQ(r.stages.back().stage, kStageDiff);
  EXPECT_EQ(r.stages.back().verdict, Verdict::Pass) << r.stages.back().message;
  EXPECT_NE(r.stages.back().message.find("not compared: undefined in D3D9 (s2 at (inf, inf))"),
            std::string::npos)
      << r.stages.back().message;

  // The same program with w = 0.5 reads at finite coordinates: compared, and agreeing.
  std::string finite = kDivideByFoldedZero;
  finite.replace(finite.find("nrm r7.w, c2.x"), 14, "mov r7.w, c2.w");
  const CaseResult f = run_listing("generated/ps_2_0/seed1/00020", "x.psh", finite, o);
  EXPECT_EQ(f.stages.back().verdict, Verdict::Pass) << f.stages.back().message;
  EXPECT_EQ(f.stages.back().message, "");
}

// The same case as `tierlift test` runs it (one module for all input sets): the infinite def
// is read from the uniform block (NUMERICS.md, "Lavapipe workarounds"), lavapipe divides at
// run time as the interpreter does, and every set is compared and agrees.
TEST(UndefinedReads, UnfoldedDefsLeaveNothingOut) {
  vulkan::Device* device = lavapipe();
  if (!device) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  StageOptions o;
  o.device = device;
  const CaseResult r = run_listing("generated/ps_2_0/seed1/00020", "x.psh", kDivideByFoldedZero, o);
  ASSERT_EQ(r.stages.back().stage, kStageDiff);
  EXPECT_EQ(r.stages.back().verdict, Verdict::Pass) << r.stages.back().message;
  EXPECT_EQ(r.stages.back().message, "");
}

// Generated case 00044 of `tierlift test --generate 200 --profile vs_2_0 --seed 3`, reduced:
// input sets 1 and 2 give v1.x = 1e30, outside the [−π, π] Direct3D 9 defines sincos on.
// The interpreter's cosine was std::cos there (−0.61 against lavapipe's 1) and the sets were
// left out; it is lavapipe's polynomial now (NUMERICS.md rule 39), so every set is compared
// and agrees, and nothing is left out.
TEST(UndefinedReads, SincosOutOfRangeIsComparedSinceTheDevicesAgree) {
  vulkan::Device* device = lavapipe();
  if (!device) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  StageOptions o;
  o.device = device;
  o.seed = 3;
  const CaseResult r = run_listing("generated/vs_2_0/seed3/00044@8cb7c74a2f28b6e1", "x.vsh",
                                   "vs_2_0\ndcl_position v0\ndcl_normal v1\nmov r5, c0\n"
                                   "sincos r5.x, v1.x, c0, c1\nmov oPos, c0\nmov oD0, r5\n",
                                   o);
  ASSERT_EQ(r.stages.back().stage, kStageDiff);
  EXPECT_EQ(r.stages.back().verdict, Verdict::Pass) << r.stages.back().message;
  EXPECT_EQ(r.stages.back().message, "");
}

} // namespace
} // namespace tierlift::corpus
