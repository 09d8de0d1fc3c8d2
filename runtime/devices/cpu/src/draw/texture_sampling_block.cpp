// BoundTextures' block read: the block executor's texture instructions sample all their lanes
// through one call. Each lane goes through the steps of sample() for that lane — the same
// functions (sampling_rules.h, address_texel) on the same values — without the virtual call,
// the optionals and the Vec4 returns, and the point and llvmpipe bilinear loops are built a
// second time for AVX2 + FMA (std::floor and std::fma become single instructions there; both
// round exactly as the baseline's libm calls do, so the result is the same bit for bit).
#include "sampling_rules.h"
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

// sample_texture's point read.
[[gnu::always_inline]] inline void point_body(const BlockRead& r) {
  for (int l = 0; l < r.n; ++l) {
    const int64_t i =
        texel_index(r.s.address_u, detail::point_texel(r.u[l], r.im.width), r.im.width);
    const int64_t j =
        texel_index(r.s.address_v, detail::point_texel(r.v[l], r.im.height), r.im.height);
    const float* p = texel(r.im, r.s, i, j);
    for (int c = 0; c < 4; ++c) r.out[c][l] = p[c];
  }
}

// sample_texture_llvmpipe's bilinear read.
[[gnu::always_inline]] inline void llvmpipe_linear_body(const BlockRead& r, int subtexel_bits) {
  for (int l = 0; l < r.n; ++l) {
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
  point_body(r);
}
void llvmpipe_linear_plain(const BlockRead& r, int bits) {
  llvmpipe_linear_body(r, bits);
}

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2,fma")]] void point_fma(const BlockRead& r) {
  point_body(r);
}
[[gnu::target("avx2,fma")]] void llvmpipe_linear_fma(const BlockRead& r, int bits) {
  llvmpipe_linear_body(r, bits);
}
bool fma_hardware() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}
#else
void point_fma(const BlockRead& r) {
  point_body(r);
}
void llvmpipe_linear_fma(const BlockRead& r, int bits) {
  llvmpipe_linear_body(r, bits);
}
bool fma_hardware() {
  return false;
}
#endif

} // namespace

void BoundTextures::sample_block(uint32_t stage, const float* const coord[4], const float* bias,
                                 int n, Lanes out[4]) const {
  if (stage >= kMaxSamplers || !bindings_[stage].image || bindings_[stage].image->width == 0 ||
      bindings_[stage].image->height == 0) {
    TextureUnit::sample_block(stage, coord, bias, n, out); // the rare cases, lane by lane
    return;
  }
  const TextureBinding& b = bindings_[stage];
  const BlockRead r{*b.image, b.sampler, coord[0], coord[1], n, out};
  const bool fma = fma_hardware();
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
