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

vulkan::Device* lavapipe() {
  ir::Result<vulkan::Device*> d = vulkan::process_device({});
  return d ? *d : nullptr;
}

// `tierlift test --generate 200 --profile ps_2_0 --seed 3`, case 00075, reduced: abs of a
// constant vector with a NaN in z came back unchanged from lavapipe (G: −inf, not inf) while
// GLSL FAbs was the emitted form (codegen SpirvArith::abs now clears the sign bit).
TEST(LavapipeWorkarounds, AbsOfAConstantVectorHoldingNan) {
  vulkan::Device* device = lavapipe();
  if (!device) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  StageOptions o;
  o.device = device;
  for (const char* text : {"ps_2_0\ndef c2, inf, -inf, 0x7fc00000, 0.5\nabs r7, c2\nmov oC0, r7\n",
                           "ps_2_0\ndef c2, 1, -2, 0x7fc00000, 0.5\nmov r0, c2\nabs r7, r0\n"
                           "mov oC0, r7\n"}) {
    const CaseResult r = run_listing("abs", "abs.psh", text, o);
    ASSERT_EQ(r.stages.back().stage, kStageDiff);
    EXPECT_EQ(r.stages.back().verdict, Verdict::Pass) << text << r.stages.back().message;
  }
}

// `tierlift test --generate 200 --profile vs_2_0 --seed 1`, case 00126, reduced: sgn of a def
// holding inf, −inf and NaN, through lrp into oD0. lavapipe folded the constant expression to
// a different alpha than it computes at run time (1 where the interpreter, and lavapipe on the
// same values from a uniform, give 0). The differential run's modules read such a def from the
// uniform block (codegen::CodegenOptions::non_finite_defs_in_block).
TEST(LavapipeWorkarounds, SgnOfADefHoldingNonFiniteValues) {
  vulkan::Device* device = lavapipe();
  if (!device) TIERLIFT_SKIP_UNLESS_REQUIRED(::tierlift::test::kRequireVulkan, "no Vulkan device");
  StageOptions o;
  o.device = device;
  const char* text = "vs_2_0\ndcl_position v0\ndef c2, inf, -inf, 0x7fc00000, 0.5\nrep i0\n"
                     "endrep\nsgn r2, c2, r0, r2\nlrp r1, c0, r2, c0\nmov oPos, c0\n"
                     "mov oD0, r1\n";
  // The case's id: the inputs the reducer kept it failing on (they are seeded by the id).
  const CaseResult r =
      run_listing("generated/vs_2_0/seed1/00126@aef80c19a15f8799", "sgn.vsh", text, o);
  ASSERT_EQ(r.stages.back().stage, kStageDiff);
  EXPECT_EQ(r.stages.back().verdict, Verdict::Pass) << r.stages.back().message;
}

} // namespace
} // namespace tierlift::corpus
