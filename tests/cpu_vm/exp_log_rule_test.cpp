// NUMERICS.md rule 40: exp2 and log2 (exp, log, pow, lit, expp, logp). Rounding::Exact takes
// the C library's exp2f/log2f; Rounding::Llvmpipe lavapipe's polynomials (rounding.h), which
// tests/vulkan/exp_log_llvmpipe_test.cpp holds to lavapipe bit for bit. Here: the model's
// distance from the exact functions (computed in double, independently of the model), values
// worked out by hand (each float step of the model redone in double and rounded), the edge
// cases, and that the interpreter follows its convention.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "tierlift/rounding/rounding.h"
#include "vm_test_util.h"

using namespace vmtest;
namespace rd = tierlift::rounding;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(ExpLogRule, Exp2ModelIsWithinThreeAndAHalfUlpsOfTheExactFunction) {
  // 2^22 evenly spread arguments over [−126, 128), where 2^x is a normal float; the error
  // in units of the last place of the exact value.
  constexpr int kSteps = 1 << 22;
  double worst = 0;
  for (int i = 0; i < kSteps; ++i) {
    const float x = static_cast<float>(-126.0 + 254.0 * i / kSteps);
    const double exact = std::exp2(static_cast<double>(x));
    const double ulp = std::ldexp(1.0, std::ilogb(exact) - 23);
    worst = std::max(worst, std::fabs(rd::exp2_llvmpipe(x) - exact) / ulp);
  }
  std::printf("[exp2 model] worst error on [-126, 128): %.3f ulp\n", worst);
  EXPECT_LT(worst, 3.5); // measured: 3.03 ulp
  EXPECT_GT(worst, 1.0); // not the correctly rounded function: that is the point of the rule
}

TEST(ExpLogRule, Log2ModelIsWithinTwoUlpsOfTheExactFunction) {
  // Every 64th positive normal float (2^25 of them, FLT_MIN to FLT_MAX): the error in units of
  // the last place of the exact value, but never units below 2^-23: just under 1 the model adds
  // the exponent −1 to a mantissa term near 1, and that sum cancels to an absolute error.
  double worst = 0;
  float worst_at = 0;
  for (uint32_t u = 0x00800000u; u < 0x7F800000u; u += 64) {
    const float x = std::bit_cast<float>(u);
    const double exact = std::log2(static_cast<double>(x));
    const double ulp = std::ldexp(1.0, std::max(exact == 0 ? 0 : std::ilogb(exact), 0) - 23);
    const double error = std::fabs(rd::log2_llvmpipe(x) - exact) / ulp;
    if (error > worst) worst = error, worst_at = x;
  }
  std::printf("[log2 model] worst error over the normal floats: %.3f ulp at %.9g\n", worst,
              worst_at);
  EXPECT_LT(worst, 2.0); // measured: 1.50, at 0.472
}

TEST(ExpLogRule, HandWorkedValues) {
  // Each float step of the model redone in double and rounded to float:
  // exp2(0.5) = 1.41421378 (the correctly rounded √2 is 0x3FB504F3, two ulps below),
  // log2(1.9) = 0.925999343, and pow(1.9, 8.3) = 2^fl32(8.3·0.925999343) = 205.899246: the
  // value lavapipe gives for the generated vs_3_0 case (the C library's is 205.899323).
  EXPECT_EQ(bits(rd::exp2_llvmpipe(0.5f)), 0x3FB504F5u);
  EXPECT_EQ(bits(rd::exp2_llvmpipe(2.5f)), 0x40B504F5u);
  EXPECT_EQ(bits(rd::exp2_llvmpipe(0.1f)), 0x3F892FE0u);
  EXPECT_EQ(bits(rd::log2_llvmpipe(1.9f)), 0x3F6D0E4Bu);
  EXPECT_EQ(bits(rd::log2_llvmpipe(10.0f)), 0x40549A78u);
  EXPECT_EQ(bits(tierlift::ir::numerics::rule::pow(
                rd::LlvmpipeArith<tierlift::ir::numerics::Denormals::Flush>{}, 1.9f, 8.3f)),
            0x434DE635u);
}

TEST(ExpLogRule, PowersOfTwoAreExact) {
  for (int k = -126; k <= 127; ++k) {
    EXPECT_EQ(rd::exp2_llvmpipe(static_cast<float>(k)), std::ldexp(1.0f, k)) << k;
    EXPECT_EQ(rd::log2_llvmpipe(std::ldexp(1.0f, k)), static_cast<float>(k)) << k;
  }
}

TEST(ExpLogRule, EdgeCases) {
  // exp2: 128 and above overflow, the clamp at −126.99999 gives 2^−127's exponent field 0.
  EXPECT_EQ(rd::exp2_llvmpipe(128.0f), kInf);
  EXPECT_EQ(rd::exp2_llvmpipe(kInf), kInf);
  EXPECT_EQ(bits(rd::exp2_llvmpipe(-126.5f)), 0u);
  EXPECT_EQ(bits(rd::exp2_llvmpipe(-kInf)), 0u);
  EXPECT_EQ(rd::exp2_llvmpipe(-1e-40f), 1.0f); // a denormal argument is a zero
  EXPECT_EQ(rd::exp2_llvmpipe(0.0f), 1.0f);
  EXPECT_TRUE(std::isnan(rd::exp2_llvmpipe(kNaN)));
  // log2: zeros and denormals −inf, negatives and NaN NaN, +inf +inf.
  for (float z : {0.0f, -0.0f, 1e-40f, -1e-40f}) EXPECT_EQ(rd::log2_llvmpipe(z), -kInf) << z;
  for (float n : {-1.0f, -kInf, kNaN, -kNaN}) EXPECT_TRUE(std::isnan(rd::log2_llvmpipe(n))) << n;
  EXPECT_EQ(rd::log2_llvmpipe(kInf), kInf);
  EXPECT_EQ(rd::log2_llvmpipe(1.0f), 0.0f);
}

TEST(ExpLogRule, TheInterpreterFollowsItsRoundingConvention) {
  // pow, exp and log of the hand-worked arguments, and the D3D9 rules around them.
  const std::string text = "vs_3_0\ndcl_position o0\n"
                           "pow r0.x, c0.x, c0.y\nexp r0.y, c0.z\nlog r0.z, c0.x\n"
                           "pow r0.w, c0.w, c1.x\nmov o0, r0\n";
  const ConstantBank c = bank({{1.9f, 8.3f, 0.5f, -1.9f}, {0.0f, 0, 0, 0}});
  for (auto rounding : {tierlift::ir::Rounding::Llvmpipe, tierlift::ir::Rounding::Exact}) {
    tierlift::ir::Conventions conv;
    conv.rounding = rounding;
    const Vec4 r = run_vs(make_vm(text, conv), {}, c).pos;
    if (rounding == tierlift::ir::Rounding::Exact) {
      EXPECT_EQ(r[0], std::exp2(8.3f * std::log2(1.9f)));
      EXPECT_EQ(r[1], std::exp2(0.5f));
      EXPECT_EQ(r[2], std::log2(1.9f));
    } else {
      EXPECT_EQ(bits(r[0]), 0x434DE635u);
      EXPECT_EQ(bits(r[1]), 0x3FB504F5u);
      EXPECT_EQ(bits(r[2]), 0x3F6D0E4Bu);
    }
    EXPECT_EQ(r[3], 1.0f); // rule 16: pow(x, 0) = 1 under both
  }
}

} // namespace
