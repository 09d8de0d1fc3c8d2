// Rules 8 and 14 with a factor known never to compare equal to zero (numeric_rules.h:
// mul_y_nonzero, mul_x_nonzero, mad_*): the CPU block executor takes them for a constant
// whose component has a non-zero exponent field. They must give mul's and mad's bits for
// every value of the tested factor, under both denormal modes: zeros of both signs,
// denormals (zeros to the Flush mode), products that underflow, NaN and infinities.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>

#include "tierlift/ir/numerics.h"

namespace num = tierlift::ir::numerics;

namespace {

const float kNan = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// The tested factor (and the addend) takes every value the rules treat specially.
const float kAny[] = {0.0f,    -0.0f, 1e-40f, -1e-40f, 0x1p-126f, -0x1p-126f, 1e-30f,
                      -1e-30f, 0.75f, -3.0f,  1e30f,   kNan,      kInf,       -kInf};
// The known factor: a normal number, an infinity or a NaN, never ±0 or a denormal.
const float kNonzero[] = {1e-10f, -1e-10f, 0x1p-126f, 0.5f, -2.0f, 3e38f, kInf, -kInf, kNan};

uint32_t bits(float x) {
  return std::bit_cast<uint32_t>(x);
}

template <num::Denormals D> void check_every_pair() {
  for (float known : kNonzero) {
    ASSERT_NE(bits(known) & 0x7F800000u, 0u); // the precondition, as the executor tests it
    for (float x : kAny) {
      EXPECT_EQ(bits(num::legacy_mul_y_nonzero<D>(x, known)), bits(num::legacy_mul<D>(x, known)))
          << x << " * " << known;
      EXPECT_EQ(bits(num::legacy_mul_x_nonzero<D>(known, x)), bits(num::legacy_mul<D>(known, x)))
          << known << " * " << x;
      for (float z : kAny) {
        EXPECT_EQ(bits(num::legacy_mad_y_nonzero<D>(x, known, z)),
                  bits(num::legacy_mad<D>(x, known, z)))
            << x << " * " << known << " + " << z;
        EXPECT_EQ(bits(num::legacy_mad_x_nonzero<D>(known, x, z)),
                  bits(num::legacy_mad<D>(known, x, z)))
            << known << " * " << x << " + " << z;
      }
    }
  }
}

TEST(NumericsNonzeroFactor, SameBitsAsMulAndMadWhenDenormalsAreKept) {
  check_every_pair<num::kKeep>();
}

TEST(NumericsNonzeroFactor, SameBitsAsMulAndMadWhenDenormalsFlush) {
  check_every_pair<num::kFlush>();
}

// The precondition matters: with a zero or a denormal as the "known" factor the shortcut is
// wrong (0 × inf must be +0, not NaN; under Flush a denormal times inf is +0 too).
TEST(NumericsNonzeroFactor, AZeroFactorBreaksTheShortcut) {
  EXPECT_EQ(bits(num::legacy_mul<num::kKeep>(kInf, 0.0f)), 0u);
  EXPECT_NE(bits(num::legacy_mul_y_nonzero<num::kKeep>(kInf, 0.0f)), 0u);
  EXPECT_EQ(bits(num::legacy_mul<num::kFlush>(kInf, 1e-40f)), 0u);
  EXPECT_NE(bits(num::legacy_mul_y_nonzero<num::kFlush>(kInf, 1e-40f)), 0u);
}

} // namespace
