// Internal: what the AVX2 + FMA builds of the CPU device's block loops share (which build
// runs: cpu_runs_avx2_fma in tierlift/cpu/cpu_features.h): eight RGBA pixels stored one after
// another (32 floats, as img::Image and the textures hold them) to and from four channel
// vectors (lane k: pixel k), as the block executor's lanes hold them.
#pragma once

#include "tierlift/cpu/cpu_features.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define TIERLIFT_CPU_AVX2 1
#else
#define TIERLIFT_CPU_AVX2 0
#endif

namespace tierlift::cpu::detail {

#if TIERLIFT_CPU_AVX2
// Four vectors, vector k holding pixel k in its low half and pixel k + 4 in its high half, as
// four channel vectors: a 4×4 transpose within each 128-bit half.
[[gnu::target("avx2,fma")]] inline void transpose8(__m256 t0, __m256 t1, __m256 t2, __m256 t3,
                                                   __m256 c[4]) {
  const __m256 xy01 = _mm256_unpacklo_ps(t0, t1), zw01 = _mm256_unpackhi_ps(t0, t1);
  const __m256 xy23 = _mm256_unpacklo_ps(t2, t3), zw23 = _mm256_unpackhi_ps(t2, t3);
  c[0] = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(1, 0, 1, 0));
  c[1] = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(3, 2, 3, 2));
  c[2] = _mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(1, 0, 1, 0));
  c[3] = _mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(3, 2, 3, 2));
}

// The eight RGBA pixels at p as four channel vectors: four wide loads, pixels k and k + 4
// paired, then transpose8.
[[gnu::target("avx2,fma")]] inline void load_rgba8(const float* p, __m256 c[4]) {
  const __m256 p01 = _mm256_loadu_ps(p), p23 = _mm256_loadu_ps(p + 8);
  const __m256 p45 = _mm256_loadu_ps(p + 16), p67 = _mm256_loadu_ps(p + 24);
  transpose8(_mm256_permute2f128_ps(p01, p45, 0x20), _mm256_permute2f128_ps(p01, p45, 0x31),
             _mm256_permute2f128_ps(p23, p67, 0x20), _mm256_permute2f128_ps(p23, p67, 0x31), c);
}

// Four channel vectors as the eight RGBA pixels at p: load_rgba8 backwards.
[[gnu::target("avx2,fma")]] inline void store_rgba8(const __m256 c[4], float* p) {
  const __m256 rg0 = _mm256_unpacklo_ps(c[0], c[1]), rg1 = _mm256_unpackhi_ps(c[0], c[1]);
  const __m256 ba0 = _mm256_unpacklo_ps(c[2], c[3]), ba1 = _mm256_unpackhi_ps(c[2], c[3]);
  // Pixels 0|4, 1|5, 2|6, 3|7 (low half | high half), then in order.
  const __m256 p04 = _mm256_shuffle_ps(rg0, ba0, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 p15 = _mm256_shuffle_ps(rg0, ba0, _MM_SHUFFLE(3, 2, 3, 2));
  const __m256 p26 = _mm256_shuffle_ps(rg1, ba1, _MM_SHUFFLE(1, 0, 1, 0));
  const __m256 p37 = _mm256_shuffle_ps(rg1, ba1, _MM_SHUFFLE(3, 2, 3, 2));
  _mm256_storeu_ps(p, _mm256_permute2f128_ps(p04, p15, 0x20));
  _mm256_storeu_ps(p + 8, _mm256_permute2f128_ps(p26, p37, 0x20));
  _mm256_storeu_ps(p + 16, _mm256_permute2f128_ps(p04, p15, 0x31));
  _mm256_storeu_ps(p + 24, _mm256_permute2f128_ps(p26, p37, 0x31));
}
#endif

} // namespace tierlift::cpu::detail
