// BoundTextures' block read: the block executor's texture instructions sample all their lanes
// through one call. Each lane goes through the steps of sample() for that lane — the same
// functions (sampling_rules.h, address_texel) on the same values — without the virtual call,
// the optionals and the Vec4 returns, and the point and llvmpipe bilinear loops are built a
// second time for AVX2 + FMA (std::floor and std::fma become single instructions there; both
// round exactly as the baseline's libm calls do, so the result is the same bit for bit).
#include <climits>

#include "sampling_rules.h"
#include "simd_rgba.h"
#include "tierlift/cpu/texture.h"

namespace tierlift::cpu {
namespace {

// The texel index after addressing, −1 for the border colour (address_texel, with its first
// rule — an index inside the texture stays itself — taken inline).
inline int64_t texel_index(AddressMode mode, int64_t i, uint32_t n) {
  if (i >= 0 && i < static_cast<int64_t>(n)) return i;
  const std::optional<int64_t> a = address_texel(mode, i, n);
  return a ? *a : -1;
}

inline const float* texel(const img::Image& im, const SamplerState& s, int64_t i, int64_t j) {
  if (i < 0 || j < 0) return s.border_color.data();
  return im.at(static_cast<uint32_t>(i), static_cast<uint32_t>(j));
}

struct BlockRead {
  const img::Image& im;
  const SamplerState& s;
  const float* u;
  const float* v;
  int n;
  Lanes* out;
};

// sample_texture's point read, lanes first..last−1.
[[gnu::always_inline]] inline void point_body(const BlockRead& r, int first, int last) {
  for (int l = first; l < last; ++l) {
    const int64_t i =
        texel_index(r.s.address_u, detail::point_texel(r.u[l], r.im.width), r.im.width);
    const int64_t j =
        texel_index(r.s.address_v, detail::point_texel(r.v[l], r.im.height), r.im.height);
    const float* p = texel(r.im, r.s, i, j);
    for (int c = 0; c < 4; ++c) r.out[c][l] = p[c];
  }
}

// sample_texture_llvmpipe's bilinear read, lanes first..last−1.
[[gnu::always_inline]] inline void llvmpipe_linear_body(const BlockRead& r, int subtexel_bits,
                                                        int first, int last) {
  for (int l = first; l < last; ++l) {
    const detail::LinearAxis x =
        detail::llvmpipe_linear_axis(r.u[l], r.im.width, r.s.address_u, subtexel_bits);
    const detail::LinearAxis y =
        detail::llvmpipe_linear_axis(r.v[l], r.im.height, r.s.address_v, subtexel_bits);
    const int64_t u0 = texel_index(r.s.address_u, x.i0, r.im.width);
    const int64_t u1 = texel_index(r.s.address_u, x.i0 + 1, r.im.width);
    const int64_t v0 = texel_index(r.s.address_v, y.i0, r.im.height);
    const int64_t v1 = texel_index(r.s.address_v, y.i0 + 1, r.im.height);
    const float *t00 = texel(r.im, r.s, u0, v0), *t10 = texel(r.im, r.s, u1, v0);
    const float *t01 = texel(r.im, r.s, u0, v1), *t11 = texel(r.im, r.s, u1, v1);
    for (int c = 0; c < 4; ++c)
      r.out[c][l] = detail::llvmpipe_lerp(y.alpha, detail::llvmpipe_lerp(x.alpha, t00[c], t10[c]),
                                          detail::llvmpipe_lerp(x.alpha, t01[c], t11[c]));
  }
}

void point_plain(const BlockRead& r) {
  point_body(r, 0, r.n);
}
void llvmpipe_linear_plain(const BlockRead& r, int bits) {
  llvmpipe_linear_body(r, bits, 0, r.n);
}

#if TIERLIFT_CPU_AVX2
// The AVX2 build runs eight lanes at a time where every lane's texels lie inside the texture
// on both axes (the common case), and sends any group of eight with one lane outside, and
// the lanes past the last full group, through the per-lane bodies above. Inside the texture
// each step below is the per-lane step on the same values, so the results are the same bits:
// u·N in float is fl32 of the exact double product texel_space takes (a float times an
// integer < 2^24 is exact in double, and both round it once); floor and truncation agree on
// values ≥ 0; address_texel leaves indices inside the texture alone (Clamp's right-hand
// neighbour is min(i0 + 1, N − 1), what address_texel gives); the lerp is rounding::lerp on
// eight lanes of a channel at once (flush, subtract, flush, one fused multiply-add, flush).
// Texels are loaded as one RGBA vector each and transposed into channel vectors.
using detail::load_rgba8;
using detail::transpose8;
constexpr int kGroup = 8;

// A texture whose float offsets 4·(y·W + x) fit an int32: every image the readers accept.
bool int32_texels(const img::Image& im) {
  return uint64_t{im.width} * im.height * 4 <= uint64_t{INT32_MAX};
}

[[gnu::target("avx2,fma")]] inline __m256 flush8(__m256 v) {
  const __m256i bits = _mm256_castps_si256(v);
  const __m256i exponent = _mm256_and_si256(bits, _mm256_set1_epi32(0x7F800000));
  const __m256 zero_exponent =
      _mm256_castsi256_ps(_mm256_cmpeq_epi32(exponent, _mm256_setzero_si256()));
  const __m256 sign = _mm256_castsi256_ps(_mm256_and_si256(bits, _mm256_set1_epi32(INT32_MIN)));
  return _mm256_blendv_ps(v, sign, zero_exponent);
}

// rounding::lerp on eight lanes of one channel (flush, subtract, flush, one fused
// multiply-add, flush): the per-lane lerp on the same values, eight at once.
[[gnu::target("avx2,fma")]] inline __m256 lerp8(__m256 alpha, __m256 v0, __m256 v1) {
  v0 = flush8(v0);
  v1 = flush8(v1);
  return flush8(_mm256_fmadd_ps(alpha, flush8(_mm256_sub_ps(v1, v0)), v0));
}

// lerp8 without its flushes, for groups whose texels pass smooth_texels below.
[[gnu::target("avx2,fma")]] inline __m256 lerp8_exact(__m256 alpha, __m256 v0, __m256 v1) {
  return _mm256_fmadd_ps(alpha, _mm256_sub_ps(v1, v0), v0);
}

// Whether no texel value of the four channel vectors of each of t[0..3] is a nonzero of
// magnitude below 2^-40 (±0, ±∞ and NaN pass). Then none of lerp8's four flushes can change a
// value, and lerp8_exact gives the same bits. Why: a finite texel v with |v| ≥ 2^-40 is a
// multiple of 2^-63 (its ulp is at least 2^-40-23), and so is 0. A bilinear weight is a
// multiple of 2^-24 in [0, 1]: it is x − floor(x), exact, of x = fl(u·N) − ½ after the
// clamp, and x is a multiple of 2^-24 (below 1 it is fl(u·N) − ½ exactly, with fl(u·N) in
// [½, 1½) a multiple of 2^-24; from 1 up its ulp is at least 2^-23); the sub-texel
// quantisation rounds it to a multiple of 2^-bits, or leaves it past 24 bits. So, for finite
// values:
//  - the texels are not denormal;
//  - v1 − v0 is a multiple of 2^-63, and rounding it to float keeps that (below 2^-39 it is
//    exact, above it the ulp is coarser), so it is 0 or at least 2^-63 in magnitude;
//  - α·(v1 − v0) + v0 is a multiple of 2^-87 before its one rounding and after it, the same
//    way: 0 or at least 2^-87;
//  - the second lerp on two such values: difference a multiple of 2^-87, result a multiple
//    of 2^-111, 0 or at least 2^-111.
// Nothing is below 2^-126, the smallest normal float. A flush leaves ±∞ and NaN alone
// (texels, or a step that overflows), so every step after them is the same either way.
[[gnu::target("avx2,fma")]] inline bool smooth_texels(const __m256 (*t)[4]) {
  // (bits << 1) − 1 as an unsigned number: the sign dropped, ±0 wrapped to the largest value.
  // A nonzero below 2^-40 is exactly one whose number is below that of 2^-40.
  const __m256i one = _mm256_set1_epi32(1);
  __m256i least = _mm256_set1_epi32(-1);
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 4; ++c)
      least = _mm256_min_epu32(
          least, _mm256_sub_epi32(_mm256_slli_epi32(_mm256_castps_si256(t[k][c]), 1), one));
  const __m256i limit = _mm256_set1_epi32(static_cast<int32_t>((0x2B800000u << 1) - 1)); // 2^-40
  const __m256i ok = _mm256_cmpeq_epi32(_mm256_max_epu32(least, limit), least);
  return _mm256_movemask_ps(_mm256_castsi256_ps(ok)) == 0xFF;
}

// The RGBA texels at float offsets o[0..7] as four channel vectors (lane k: texel k): texels
// k and k + 4 share a 256-bit row, and a 4×4 transpose within each 128-bit half does the rest.
[[gnu::target("avx2,fma")]] inline void channels8(const float* base, const int32_t* o,
                                                  __m256 c[4]) {
  __m256 t[4];
  for (int k = 0; k < 4; ++k)
    t[k] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(base + o[k])),
                                _mm_loadu_ps(base + o[k + 4]), 1);
  transpose8(t[0], t[1], t[2], t[3], c);
}

// Four RGBA texels (lanes l..l+3) into the lane arrays.
[[gnu::target("avx2,fma")]] inline void put4(__m128 t0, __m128 t1, __m128 t2, __m128 t3, Lanes* out,
                                             int l) {
  _MM_TRANSPOSE4_PS(t0, t1, t2, t3);
  _mm_storeu_ps(out[0] + l, t0);
  _mm_storeu_ps(out[1] + l, t1);
  _mm_storeu_ps(out[2] + l, t2);
  _mm_storeu_ps(out[3] + l, t3);
}

// One axis of eight lanes: whether all lie inside (point) and their indices.
[[gnu::target("avx2,fma")]] inline int point_axis(const float* u, uint32_t n, __m256i& index) {
  const __m256 size = _mm256_set1_ps(static_cast<float>(n));
  const __m256 x = _mm256_mul_ps(_mm256_loadu_ps(u), size);
  const __m256 inside = _mm256_and_ps(_mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_GE_OQ),
                                      _mm256_cmp_ps(x, size, _CMP_LT_OQ));
  // Outside lanes convert 0 instead (their group is not used): no undefined conversion.
  index = _mm256_cvttps_epi32(_mm256_and_ps(x, inside));
  return _mm256_movemask_ps(inside);
}

[[gnu::target("avx2,fma")]] void point_fma(const BlockRead& r) {
  if (!int32_texels(r.im)) return point_body(r, 0, r.n);
  const float* base = r.im.rgba.data();
  const __m256i width = _mm256_set1_epi32(static_cast<int32_t>(r.im.width));
  int l = 0;
  for (; l + kGroup <= r.n; l += kGroup) {
    __m256i i, j;
    const int in_u = point_axis(r.u + l, r.im.width, i);
    const int in_v = point_axis(r.v + l, r.im.height, j);
    if ((in_u & in_v) != 0xFF) {
      point_body(r, l, l + kGroup);
      continue;
    }
    const __m256i at = _mm256_slli_epi32(_mm256_add_epi32(_mm256_mullo_epi32(j, width), i), 2);
    const __m256i first = _mm256_broadcastd_epi32(_mm256_castsi256_si128(at));
    if (_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(
            at, _mm256_add_epi32(first, _mm256_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28))))) ==
        0xFF) {
      // Eight texels side by side (a pass reading its source one to one): four wide loads.
      __m256 c[4];
      load_rgba8(base + _mm256_cvtsi256_si32(at), c);
      for (int ch = 0; ch < 4; ++ch) _mm256_storeu_ps(r.out[ch] + l, c[ch]);
      continue;
    }
    alignas(32) int32_t o[kGroup];
    _mm256_store_si256(reinterpret_cast<__m256i*>(o), at);
    for (int k = 0; k < kGroup; k += 4)
      put4(_mm_loadu_ps(base + o[k]), _mm_loadu_ps(base + o[k + 1]), _mm_loadu_ps(base + o[k + 2]),
           _mm_loadu_ps(base + o[k + 3]), r.out, l + k);
  }
  point_body(r, l, r.n);
}

// One bilinear axis of eight lanes (rounding::linear_axis and address_texel): left (top)
// index, its right (bottom) neighbour, the weight, and the lanes that need no other address
// rule than Clamp's right edge. Under Clamp x lies in [0, N − ½], so i0 lies inside; under
// the other modes a lane is inside when 0 ≤ x < N − 1 (NaN and the ±2^40 clamp lie outside).
[[gnu::target("avx2,fma")]] inline int linear_axis8(const float* u, uint32_t n, AddressMode mode,
                                                    __m256i& i0, __m256i& i1, __m256& alpha) {
  const __m256 size = _mm256_set1_ps(static_cast<float>(n));
  const __m256 zero = _mm256_setzero_ps();
  __m256 x = _mm256_mul_ps(_mm256_loadu_ps(u), size);
  int inside = 0xFF;
  if (mode == AddressMode::Clamp) {
    x = _mm256_blendv_ps(size, x, _mm256_cmp_ps(x, size, _CMP_LT_OQ));
    x = _mm256_sub_ps(x, _mm256_set1_ps(0.5f));
    x = _mm256_blendv_ps(zero, x, _mm256_cmp_ps(x, zero, _CMP_GT_OQ));
  } else {
    x = _mm256_sub_ps(x, _mm256_set1_ps(0.5f));
    const __m256 in =
        _mm256_and_ps(_mm256_cmp_ps(x, zero, _CMP_GE_OQ),
                      _mm256_cmp_ps(x, _mm256_sub_ps(size, _mm256_set1_ps(1.0f)), _CMP_LT_OQ));
    x = _mm256_and_ps(x, in);
    inside = _mm256_movemask_ps(in);
  }
  const __m256 f = _mm256_floor_ps(x);
  alpha = _mm256_sub_ps(x, f);
  i0 = _mm256_cvttps_epi32(f);
  i1 = _mm256_min_epi32(_mm256_add_epi32(i0, _mm256_set1_epi32(1)),
                        _mm256_set1_epi32(static_cast<int32_t>(n) - 1));
  return inside;
}

// detail::llvmpipe_linear_axis's sub-texel quantisation, lane by lane.
[[gnu::target("avx2,fma")]] inline __m256 quantize8(__m256 alpha, int bits) {
  if (bits <= 0) return alpha;
  alignas(32) float a[kGroup];
  _mm256_store_ps(a, alpha);
  for (float& v : a) v = static_cast<float>(quantize_fraction(v, bits));
  return _mm256_load_ps(a);
}

// The float offsets 4·(row + i) of eight texels.
[[gnu::target("avx2,fma")]] inline void offset(int32_t* o, __m256i row, __m256i i) {
  _mm256_store_si256(reinterpret_cast<__m256i*>(o), _mm256_slli_epi32(_mm256_add_epi32(row, i), 2));
}

[[gnu::target("avx2,fma")]] void llvmpipe_linear_fma(const BlockRead& r, int bits) {
  if (!int32_texels(r.im)) return llvmpipe_linear_body(r, bits, 0, r.n);
  const float* base = r.im.rgba.data();
  const __m256i width = _mm256_set1_epi32(static_cast<int32_t>(r.im.width));
  int l = 0;
  for (; l + kGroup <= r.n; l += kGroup) {
    __m256i i0, i1, j0, j1;
    __m256 ax, ay;
    const int in_u = linear_axis8(r.u + l, r.im.width, r.s.address_u, i0, i1, ax);
    const int in_v = linear_axis8(r.v + l, r.im.height, r.s.address_v, j0, j1, ay);
    if ((in_u & in_v) != 0xFF) {
      llvmpipe_linear_body(r, bits, l, l + kGroup);
      continue;
    }
    alignas(32) int32_t o00[kGroup], o10[kGroup], o01[kGroup], o11[kGroup];
    const __m256i row0 = _mm256_mullo_epi32(j0, width), row1 = _mm256_mullo_epi32(j1, width);
    offset(o00, row0, i0);
    offset(o10, row0, i1);
    offset(o01, row1, i0);
    offset(o11, row1, i1);
    ax = quantize8(ax, bits);
    ay = quantize8(ay, bits);
    __m256 t[4][4]; // texels 00, 10, 01, 11
    channels8(base, o00, t[0]);
    channels8(base, o10, t[1]);
    channels8(base, o01, t[2]);
    channels8(base, o11, t[3]);
    if (smooth_texels(t)) {
      for (int c = 0; c < 4; ++c)
        _mm256_storeu_ps(r.out[c] + l, lerp8_exact(ay, lerp8_exact(ax, t[0][c], t[1][c]),
                                                   lerp8_exact(ax, t[2][c], t[3][c])));
    } else {
      for (int c = 0; c < 4; ++c)
        _mm256_storeu_ps(r.out[c] + l,
                         lerp8(ay, lerp8(ax, t[0][c], t[1][c]), lerp8(ax, t[2][c], t[3][c])));
    }
  }
  llvmpipe_linear_body(r, bits, l, r.n);
}
#else
void point_fma(const BlockRead& r) {
  point_body(r, 0, r.n);
}
void llvmpipe_linear_fma(const BlockRead& r, int bits) {
  llvmpipe_linear_body(r, bits, 0, r.n);
}
#endif

// Whether a lane's coordinate is one llvmpipe cannot address under a mode other than Clamp
// (detail::llvmpipe_unaddressable): those lanes take the per-lane read and its rule.
bool unaddressable_lane(const TextureBinding& b, const float* const coord[4], int n) {
  const SamplerState& s = b.sampler;
  const auto axis = [&](const float* c, uint32_t size, AddressMode mode) {
    if (mode == AddressMode::Clamp) return false;
    for (int l = 0; l < n; ++l)
      if (detail::llvmpipe_unaddressable(c[l], size, mode, s.filter).kind !=
          detail::UnaddressableAxis::Kind::Ordinary)
        return true;
    return false;
  };
  return axis(coord[0], b.image->width, s.address_u) ||
         axis(coord[1], b.image->height, s.address_v);
}

} // namespace

void BoundTextures::sample_block(uint32_t stage, const float* const coord[4], const float* bias,
                                 int n, Lanes out[4]) const {
  if (stage >= bindings_.size() || !bindings_[stage].image || bindings_[stage].image->width == 0 ||
      bindings_[stage].image->height == 0 ||
      bindings_[stage].shape != pass::TextureShape::Tex2D || // cubes and volumes: per lane
      bindings_[stage].levels.size() > 1) {                  // mip chains: sample() picks the level
    TextureUnit::sample_block(stage, coord, bias, n, out);   // the rare cases, lane by lane
    return;
  }
  const TextureBinding& b = bindings_[stage];
  if (llvmpipe_ && unaddressable_lane(b, coord, n)) {
    TextureUnit::sample_block(stage, coord, bias, n, out); // sample_texture_llvmpipe's rule
    return;
  }
  const BlockRead r{*b.image, b.sampler, coord[0], coord[1], n, out};
  const bool fma = cpu_runs_avx2_fma();
  if (b.sampler.filter == Filter::Point) {
    fma ? point_fma(r) : point_plain(r);
  } else if (llvmpipe_) {
    fma ? llvmpipe_linear_fma(r, subtexel_bits_) : llvmpipe_linear_plain(r, subtexel_bits_);
  } else {
    for (int l = 0; l < n; ++l) {
      const Vec4 v = sample_texture(*b.image, b.sampler, coord[0][l], coord[1][l], subtexel_bits_);
      for (int c = 0; c < 4; ++c) out[c][l] = v[c];
    }
  }
}

} // namespace tierlift::cpu
