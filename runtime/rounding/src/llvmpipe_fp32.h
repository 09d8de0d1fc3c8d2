// The fp32 operations of llvmpipe's shader code, as the lavapipe models (sincos.cpp,
// exp2_log2.cpp) build their polynomials from them.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "tierlift/rounding/rounding.h"

namespace tierlift::rounding::llvmpipe_fp32 {

// llvmpipe builds its constants from doubles: each is the double rounded to float.
constexpr float single(double d) {
  return static_cast<float>(d);
}

// Each operation reads and writes denormals as zeros (NUMERICS.md rule 13).
inline float mul(float a, float b) {
  return flush(flush(a) * flush(b));
}
inline float add(float a, float b) {
  return flush(flush(a) + flush(b));
}
inline float sub(float a, float b) {
  return flush(flush(a) - flush(b));
}
inline float divide(float a, float b) {
  return flush(flush(a) / flush(b));
}
inline float fused(float a, float b, float c) { // llvm.fmuladd, one FMA on an x86-64 with FMA3
  return flush(std::fma(flush(a), flush(b), flush(c)));
}

// cvttps2dq: truncation toward zero; NaN and values out of the int32 range give INT32_MIN.
inline int32_t truncate_x86(float y) {
  if (!(y > -2147483904.0f && y < 2147483648.0f)) return std::numeric_limits<int32_t>::min();
  return static_cast<int32_t>(y);
}

} // namespace tierlift::rounding::llvmpipe_fp32
