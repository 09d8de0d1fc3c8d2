// Cases the generated corpus found where lavapipe computed a wrong value and the SPIR-V now
// takes a form it compiles right; each fails its differential stage without the workaround.
#include <gtest/gtest.h>

#include <string>

#include "skip_policy.h"
#include "tierlift/corpus/stages.h"
#include "tierlift/vulkan/device.h"
#include "tierlift/vulkan/process_device.h"

namespace tierlift::corpus {
namespace {

// The process's Vulkan device; without one every test skips, and fails under
// TIERLIFT_REQUIRE_VULKAN (CI).
class LavapipeWorkarounds : public ::testing::Test {
protected:
  void SetUp() override {
    ir::Result<vulkan::Device*> d = vulkan::process_device({});
    if (!d) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, d.message());
    device = *d;
  }
  vulkan::Device* device = nullptr;
};

// Runs `text` through every stage as case `id` of a run seeded `seed` and expects its
// differential stage to pass. The id and the seed choose the generated inputs: a reduced
// case keeps its id and its run's seed, so it is drawn on the inputs it failed on.
void expect_differential_pass(vulkan::Device& device, const std::string& id, const char* name,
                              const std::string& text, uint64_t seed = 1) {
  StageOptions o;
  o.device = &device;
  o.seed = seed;
  const CaseResult r = run_listing(id, name, text, o);
  ASSERT_EQ(r.stages.back().stage, kStageDiff) << text;
  EXPECT_EQ(r.stages.back().verdict, Verdict::Pass) << text << r.stages.back().message;
}

// `tierlift test --generate 200 --profile ps_2_0 --seed 3`, case 00075, reduced: abs of a
// constant vector with a NaN in z came back unchanged from lavapipe (G: −inf, not inf) while
// GLSL FAbs was the emitted form (codegen SpirvArith::abs now clears the sign bit).
TEST_F(LavapipeWorkarounds, AbsOfAConstantVectorHoldingNan) {
  for (const char* text : {"ps_2_0\ndef c2, inf, -inf, 0x7fc00000, 0.5\nabs r7, c2\nmov oC0, r7\n",
                           "ps_2_0\ndef c2, 1, -2, 0x7fc00000, 0.5\nmov r0, c2\nabs r7, r0\n"
                           "mov oC0, r7\n"})
    expect_differential_pass(*device, "abs", "abs.psh", text);
}

// `tierlift test --generate 200 --profile vs_2_0 --seed 1`, case 00126, reduced: sgn of a def
// holding inf, −inf and NaN, through lrp into oD0. lavapipe folded the constant expression to
// a different alpha than it computes at run time (1 where the interpreter, and lavapipe on the
// same values from a uniform, give 0). The differential run's modules read such a def from the
// uniform block (codegen::CodegenOptions::defs_in_block).
TEST_F(LavapipeWorkarounds, SgnOfADefHoldingNonFiniteValues) {
  expect_differential_pass(*device, "generated/vs_2_0/seed1/00126@aef80c19a15f8799", "sgn.vsh",
                           "vs_2_0\ndcl_position v0\ndef c2, inf, -inf, 0x7fc00000, 0.5\nrep i0\n"
                           "endrep\nsgn r2, c2, r0, r2\nlrp r1, c0, r2, c0\nmov oPos, c0\n"
                           "mov oD0, r1\n");
}

// `tierlift test --generate 3000 --profile vs_3_0 --seed 3`, case 01220, reduced: pow of two
// defs (1e30 to the power −FLT_MIN), less a uniform, then frc. lavapipe's compiler folds exp2
// and log2 of constants with the C library (2^-1.2e-36 = exactly 1) but computes them at run
// time with its own polynomials, which the interpreter follows (NUMERICS.md rule 40: the
// fraction of −1.2e-36 rounds to 1, and 2^-1·P(1) = 1 − 2^-24), and frc showed the last bit.
// The differential run's modules read every def from the uniform block
// (codegen::CodegenOptions::defs_in_block), so nothing of it is folded.
TEST_F(LavapipeWorkarounds, PowOfDefsIsComputedAtRunTime) {
  expect_differential_pass(*device, "generated/vs_3_0/seed3/01220@989330651a2829e0", "pow.vsh",
                           "vs_3_0\ndcl_position v0\ndcl_normal v1\ndcl_color o1\n"
                           "def c1, 1e+30, -1e+30, 1e-40, -1.1754944e-38\npow r7, c1.y, c1\n"
                           "sub r4, r7, c4\nfrc r10, r4.y\nsetp_le p0, v1, r10\n"
                           "(!p0.z) mov r4, c0\nmov o1, r4\n",
                           3);
}

// `tierlift test --generate 300 --profile ps_3_0 --seed 2`, case 00147, reduced: m4x4 of a def
// scalar by def rows, then texkill. Row c1 gives 0.0752·1e30 − 0.0752·1e30 + 0 − 8.8e-40: at
// run time (denormals flushed, rule 13) the last product is −0 and no component is below 0,
// so the pixel stays (the interpreter); folded by lavapipe's compiler, which keeps the
// denormal, it is −8.8e-40 < 0 and the pixel was killed. The differential run's modules read
// every def from the uniform block (codegen::CodegenOptions::defs_in_block), so nothing of it
// is folded.
TEST_F(LavapipeWorkarounds, TexkillOfADenormalFoldedFromDefs) {
  expect_differential_pass(*device, "generated/ps_3_0/seed2/00147@8010c8d0afc25b5e", "kill.psh",
                           "ps_3_0\ndef c0, 0, -0, 1, -1\n"
                           "def c1, 1e+30, -1e+30, 1e-40, -1.1754944e-38\n"
                           "def c3, -1.1994686, 0.07520628, 2.7075415, -0.53357077\n"
                           "m4x4 r7, c3.y, c0\nif b1\ntexkill r7\nendif\nmov oC0, c0\n",
                           2);
}

} // namespace
} // namespace tierlift::corpus
