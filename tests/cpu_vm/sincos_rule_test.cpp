// NUMERICS.md rule 39: sincos's sine and cosine. Rounding::Exact takes the double sin/cos of
// the float, rounded once; Rounding::Llvmpipe lavapipe's polynomial (rounding.h), which
// tests/vulkan/sincos_llvmpipe_test.cpp holds to lavapipe bit for bit. Here: the model's
// distance from the exact functions on [−π, π] (computed in double, independently of the
// model), values worked out by hand, and that the interpreter follows its convention.
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

#include "tierlift/rounding/rounding.h"
#include "vm_test_util.h"

using namespace vmtest;
namespace rd = tierlift::rounding;

namespace {

constexpr float kPi = static_cast<float>(std::numbers::pi);

TEST(SincosRule, LlvmpipeModelIsWithinTwoToTheMinus23OfTheExactFunctions) {
  // 2^22 evenly spread floats over [−π, π] (the range Direct3D 9 defines sincos on).
  constexpr int kSteps = 1 << 22;
  double worst = 0;
  size_t differ = 0;
  for (int i = 0; i <= kSteps; ++i) {
    const float x = static_cast<float>(-std::numbers::pi + 2 * std::numbers::pi * i / kSteps);
    const double s = std::sin(static_cast<double>(x)), c = std::cos(static_cast<double>(x));
    worst =
        std::max({worst, std::fabs(rd::sin_llvmpipe(x) - s), std::fabs(rd::cos_llvmpipe(x) - c)});
    differ += rd::sin_llvmpipe(x) != static_cast<float>(s);
    ASSERT_EQ(rd::sin_exact(x), static_cast<float>(s)) << x;
    ASSERT_EQ(rd::cos_exact(x), static_cast<float>(c)) << x;
  }
  EXPECT_LE(worst, 0x1p-23);
  EXPECT_GT(differ, size_t{1000}); // a different function, not the exact one rounded
}

TEST(SincosRule, LlvmpipeModelByHand) {
  const float inf = std::numeric_limits<float>::infinity();
  // 0: octant j = 0, r = 0: sin = 0 + 0 = 0, cos = 1 − 0 + 0 = 1.
  EXPECT_EQ(std::bit_cast<uint32_t>(rd::sin_llvmpipe(0.0f)), 0u);
  EXPECT_EQ(rd::cos_llvmpipe(0.0f), 1.0f);
  // −0 and −1e-40 (flushed): sin keeps a's sign bit, −0.
  EXPECT_EQ(std::bit_cast<uint32_t>(rd::sin_llvmpipe(-0.0f)), 0x80000000u);
  EXPECT_EQ(std::bit_cast<uint32_t>(rd::sin_llvmpipe(-1e-40f)), 0x80000000u);
  EXPECT_EQ(rd::cos_llvmpipe(1e-40f), 1.0f);
  // fl32(π/2) = 1.57079637: |a|·fl32(4/π) = 2.0000002 truncates to 2, j = (2 + 1) & ~1 = 2,
  // r = a − 2·π/4 = −4.4e-8, so sin takes the cosine polynomial: 1 − r²/2 = 1 in float.
  EXPECT_EQ(rd::sin_llvmpipe(kPi / 2), 1.0f);
  // ±inf and NaN give NaN.
  for (float a : {inf, -inf, std::numeric_limits<float>::quiet_NaN()}) {
    EXPECT_TRUE(std::isnan(rd::sin_llvmpipe(a))) << a;
    EXPECT_TRUE(std::isnan(rd::cos_llvmpipe(a))) << a;
  }
  // 3e38·fl32(4/π) is out of the int32 range: octant INT32_MIN, r ≈ 3e38 and z = r² = inf.
  // sin's polynomial goes to −inf (clamped to −1, +1 for −3e38 by a's sign); cos's computes
  // inf − inf = NaN, which the clamp (x86 max, then min) turns into 1.
  EXPECT_EQ(rd::sin_llvmpipe(3e38f), -1.0f);
  EXPECT_EQ(rd::sin_llvmpipe(-3e38f), 1.0f);
  EXPECT_EQ(rd::cos_llvmpipe(3e38f), 1.0f);
  EXPECT_EQ(rd::cos_llvmpipe(-3e38f), 1.0f);
}

TEST(SincosRule, TheInterpreterFollowsItsRoundingConvention) {
  // The first float above 1 where the model and the exact sine part.
  float x = 1.0f;
  while (rd::sin_llvmpipe(x) == static_cast<float>(std::sin(static_cast<double>(x))))
    x = std::nextafter(x, 2.0f);
  ASSERT_LT(x, 2.0f);
  const std::string text = "ps_3_0\nmov r0, c1\nsincos r0.xy, c0.x\nmov oC0, r0\n";
  const ConstantBank c = bank({{x, 0, 0, 0}, {0, 0, 7, 8}});
  for (auto rounding : {tierlift::ir::Rounding::Llvmpipe, tierlift::ir::Rounding::Exact}) {
    tierlift::ir::Conventions conv;
    conv.rounding = rounding;
    const Vec4 r = run_ps(make_vm(text, conv), {}, nullptr, c).color[0];
    const bool exact = rounding == tierlift::ir::Rounding::Exact;
    EXPECT_EQ(r[0],
              exact ? static_cast<float>(std::cos(static_cast<double>(x))) : rd::cos_llvmpipe(x));
    EXPECT_EQ(r[1],
              exact ? static_cast<float>(std::sin(static_cast<double>(x))) : rd::sin_llvmpipe(x));
    EXPECT_EQ(r[2], 7.0f);
  }
}

} // namespace
