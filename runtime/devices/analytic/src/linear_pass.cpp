// A pass as math (linear_pass.h): weighted reads over several sampler stages, or the
// rgb × alpha of one read; then the ps_1_x range, the blend and the store, in double.
#include "tierlift/analytic/linear_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "tierlift/analytic/quad_coords.h"
#include "unorm8_store.h"

namespace tierlift::analytic {
namespace {

using Rgba = std::array<double, 4>;

constexpr uint32_t kMaxStages = 16;

double clamp_range(double v, double m) {
  return std::isnan(v) ? v : std::clamp(v, -m, m);
}

// What the pass reads and where it writes, checked once.
struct Setup {
  std::array<const StageTexture*, kMaxStages> stage{};
  uint32_t width = 0, height = 0;
  double ps1x_max = 1;
};

// The model's failures: the pass it was asked for cannot be computed.
ir::Failure fail(std::string message) {
  return ir::fail("analytic", "analytic", std::move(message));
}

ir::Result<Setup> check(const LinearPassInput& in) {
  Setup s;
  s.width = in.model.target_width;
  s.height = in.model.target_height;
  if (!img::valid_size(s.width, s.height)) {
    return fail(fmt::format("target {}x{}: expected 1..{}", s.width, s.height, img::kMaxDimension));
  }
  for (const StageTexture& t : in.textures) {
    if (t.stage >= kMaxStages) {
      return fail(fmt::format("sampler stage {} is out of range (0..{})", t.stage, kMaxStages - 1));
    }
    if (s.stage[t.stage]) {
      return fail(fmt::format("sampler stage {} is bound twice", t.stage));
    }
    const img::Image* im = t.image;
    if (!im || im->width == 0 || im->height == 0 ||
        im->rgba.size() != size_t{im->width} * im->height * 4) {
      return fail(fmt::format("the texture on stage {} is missing or malformed", t.stage));
    }
    s.stage[t.stage] = &t;
  }
  if (in.blend == Blend::OneOne) {
    const img::Image* d = in.destination;
    if (!d || d->width != s.width || d->height != s.height ||
        d->rgba.size() != size_t{s.width} * s.height * 4) {
      return fail("ONE/ONE blending needs the destination image at the target's size");
    }
  }
  s.ps1x_max = in.model.conventions.ps1x_max_value;
  if (!(s.ps1x_max > 0) || !std::isfinite(s.ps1x_max)) {
    return fail(fmt::format("ps1x_max_value {} is not a positive number", s.ps1x_max));
  }
  return s;
}

// The pass's own stage list, with notes for reads of unbound stages. Each tap's coordinate
// at a pixel: the devices' fp32 interpolation of the vertex listing's corner values
// (quad_coords.h) under Rounding::Llvmpipe when extract_taps gave them and the quad spans
// uv (0, 0)–(1, 1); else scale·pixel_uv + offset in double.
class Reader {
public:
  Reader(const Setup& s, const LinearPassInput& in, const std::vector<Tap>& taps)
      : s_(s), in_(in), taps_(taps) {
    const PassModel& m = in.model;
    const bool unit_quad = m.u0 == 0 && m.v0 == 0 && m.u1 == 1 && m.v1 == 1;
    for (const Tap& t : taps)
      if (t.corners && unit_quad && m.conventions.rounding == ir::Rounding::Llvmpipe)
        coords_.emplace_back(std::in_place, *t.corners, s.width, s.height,
                             m.conventions.pixel_center);
      else
        coords_.emplace_back(std::nullopt);
  }

  // Every tap's coordinate is the devices' own: the RGBA8 store can then settle the values
  // the double sum leaves open in their fp32 arithmetic (store_settled).
  bool all_fp32() const {
    for (const auto& c : coords_)
      if (!c) return false;
    return true;
  }

  // `texel_max` (needs all_fp32): the largest |texel| the read weighs, per channel.
  Rgba read(size_t k, uint32_t i, uint32_t j, Rgba* texel_max = nullptr) {
    const Tap& t = taps_[k];
    const StageTexture* st = t.sampler < kMaxStages ? s_.stage[t.sampler] : nullptr;
    if (!st) {
      unbound_read = true;
      if (texel_max) *texel_max = {0, 0, 0, 1};
      return {0, 0, 0, 1}; // D3D9: an unbound stage reads (0, 0, 0, 1)
    }
    Rgba v = filtered(k, *st->image, st->sampler, i, j, texel_max);
    if (in_.ps1x_clamp)
      for (double& c : v) {
        if (c < 0) negative_sample = true;
        c = clamp_range(c, s_.ps1x_max); // the t# write clamps (NUMERICS.md rule 25)
      }
    return v;
  }

  // The same read in the devices' fp32 arithmetic (needs all_fp32), with the t# clamp.
  std::array<float, 4> read_fp32(size_t k, uint32_t i, uint32_t j) const {
    const Tap& t = taps_[k];
    const StageTexture* st = t.sampler < kMaxStages ? s_.stage[t.sampler] : nullptr;
    if (!st) return {0, 0, 0, 1};
    const auto uv = fp32_coord(k, i, j);
    auto v =
        sample_fp32(*st->image, uv[0], uv[1], st->sampler, in_.model.conventions.subtexel_bits);
    if (in_.ps1x_clamp)
      for (float& c : v) c = clamp_fp32(c);
    return v;
  }

  // Tap k's coordinate as the devices compute it: the fp32 interpolation, plus the pixel
  // listing's fp32 add when the tap has one.
  std::array<float, 2> fp32_coord(size_t k, uint32_t i, uint32_t j) const {
    const auto uv = coords_[k]->at(i, j);
    const auto& add = taps_[k].pixel_add;
    if (!add) return {uv[0], uv[1]};
    return {uv[0] + (*add)[0], uv[1] + (*add)[1]};
  }

  float clamp_fp32(float v) const {
    const auto m = static_cast<float>(s_.ps1x_max);
    return std::isnan(v) ? v : std::clamp(v, -m, m);
  }

  bool unbound_read = false, negative_sample = false;

private:
  Rgba filtered(size_t k, const img::Image& image, const SamplerModel& sampler, uint32_t i,
                uint32_t j, Rgba* texel_max = nullptr) const {
    const int bits = in_.model.conventions.subtexel_bits;
    if (coords_[k]) {
      const auto uv = fp32_coord(k, i, j);
      return sample_at_float(image, uv[0], uv[1], sampler, bits, texel_max);
    }
    const Tap& t = taps_[k];
    const auto uv = pixel_uv(i, j, s_.width, s_.height, in_.model);
    return sample(image, t.scale[0] * uv[0] + t.offset[0], t.scale[1] * uv[1] + t.offset[1],
                  sampler, bits);
  }

  const Setup& s_;
  const LinearPassInput& in_;
  const std::vector<Tap>& taps_;
  std::vector<std::optional<QuadCoords>> coords_;
};

// The ps_1_x output clamp, the blend with the stored destination and the store rule, in
// double (the path for coordinates the model does not take from the devices, and for
// Rounding::Exact): an RGBA8 value within kUnorm8MidpointBand of a midpoint gets one step
// of slack.
void store(img::Image& out, const LinearPassInput& in, const Setup& s, uint32_t i, uint32_t j,
           Rgba v) {
  if (in.ps1x_clamp)
    for (double& c : v) c = clamp_range(c, s.ps1x_max);
  const bool unorm = in.model.target_format == img::Format::RGBA8;
  if (in.blend == Blend::OneOne) {
    for (int c = 0; c < 4; ++c) {
      // UNORM attachments clamp the source to [0, 1] before blending (NaN → 0).
      const double src = unorm ? (v[c] > 0 ? std::min(v[c], 1.0) : 0.0) : v[c];
      v[c] = src + texel_value(*in.destination, i, j, c);
    }
  }
  float* p = out.at(i, j);
  for (int c = 0; c < 4; ++c) p[c] = store_value(out.format, v[c], in.model.unorm8_ties);
  // RGBA16F under Rounding::Llvmpipe: the store rounds toward zero (NUMERICS.md rule 35), a
  // property of the target the model states like the 8-bit midpoint rule.
  if (out.format == img::Format::RGBA16F && in.model.conventions.rounding == ir::Rounding::Llvmpipe)
    for (int c = 0; c < 4; ++c) p[c] = half_toward_zero_model(v[c]);
  const size_t pixel = size_t(j) * out.width + i, pixels = size_t(out.width) * out.height;
  if (!unorm || !in.slack || in.slack->size() != pixels) return;
  const double reach = kUnorm8MidpointBand / 255.0;
  int most = 0;
  for (int c = 0; c < 4; ++c) {
    if (std::isnan(v[c])) continue; // NaN stores 0 on every device
    const int mine = int(std::lround(p[c] * 255.0));
    const int lo =
        int(std::lround(store_value(out.format, v[c] - reach, in.model.unorm8_ties) * 255.0));
    const int hi =
        int(std::lround(store_value(out.format, v[c] + reach, in.model.unorm8_ties) * 255.0));
    most = std::max({most, mine - lo, hi - mine});
  }
  if (most > 0) (*in.slack)[pixel] = 1;
}

// The RGBA8 and RGBA16F stores when every coordinate is the devices' own
// (Rounding::Llvmpipe): per channel, the double value v settles what is stored unless the
// devices' fp32 value, which lies within e[c] of it, may fall on either side of a rounding
// boundary; then the pass's fp32 arithmetic (`fp32`, computed once for the pixel) decides as
// the devices do. RGBA8: ONE/ONE adds the destination's step to the source's, saturating at
// 255 (NUMERICS.md rule 34). RGBA16F: ONE/ONE adds in fp32 (one more rounding, within
// 2^-24 of the sum) and the sum is stored toward zero (rule 35).
// Returns whether an RGBA8 channel's fp32 value x·255 fell exactly half-way: the one store
// D3D9 and Vulkan leave open (the slack of linear_pass.h).
template <class Fp32>
bool store_settled(img::Image& out, const LinearPassInput& in, uint32_t i, uint32_t j, Rgba v,
                   Rgba e, const Fp32& fp32) {
  bool tie_any = false, have = false;
  std::array<float, 4> x{};
  float* p = out.at(i, j);
  const bool one_one = in.blend == Blend::OneOne;
  for (int c = 0; c < 4; ++c) {
    if (out.format == img::Format::RGBA8) {
      int step = 0;
      if (auto settled = detail::unorm8_settled(v[c], e[c])) {
        step = *settled;
      } else {
        if (!have) x = fp32(), have = true;
        bool tie = false;
        step = detail::unorm8_of_fp32(x[c], in.model.unorm8_ties, &tie);
        tie_any = tie_any || tie;
      }
      if (one_one)
        step =
            std::min(255, step + int(std::lround(texel_value(*in.destination, i, j, c) * 255.0)));
      p[c] = static_cast<float>(step / 255.0); // the float every RGBA8 image holds for a step
      continue;
    }
    const float dst = one_one ? in.destination->at(i, j)[c] : 0.0f;
    if (one_one) {
      v[c] += dst;
      e[c] += detail::kFp32Unit * (std::fabs(v[c]) + e[c]);
    }
    const float lo = half_toward_zero_model(v[c] - e[c]), hi = half_toward_zero_model(v[c] + e[c]);
    // ±inf: an infinite double sum means an infinite input, which the fp32 sum holds too
    // (its error bound is infinite as well, so lo and hi say nothing).
    if (lo == hi || std::isnan(v[c]) || std::isinf(v[c])) { // toward zero is monotone
      p[c] = half_toward_zero_model(v[c]);
    } else {
      if (!have) x = fp32(), have = true;
      p[c] = half_toward_zero_model(one_one ? double(x[c] + dst) : double(x[c]));
    }
  }
  return tie_any;
}

// Formats whose store the model settles exactly (store_settled) under Rounding::Llvmpipe.
bool settles_store(const LinearPassInput& in) {
  return in.model.conventions.rounding == ir::Rounding::Llvmpipe &&
         (in.model.target_format == img::Format::RGBA8 ||
          in.model.target_format == img::Format::RGBA16F);
}

void mark_slack(const LinearPassInput& in, const img::Image& out, uint32_t i, uint32_t j,
                bool tie) {
  const size_t pixels = size_t(out.width) * out.height;
  if (tie && in.slack && in.slack->size() == pixels) (*in.slack)[size_t(j) * out.width + i] = 1;
}

void add_notes(std::vector<std::string>* notes, const LinearPassInput& in, const Reader& r,
               bool negative_weight) {
  if (!notes) return;
  if (r.unbound_read) notes->push_back("a tap reads an unbound sampler stage: (0, 0, 0, 1)");
  if (in.ps1x_clamp) {
    notes->push_back(fmt::format("ps_1_x range: samples and the final sum clamped to ±{}",
                                 in.model.conventions.ps1x_max_value));
    if (negative_weight)
      notes->push_back("ps_1_x: a weight is negative, so a partial sum may leave the range and "
                       "come back; clamping only the final sum is then not exact");
    if (r.negative_sample)
      notes->push_back("ps_1_x: a sample is negative, so a partial sum may leave the range and "
                       "come back; clamping only the final sum is then not exact");
  }
}

// RGBA8 or RGBA16F under Rounding::Llvmpipe with every coordinate the devices' own: the
// exact store.
bool exact_store(const LinearPassInput& in, const Reader& reader) {
  return settles_store(in) && reader.all_fp32();
}

} // namespace

img::ImageResult linear_pass(const std::vector<Tap>& taps, const LinearPassInput& in,
                             std::vector<std::string>* notes) {
  ir::Result<Setup> s = check(in);
  if (!s) return std::move(s).failure();
  bool negative_weight = false;
  for (const Tap& t : taps)
    for (double w : t.weight) negative_weight = negative_weight || w < 0;
  img::Image out(s->width, s->height, in.model.target_format);
  Reader reader(*s, in, taps);
  if (exact_store(in, reader)) {
    for (uint32_t j = 0; j < s->height; ++j)
      for (uint32_t i = 0; i < s->width; ++i) {
        // S = Σ|w|·(largest texel a read weighs) bounds every partial sum; each of the n
        // products and n − 1 sums of the listing's chain rounds once (≤ 2^-24 of S each), and
        // each read is off by at most 8·2^-24 of its largest texel (the texel's own float,
        // two lerps of three roundings each): |fp32 − v| ≤ (2n + 8)·2^-24·S < e.
        Rgba sum{}, bound{};
        std::array<int, 4> n{};
        for (size_t k = 0; k < taps.size(); ++k) {
          const Tap& t = taps[k];
          Rgba most{};
          const Rgba v = reader.read(k, i, j, &most);
          for (int c = 0; c < 4; ++c)
            if (t.weight[c] != 0) {
              sum[c] += t.weight[c] * v[c];
              bound[c] += std::fabs(t.weight[c]) * most[c];
              ++n[c];
            }
        }
        Rgba e{};
        for (int c = 0; c < 4; ++c) {
          if (in.ps1x_clamp) sum[c] = clamp_range(sum[c], s->ps1x_max);
          e[c] = (2.0 * n[c] + 10.0) * detail::kFp32Unit * bound[c];
        }
        // The listing's chain in fp32: r = w0·s0, then r = w_k·s_k + r (mul, then mad), in
        // the order it first samples — the order of every glow listing and the article's.
        auto fp32 = [&] {
          std::array<float, 4> r{};
          std::array<bool, 4> started{};
          for (size_t k = 0; k < taps.size(); ++k) {
            const Tap& t = taps[k];
            if (t.weight == Rgba{}) continue; // adds exactly 0
            const auto smp = reader.read_fp32(k, i, j);
            for (int c = 0; c < 4; ++c) {
              if (t.weight[c] == 0) continue;
              const float prod = detail::product_fp32(static_cast<float>(t.weight[c]), smp[c]);
              r[c] = started[c] ? prod + r[c] : prod;
              started[c] = true;
              if (in.ps1x_clamp) r[c] = reader.clamp_fp32(r[c]);
            }
          }
          return r;
        };
        mark_slack(in, out, i, j, store_settled(out, in, i, j, sum, e, fp32));
      }
    add_notes(notes, in, reader, negative_weight);
    return img::ImageResult(std::move(out));
  }
  for (uint32_t j = 0; j < s->height; ++j)
    for (uint32_t i = 0; i < s->width; ++i) {
      Rgba sum{};
      for (size_t k = 0; k < taps.size(); ++k) {
        const Tap& t = taps[k];
        const Rgba v = reader.read(k, i, j);
        for (int c = 0; c < 4; ++c)
          if (t.weight[c] != 0) sum[c] += t.weight[c] * v[c]; // 0-weight taps add exactly 0
      }
      store(out, in, *s, i, j, sum);
    }
  add_notes(notes, in, reader, negative_weight);
  return img::ImageResult(std::move(out));
}

img::ImageResult mask_by_alpha_pass(const Tap& read, const LinearPassInput& in,
                                    std::vector<std::string>* notes) {
  ir::Result<Setup> s = check(in);
  if (!s) return std::move(s).failure();
  img::Image out(s->width, s->height, in.model.target_format);
  const std::vector<Tap> one{read};
  Reader reader(*s, in, one);
  if (exact_store(in, reader)) {
    for (uint32_t j = 0; j < s->height; ++j)
      for (uint32_t i = 0; i < s->width; ++i) {
        Rgba most{};
        Rgba v = reader.read(0, i, j, &most);
        // The read is off by at most 8·2^-24 of its largest texel per channel (see
        // linear_pass), the product rounds once: |fp32 − r·a| ≤ 8u·R·A + 8u·A·R + u·R·A,
        // plus second-order terms, below 20u·R·A.
        Rgba e{};
        for (int c = 0; c < 3; ++c) {
          v[c] *= v[3];
          e[c] = 20.0 * detail::kFp32Unit * most[c] * most[3];
        }
        e[3] = 10.0 * detail::kFp32Unit * most[3];
        if (in.ps1x_clamp)
          for (double& c : v) c = clamp_range(c, s->ps1x_max);
        auto fp32 = [&] {
          auto r = reader.read_fp32(0, i, j);
          for (int c = 0; c < 3; ++c) r[c] = reader.clamp_fp32(detail::product_fp32(r[c], r[3]));
          return r;
        };
        mark_slack(in, out, i, j, store_settled(out, in, i, j, v, e, fp32));
      }
    add_notes(notes, in, reader, false);
    return img::ImageResult(std::move(out));
  }
  for (uint32_t j = 0; j < s->height; ++j)
    for (uint32_t i = 0; i < s->width; ++i) {
      const Rgba v = reader.read(0, i, j);
      store(out, in, *s, i, j, {v[0] * v[3], v[1] * v[3], v[2] * v[3], v[3]});
    }
  reader.negative_sample = false; // one product, no partial sums: the clamps are exact
  add_notes(notes, in, reader, false);
  return img::ImageResult(std::move(out));
}

img::ImageResult fogged_mask_pass(const Tap& source, const Tap& depth, const FogForm& fog,
                                  const LinearPassInput& in, std::vector<std::string>* notes) {
  ir::Result<Setup> s = check(in);
  if (!s) return std::move(s).failure();
  img::Image out(s->width, s->height, in.model.target_format);
  const std::vector<Tap> reads{source, depth};
  Reader reader(*s, in, reads);
  // Each step the listing stores in a register is clamped as the ps_1_x rule says (the
  // product, the fog factor before its saturate, the blend); the store clamps the result.
  auto range = [&](double v) { return in.ps1x_clamp ? clamp_range(v, s->ps1x_max) : v; };
  auto range32 = [&](float v) { return in.ps1x_clamp ? reader.clamp_fp32(v) : v; };
  if (exact_store(in, reader)) {
    for (uint32_t j = 0; j < s->height; ++j)
      for (uint32_t i = 0; i < s->width; ++i) {
        Rgba ms{}, md{};
        const Rgba v = reader.read(0, i, j, &ms), d = reader.read(1, i, j, &md);
        Rgba o{0, 0, 0, range(v[3])}, e{0, 0, 0, 10.0 * detail::kFp32Unit * ms[3]};
        for (int c = 0; c < 3; ++c) {
          const double f =
              std::clamp(range(fog.scale * (fog.slope[c] * d[c] + fog.bias[c])), 0.0, 1.0);
          o[c] = range(f * range(v[c] * v[3]) + (1 - f) * fog.color[c]);
          // Generous on purpose (a larger bound only sends more values to the fp32 path):
          // the factor's mad rounds at the size of its terms, the lrp at the size of its
          // operands, and each read is off by a few units of its largest texel.
          const double reach =
              1 + fog.scale * (std::fabs(fog.slope[c]) * md[c] + std::fabs(fog.bias[c]));
          e[c] = 64.0 * detail::kFp32Unit * reach * (ms[c] * ms[3] + std::fabs(fog.color[c]) + 1);
        }
        // The listing in fp32: mul, then mad (product rounded, then the sum; _x4 a plain
        // product), saturate, then lrp as s2 + s0·(s1 − s2) (NUMERICS.md rules 8, 14).
        auto fp32 = [&] {
          const auto src = reader.read_fp32(0, i, j), dep = reader.read_fp32(1, i, j);
          std::array<float, 4> r{0, 0, 0, range32(src[3])};
          for (int c = 0; c < 3; ++c) {
            const float prod = range32(detail::product_fp32(src[c], src[3]));
            float pre = detail::product_fp32(float(fog.slope[c]), dep[c]) + float(fog.bias[c]);
            if (fog.scale != 1) pre *= float(fog.scale);
            const float f = std::clamp(range32(pre), 0.0f, 1.0f);
            const auto col = float(fog.color[c]);
            r[c] = range32(detail::product_fp32(f, prod - col) + col);
          }
          return r;
        };
        mark_slack(in, out, i, j, store_settled(out, in, i, j, o, e, fp32));
      }
    add_notes(notes, in, reader, false);
    return img::ImageResult(std::move(out));
  }
  for (uint32_t j = 0; j < s->height; ++j)
    for (uint32_t i = 0; i < s->width; ++i) {
      const Rgba v = reader.read(0, i, j), d = reader.read(1, i, j);
      Rgba o{0, 0, 0, v[3]};
      for (int c = 0; c < 3; ++c) {
        const double f =
            std::clamp(range(fog.scale * (fog.slope[c] * d[c] + fog.bias[c])), 0.0, 1.0);
        o[c] = f * range(v[c] * v[3]) + (1 - f) * fog.color[c];
      }
      store(out, in, *s, i, j, o);
    }
  reader.negative_sample = false; // no partial sums of several reads: the clamps are exact
  add_notes(notes, in, reader, false);
  return img::ImageResult(std::move(out));
}

} // namespace tierlift::analytic
