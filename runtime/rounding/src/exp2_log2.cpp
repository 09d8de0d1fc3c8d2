// exp2 and log2 as lavapipe computes them (rounding.h, NUMERICS.md rule 40).
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "llvmpipe_fp32.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding {
namespace {

using namespace llvmpipe_fp32;

// 2^f ≈ e0 + f·e1 + f²·e2 + … + f⁵·e5 for f in [0, 1) (a minimax fit whose constant term is
// exactly 1, so that 2^integer is exact).
constexpr float kExp[6] = {single(1.0),
                           single(0.693153073200168932794),
                           single(0.240153617044375388211),
                           single(0.0558263180532956664775),
                           single(0.00898934009049466391101),
                           single(0.00187757667519147912699)};
// log2(m) = y·P(y²) with y = (m − 1)/(m + 1), m in [1, 2): P a degree-4 minimax fit of
// log2((1 + √z)/(1 − √z))/√z on [0, 1/9).
constexpr float kLog[5] = {single(2.88539009343309178325), single(0.961791550404184197881),
                           single(0.577440339438736392009), single(0.403343858251329912514),
                           single(0.406718052498846252698)};
// exp2's argument is clamped to [kExpLow, 128]: 2^128 is +inf, and below −127 the integer part
// would leave the exponent field.
constexpr float kExpLow = single(-126.99999);

// gallivm's polynomial evaluation: the even and the odd coefficients each in a Horner chain
// of FMAs in x², then odd·x + even in one more FMA.
template <int N> float polynomial(const float (&c)[N], float x) {
  const float x2 = mul(x, x);
  float even = c[(N - 1) & ~1];
  float odd = c[N % 2 == 0 ? N - 1 : N - 2];
  for (int i = ((N - 1) & ~1) - 2; i >= 0; i -= 2) even = fused(x2, even, c[i]);
  for (int i = (N % 2 == 0 ? N - 1 : N - 2) - 2; i >= 1; i -= 2) odd = fused(x2, odd, c[i]);
  return fused(odd, x, even);
}

} // namespace

float exp2_llvmpipe(float a) {
  float x = flush(a);
  // min(128, x) then max(kExpLow, x), each handing a NaN x on.
  if (x > 128.0f) x = 128.0f;
  if (x < kExpLow) x = kExpLow;
  const float whole = std::floor(x);
  const float fraction = sub(x, whole); // exact
  const uint32_t biased = static_cast<uint32_t>(truncate_x86(whole)) + 127u;
  const float scale = std::bit_cast<float>(biased << 23); // 2^whole; 0 for whole = −127
  return mul(scale, polynomial(kExp, fraction));
}

float log2_llvmpipe(float a) {
  const float x = flush(a); // the compares below read a denormal as zero
  // Measured: a NaN gives NaN (the selects below read it as a negative number).
  if (x < 0.0f || x != x) return std::numeric_limits<float>::quiet_NaN();
  if (x == 0.0f) return -std::numeric_limits<float>::infinity();
  if (x == std::numeric_limits<float>::infinity()) return x;
  // The exponent and the mantissa are read from a's bits (integer operations do not flush).
  const uint32_t bits = std::bit_cast<uint32_t>(a);
  const float exponent = static_cast<float>(static_cast<int32_t>((bits & 0x7F800000u) >> 23) - 127);
  const float m = std::bit_cast<float>((bits & 0x007FFFFFu) | 0x3F800000u); // in [1, 2)
  const float y = divide(sub(m, 1.0f), add(m, 1.0f));
  return fused(y, polynomial(kLog, mul(y, y)), exponent);
}

} // namespace tierlift::rounding
