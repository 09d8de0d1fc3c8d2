// sin and cos: the exact rule and lavapipe's polynomial (rounding.h, NUMERICS.md rule 39).
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "llvmpipe_fp32.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding {
namespace {

using namespace llvmpipe_fp32;

constexpr float kFourOverPi = single(1.27323954473516);
// π/4 in three parts whose products by a small integer are exact (Cody and Waite).
constexpr float kQuarterPi1 = single(0.78515625);
constexpr float kQuarterPi2 = single(2.4187564849853515625e-4);
constexpr float kQuarterPi3 = single(3.77489497744594108e-8);
// cos(r) ≈ 1 − r²/2 + r⁴·(c2 + r²·(c1 + r²·c0)), sin(r) ≈ r + r³·(s2 + r²·(s1 + r²·s0)),
// for |r| ≤ π/4.
constexpr float kCos0 = single(2.443315711809948e-5);
constexpr float kCos1 = single(-1.388731625493765e-3);
constexpr float kCos2 = single(4.166664568298827e-2);
constexpr float kSin0 = single(-1.9515295891e-4);
constexpr float kSin1 = single(8.3321608736e-3);
constexpr float kSin2 = single(-1.6666654611e-1);

// The octant j of |a| (even, the nearest multiple of π/4 at or above a/(π/4) rounded so),
// the reduced argument r = |a| − j·π/4 in [−π/4, π/4], one of the two polynomials by j,
// and the sign from j and a's sign. Unsigned arithmetic wraps as the vector integers do.
float sin_or_cos(float a, bool cosine) {
  const uint32_t bits = std::bit_cast<uint32_t>(a);
  const float x = std::bit_cast<float>(bits & 0x7FFFFFFFu);
  const uint32_t j1 = static_cast<uint32_t>(truncate_x86(mul(x, kFourOverPi))) + 1u;
  const uint32_t j = j1 & ~1u;
  const float jf = static_cast<float>(static_cast<int32_t>(j));
  const uint32_t octant = cosine ? j - 2u : j;
  const uint32_t sign = cosine ? ((~octant & 4u) << 29) : ((bits ^ (j1 << 29)) & 0x80000000u);
  float r = fused(jf, -kQuarterPi1, x);
  r = fused(jf, -kQuarterPi2, r);
  r = fused(jf, -kQuarterPi3, r);
  const float z = mul(r, r);
  float p = 0;
  if ((octant & 2u) == 0) { // the sine polynomial
    p = fused(fused(z, kSin0, kSin1), z, kSin2);
    p = fused(mul(p, z), r, r);
  } else { // the cosine polynomial
    p = fused(fused(z, kCos0, kCos1), z, kCos2);
    p = mul(mul(p, z), z);
    p = add(add(p, -mul(z, 0.5f)), 1.0f);
  }
  float y = std::bit_cast<float>(std::bit_cast<uint32_t>(p) ^ sign);
  // The clamp is x86's max(−1, y) then min(·, 1), each handing on its second operand when one
  // is NaN: a NaN (cos's ∞ − ∞ once |a| is near FLT_MAX) comes out as 1.
  const float low = -1.0f > y ? -1.0f : y;
  y = low < 1.0f ? low : 1.0f;
  return std::isfinite(a) ? y : std::numeric_limits<float>::quiet_NaN();
}

} // namespace

float sin_exact(float a) {
  return static_cast<float>(std::sin(static_cast<double>(a)));
}
float cos_exact(float a) {
  return static_cast<float>(std::cos(static_cast<double>(a)));
}
float sin_llvmpipe(float a) {
  return sin_or_cos(a, false);
}
float cos_llvmpipe(float a) {
  return sin_or_cos(a, true);
}

} // namespace tierlift::rounding
