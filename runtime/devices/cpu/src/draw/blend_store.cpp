// Blending on the stored destination value, then the format's store rule. Two ways, chosen by
// ir::Conventions::rounding: Exact blends in float and rounds once (img::quantize); Llvmpipe
// reproduces lavapipe, which converts the source to UNORM8 first and blends in 8-bit integers,
// and stores RGBA16F rounded toward zero.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "raster.h"
#include "simd_rgba.h"
#include "tierlift/cpu/draw.h"
#include "tierlift/rounding/rounding.h"

namespace tierlift::cpu {
namespace {

float clamp01(float v) {
  return v > 0 ? (v < 1 ? v : 1) : 0;
} // NaN → 0

// The blend equation of one channel in float (a: the source alpha).
inline float blend_equation(BlendMode mode, float s, float a, float d) {
  switch (mode) {
  case BlendMode::Replace: return s;
  case BlendMode::OneOne: return s + d;
  case BlendMode::SrcAlphaOne: return s * a + d;
  case BlendMode::SrcAlphaInvSrcAlpha: return s * a + d * (1.0f - a);
  }
  return s;
}

// RGBA32F's store rule is the identity (img::quantize): each stored value is the blend
// equation itself, written over the destination in place.
template <BlendMode kMode>
void store_block_float32(const LaneVec4& src, const std::array<bool, kBlockLanes>& discarded, int n,
                         float* first) {
  for (int l = 0; l < n; ++l) {
    if (discarded[static_cast<size_t>(l)]) continue;
    float* p = first + 4 * l;
    const float a = src.c[3][l];
    for (int c = 0; c < 4; ++c) p[c] = blend_equation(kMode, src.c[c][l], a, p[c]);
  }
}

Vec4 blend_float(BlendMode mode, img::Format format, const Vec4& src_in, const Vec4& dst,
                 ir::Rounding rounding) {
  Vec4 src = src_in;
  // UNORM attachments clamp the source colour (and so the SRCALPHA factors) to [0, 1]
  // before blending (Vulkan "Blend Operations"; D3D9 hardware does the same).
  if (format == img::Format::RGBA8)
    for (auto& c : src) c = clamp01(c);
  Vec4 out;
  const float a = src[3];
  for (int c = 0; c < 4; ++c) {
    out[c] = blend_equation(mode, src[c], a, dst[c]);
    out[c] = format == img::Format::RGBA16F && rounding == ir::Rounding::Llvmpipe
                 ? rounding::half_toward_zero(out[c])
                 : img::quantize(format, out[c]);
  }
  return out;
}

// llvmpipe's normalised 8-bit product a·b/255: (t + (t >> 8) + 128) >> 8 with t = a·b
// (lp_build_mul_norm, after Jim Blinn). It is the nearest integer to a·b/255 for all but 24
// of the 65536 byte pairs; those 24 are kept as llvmpipe computes them.
int mul_norm8(int a, int b) {
  const int t = a * b;
  return (t + (t >> 8) + 0x80) >> 8;
}

// lavapipe's blend on an R8G8B8A8_UNORM attachment (Mesa llvmpipe's AoS blend): the shader's
// colour is converted with rounding::unorm8_llvmpipe, the destination is read as its byte, factors
// multiply with mul_norm8, the two terms add with saturation at 255. SRC_ALPHA/
// ONE_MINUS_SRC_ALPHA is src·a + dst·(255 − a) with both products rounded separately (not
// llvmpipe's lerp shortcut: measured, the lerp form does not match).
Vec4 blend_unorm8_llvmpipe(BlendMode mode, const Vec4& src_in, const Vec4& dst_in) {
  int src[4], dst[4];
  for (int c = 0; c < 4; ++c) {
    src[c] = rounding::unorm8_llvmpipe(src_in[c]);
    // An RGBA8 target holds k/255: its byte is the exact rounding of value·255.
    dst[c] = static_cast<int>(std::lround(img::quantize(img::Format::RGBA8, dst_in[c]) * 255.0f));
  }
  const int a = src[3];
  Vec4 out;
  for (int c = 0; c < 4; ++c) {
    int v = 0;
    switch (mode) {
    case BlendMode::Replace: v = src[c]; break;
    case BlendMode::OneOne: v = src[c] + dst[c]; break;
    case BlendMode::SrcAlphaOne: v = mul_norm8(src[c], a) + dst[c]; break;
    case BlendMode::SrcAlphaInvSrcAlpha:
      v = mul_norm8(src[c], a) + mul_norm8(dst[c], 255 - a);
      break;
    }
    out[c] = static_cast<float>(std::min(v, 255)) / 255.0f;
  }
  return out;
}

// blend_unorm8_llvmpipe on lane arrays, for every blend mode, on machines without AVX2 + FMA
// (store_unorm8_llvmpipe_avx2 below is the same store for the others): the source bytes,
// then the destination's (Replace reads none; read before any lane is written, a block's
// pixels being distinct), then the same integer blend, each byte's value k/255.0f (what
// rounding::unorm8_levels holds, computed the same way) and the write. The result is the
// same bits as blend_unorm8_llvmpipe pixel by pixel (BlockBlendMatchesThePixelRule in
// tests/cpu_draw/rgba8_store_llvmpipe_test.cpp, and the block executor's identity tests).
void store_block_unorm8_llvmpipe(BlendMode mode, const LaneVec4& src,
                                 const std::array<bool, kBlockLanes>& discarded, int n, float* p) {
  int32_t s[4][kBlockLanes];
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < n; ++l) s[c][l] = rounding::unorm8_llvmpipe_lane(src.c[c][l]);
  if (mode != BlendMode::Replace) {
    int32_t d[4][kBlockLanes];
    for (int l = 0; l < n; ++l)
      for (int c = 0; c < 4; ++c) d[c][l] = rounding::unorm8_nearest_lane(p[4 * l + c]);
    // The blend per mode and channel over the lanes. Channel 3 goes last, in place: the
    // others read its source byte as the alpha factor.
    const int32_t* a = s[3];
    for (int c = 0; c < 4; ++c) {
      int32_t* v = s[c];
      const int32_t* e = d[c];
      switch (mode) {
      case BlendMode::Replace: break;
      case BlendMode::OneOne:
        for (int l = 0; l < n; ++l) v[l] += e[l];
        break;
      case BlendMode::SrcAlphaOne:
        for (int l = 0; l < n; ++l) v[l] = mul_norm8(v[l], a[l]) + e[l];
        break;
      case BlendMode::SrcAlphaInvSrcAlpha:
        for (int l = 0; l < n; ++l) v[l] = mul_norm8(v[l], a[l]) + mul_norm8(e[l], 255 - a[l]);
        break;
      }
    }
  }
  float out[4][kBlockLanes];
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < n; ++l) out[c][l] = static_cast<float>(std::min(s[c][l], 255)) / 255.0f;
  bool any_discarded = false;
  for (int l = 0; l < n; ++l) any_discarded |= discarded[static_cast<size_t>(l)];
  if (!any_discarded) { // the usual block: one interleaving loop the compiler vectorises
    for (int l = 0; l < n; ++l)
      for (int c = 0; c < 4; ++c) p[4 * l + c] = out[c][l];
    return;
  }
  for (int l = 0; l < n; ++l) {
    if (discarded[static_cast<size_t>(l)]) continue;
    for (int c = 0; c < 4; ++c) p[4 * l + c] = out[c][l];
  }
}

#if TIERLIFT_CPU_AVX2
using detail::load_rgba8;
using detail::store_rgba8;

// k/255.0f for the integer-valued floats k = 0..255, without a division: the product with
// fl(1/255), then one correction by its exact residual k − q·255 (both steps fused). For all
// 256 values it is k/255 correctly rounded, the same float as the division (worked out for
// each k, and BlockBlendMatchesThePixelRule stores every level through it).
[[gnu::target("avx2,fma")]] inline __m256 unorm8_levels8(__m256 k) {
  const __m256 inverse = _mm256_set1_ps(1.0f / 255.0f);
  const __m256 q = _mm256_mul_ps(k, inverse);
  const __m256 residual = _mm256_fnmadd_ps(q, _mm256_set1_ps(255.0f), k);
  return _mm256_fmadd_ps(residual, inverse, q);
}

// rounding::unorm8_llvmpipe_lane on eight lanes: max with 0 (NaN and −0 give 0), min with 1,
// the fl32 product with 255, nearest-even rounding with the mode in the instruction (not
// MXCSR's), then the integer.
[[gnu::target("avx2,fma")]] inline __m256i source_bytes8(__m256 v) {
  const __m256 t = _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
  return _mm256_cvttps_epi32(_mm256_round_ps(_mm256_mul_ps(t, _mm256_set1_ps(255.0f)),
                                             _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC));
}

// rounding::unorm8_nearest_lane on four lanes, in double as it is: max with 0 (NaN gives 0),
// min with 1, ·255 (exact), + ½, truncation.
[[gnu::target("avx2,fma")]] inline __m128i nearest_bytes4(__m128 v) {
  const __m256d t =
      _mm256_min_pd(_mm256_max_pd(_mm256_cvtps_pd(v), _mm256_setzero_pd()), _mm256_set1_pd(1.0));
  return _mm256_cvttpd_epi32(
      _mm256_add_pd(_mm256_mul_pd(t, _mm256_set1_pd(255.0)), _mm256_set1_pd(0.5)));
}
[[gnu::target("avx2,fma")]] inline __m256i nearest_bytes8(__m256 v) {
  return _mm256_set_m128i(nearest_bytes4(_mm256_extractf128_ps(v, 1)),
                          nearest_bytes4(_mm256_castps256_ps128(v)));
}

// mul_norm8 on eight lanes (a·b ≥ 0, so the shifts are the same logical or arithmetic).
[[gnu::target("avx2,fma")]] inline __m256i mul_norm8_8(__m256i a, __m256i b) {
  const __m256i t = _mm256_mullo_epi32(a, b);
  return _mm256_srli_epi32(
      _mm256_add_epi32(_mm256_add_epi32(t, _mm256_srli_epi32(t, 8)), _mm256_set1_epi32(0x80)), 8);
}

// store_block_unorm8_llvmpipe eight lanes at a time: the same bytes and blend step by step,
// the destination's eight RGBA pixels read with four wide loads and split into channels, the
// results interleaved back with four wide stores (a group with a killed lane is written
// pixel by pixel, its killed pixels left alone).
[[gnu::target("avx2,fma")]] void
store_unorm8_llvmpipe_avx2(BlendMode mode, const LaneVec4& src,
                           const std::array<bool, kBlockLanes>& discarded, int n, float* p) {
  const __m256i max_byte = _mm256_set1_epi32(255);
  int l = 0;
  for (; l + 8 <= n; l += 8) {
    float* px = p + 4 * l;
    __m256i v[4];
    for (int c = 0; c < 4; ++c) v[c] = source_bytes8(_mm256_loadu_ps(src.c[c] + l));
    if (mode != BlendMode::Replace) {
      __m256 dst[4];
      load_rgba8(px, dst);
      const __m256i a = v[3], inverse_a = _mm256_sub_epi32(max_byte, a);
      for (int c = 0; c < 4; ++c) {
        const __m256i d = nearest_bytes8(dst[c]);
        switch (mode) {
        case BlendMode::Replace: break;
        case BlendMode::OneOne: v[c] = _mm256_add_epi32(v[c], d); break;
        case BlendMode::SrcAlphaOne: v[c] = _mm256_add_epi32(mul_norm8_8(v[c], a), d); break;
        case BlendMode::SrcAlphaInvSrcAlpha:
          v[c] = _mm256_add_epi32(mul_norm8_8(v[c], a), mul_norm8_8(d, inverse_a));
          break;
        }
      }
    }
    __m256 c[4];
    for (int k = 0; k < 4; ++k)
      c[k] = unorm8_levels8(_mm256_cvtepi32_ps(_mm256_min_epi32(v[k], max_byte)));
    static_assert(sizeof(bool) == 1);
    uint64_t killed; // the group's eight flags at once
    std::memcpy(&killed, &discarded[static_cast<size_t>(l)], sizeof killed);
    if (killed == 0) {
      store_rgba8(c, px);
      continue;
    }
    alignas(32) float out[32];
    store_rgba8(c, out);
    for (int k = 0; k < 8; ++k)
      if (!discarded[static_cast<size_t>(l + k)]) std::memcpy(px + 4 * k, out + 4 * k, 16);
  }
  for (; l < n; ++l) { // the tail, pixel by pixel through the rule
    if (discarded[static_cast<size_t>(l)]) continue;
    float* px = p + 4 * l;
    const Vec4 out = blend_unorm8_llvmpipe(
        mode, {src.c[0][l], src.c[1][l], src.c[2][l], src.c[3][l]}, {px[0], px[1], px[2], px[3]});
    std::copy(out.begin(), out.end(), px);
  }
}

#else
void store_unorm8_llvmpipe_avx2(BlendMode, const LaneVec4&, const std::array<bool, kBlockLanes>&,
                                int, float*) {}
#endif

} // namespace

Vec4 blend_and_store(BlendMode mode, img::Format format, const Vec4& src, const Vec4& dst,
                     ir::Rounding rounding) {
  if (format == img::Format::RGBA8 && rounding == ir::Rounding::Llvmpipe)
    return blend_unorm8_llvmpipe(mode, src, dst);
  return blend_float(mode, format, src, dst, rounding);
}

namespace detail {

void store_block(BlendMode mode, img::Format format, ir::Rounding rounding, const LaneVec4& src,
                 const std::array<bool, kBlockLanes>& discarded, int64_t x0, int n, float* row) {
  float* first = row + 4 * x0;
  if (format == img::Format::RGBA32F) {
    switch (mode) {
    case BlendMode::Replace:
      return store_block_float32<BlendMode::Replace>(src, discarded, n, first);
    case BlendMode::OneOne: return store_block_float32<BlendMode::OneOne>(src, discarded, n, first);
    case BlendMode::SrcAlphaOne:
      return store_block_float32<BlendMode::SrcAlphaOne>(src, discarded, n, first);
    case BlendMode::SrcAlphaInvSrcAlpha:
      return store_block_float32<BlendMode::SrcAlphaInvSrcAlpha>(src, discarded, n, first);
    }
  }
  if (format == img::Format::RGBA8 && rounding == ir::Rounding::Llvmpipe) {
    if (cpu_runs_avx2_fma()) return store_unorm8_llvmpipe_avx2(mode, src, discarded, n, first);
    return store_block_unorm8_llvmpipe(mode, src, discarded, n, first);
  }
  for (int l = 0; l < n; ++l) {
    if (discarded[static_cast<size_t>(l)]) continue;
    float* p = first + 4 * l;
    const Vec4 v =
        blend_and_store(mode, format, {src.c[0][l], src.c[1][l], src.c[2][l], src.c[3][l]},
                        {p[0], p[1], p[2], p[3]}, rounding);
    std::copy(v.begin(), v.end(), p);
  }
}

} // namespace detail
} // namespace tierlift::cpu
