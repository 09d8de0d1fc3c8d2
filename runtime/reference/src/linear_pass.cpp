// A pass as math (linear_pass.h): weighted reads over several sampler stages, or the
// rgb × alpha of one read; then the ps_1_x range, the blend and the store, in double.
#include "tierlift/reference/linear_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <optional>

namespace tierlift::ref {
namespace {

using Rgba = std::array<double, 4>;

constexpr uint32_t kMaxStages = 16;

double clamp_range(double v, double m) {
  return std::isnan(v) ? v : std::clamp(v, -m, m);
}

// What the pass reads and where it writes, checked once.
struct Setup {
  std::array<const StageTexture*, kMaxStages> stage{};
  // A stage's slack as an image (slack / 255 in every channel), sampled like the texture:
  // the bilinear weights carry it exactly as they carry the texel values.
  std::array<std::optional<img::Image>, kMaxStages> slack;
  uint32_t width = 0, height = 0;
  double ps1x_max = 1;
};

std::optional<Setup> check(const LinearPassInput& in, std::string& error) {
  Setup s;
  s.width = in.model.target_width;
  s.height = in.model.target_height;
  if (s.width == 0 || s.height == 0 || s.width > img::kMaxDimension ||
      s.height > img::kMaxDimension) {
    error = fmt::format("target {}x{}: expected 1..{}", s.width, s.height, img::kMaxDimension);
    return std::nullopt;
  }
  for (const StageTexture& t : in.textures) {
    if (t.stage >= kMaxStages) {
      error = fmt::format("sampler stage {} is out of range (0..{})", t.stage, kMaxStages - 1);
      return std::nullopt;
    }
    if (s.stage[t.stage]) {
      error = fmt::format("sampler stage {} is bound twice", t.stage);
      return std::nullopt;
    }
    const img::Image* im = t.image;
    if (!im || im->width == 0 || im->height == 0 ||
        im->rgba.size() != size_t{im->width} * im->height * 4) {
      error = fmt::format("the texture on stage {} is missing or malformed", t.stage);
      return std::nullopt;
    }
    s.stage[t.stage] = &t;
    if (t.slack && t.slack->size() == size_t{im->width} * im->height) {
      img::Image sl(im->width, im->height, img::Format::RGBA32F);
      for (size_t p = 0; p < t.slack->size(); ++p)
        for (int c = 0; c < 4; ++c) sl.rgba[4 * p + c] = float((*t.slack)[p]) / 255.0f;
      s.slack[t.stage] = std::move(sl);
    }
  }
  if (in.blend == Blend::OneOne) {
    const img::Image* d = in.destination;
    if (!d || d->width != s.width || d->height != s.height ||
        d->rgba.size() != size_t{s.width} * s.height * 4) {
      error = "ONE/ONE blending needs the destination image at the target's size";
      return std::nullopt;
    }
  }
  s.ps1x_max = in.model.conventions.ps1x_max_value;
  if (!(s.ps1x_max > 0) || !std::isfinite(s.ps1x_max)) {
    error = fmt::format("ps1x_max_value {} is not a positive number", s.ps1x_max);
    return std::nullopt;
  }
  return s;
}

// The pass's own stage list, with notes for reads of unbound stages.
class Reader {
public:
  Reader(const Setup& s, const LinearPassInput& in) : s_(s), in_(in) {}

  Rgba read(const Tap& t, const std::array<double, 2>& uv) {
    const StageTexture* st = t.sampler < kMaxStages ? s_.stage[t.sampler] : nullptr;
    if (!st) {
      unbound_read = true;
      return {0, 0, 0, 1}; // D3D9: an unbound stage reads (0, 0, 0, 1)
    }
    Rgba v = sample(*st->image, t.scale[0] * uv[0] + t.offset[0], t.scale[1] * uv[1] + t.offset[1],
                    st->sampler, in_.model.conventions.subtexel_bits);
    if (in_.ps1x_clamp)
      for (double& c : v) {
        if (c < 0) negative_sample = true;
        c = clamp_range(c, s_.ps1x_max); // the t# write clamps (NUMERICS.md rule 25)
      }
    return v;
  }

  // How far (in value units) the devices' read may lie from read(t, uv): the texels' slack
  // under the same filter weights.
  double slack(const Tap& t, const std::array<double, 2>& uv) const {
    if (t.sampler >= kMaxStages) return 0;
    const std::optional<img::Image>& sl = s_.slack[t.sampler]; // no copy: images are large
    if (!sl) return 0;
    const StageTexture* st = s_.stage[t.sampler];
    return sample(*sl, t.scale[0] * uv[0] + t.offset[0], t.scale[1] * uv[1] + t.offset[1],
                  st->sampler, in_.model.conventions.subtexel_bits)[0];
  }

  bool unbound_read = false, negative_sample = false;

private:
  const Setup& s_;
  const LinearPassInput& in_;
};

// The ps_1_x output clamp, the blend with the stored destination and the store rule.
// `u`: how far (value units) the devices' value may lie from v, from their inputs' slack.
void store(img::Image& out, const LinearPassInput& in, const Setup& s, uint32_t i, uint32_t j,
           Rgba v, double u) {
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
    for (int c = 0; c < 4; ++c) p[c] = img::half_toward_zero(v[c]);
  const size_t pixel = size_t(j) * out.width + i, pixels = size_t(out.width) * out.height;
  if (!unorm || !in.slack || in.slack->size() != pixels) return;
  if (in.blend == Blend::OneOne && in.destination_slack && in.destination_slack->size() == pixels)
    u += (*in.destination_slack)[pixel] / 255.0;
  const double reach = u + kUnorm8MidpointBand / 255.0;
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
  (*in.slack)[pixel] = static_cast<uint8_t>(std::min(most, 255));
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

} // namespace

img::LoadResult linear_pass(const std::vector<Tap>& taps, const LinearPassInput& in,
                            std::vector<std::string>* notes) {
  std::string error;
  auto s = check(in, error);
  if (!s) return {std::nullopt, error};
  bool negative_weight = false;
  for (const Tap& t : taps)
    for (double w : t.weight) negative_weight = negative_weight || w < 0;
  img::Image out(s->width, s->height, in.model.target_format);
  Reader reader(*s, in);
  for (uint32_t j = 0; j < s->height; ++j)
    for (uint32_t i = 0; i < s->width; ++i) {
      const auto uv = pixel_uv(i, j, s->width, s->height, in.model);
      Rgba sum{};
      double u = 0;
      for (const Tap& t : taps) {
        const Rgba v = reader.read(t, uv);
        double w_most = 0;
        for (int c = 0; c < 4; ++c)
          if (t.weight[c] != 0) {
            sum[c] += t.weight[c] * v[c]; // 0-weight taps add exactly 0
            w_most = std::max(w_most, std::fabs(t.weight[c]));
          }
        if (w_most != 0) u += w_most * reader.slack(t, uv);
      }
      store(out, in, *s, i, j, sum, u);
    }
  add_notes(notes, in, reader, negative_weight);
  return {std::move(out), ""};
}

img::LoadResult mask_by_alpha_pass(const Tap& read, const LinearPassInput& in,
                                   std::vector<std::string>* notes) {
  std::string error;
  auto s = check(in, error);
  if (!s) return {std::nullopt, error};
  img::Image out(s->width, s->height, in.model.target_format);
  Reader reader(*s, in);
  for (uint32_t j = 0; j < s->height; ++j)
    for (uint32_t i = 0; i < s->width; ++i) {
      const auto uv = pixel_uv(i, j, s->width, s->height, in.model);
      const Rgba v = reader.read(read, uv);
      // (x + dx)(a + da) − x·a ≤ dx·a + x·da + dx·da for x, a in [0, 1], |dx|, |da| ≤ d.
      const double d = reader.slack(read, uv);
      store(out, in, *s, i, j, {v[0] * v[3], v[1] * v[3], v[2] * v[3], v[3]}, d * (2 + d));
    }
  reader.negative_sample = false; // one product, no partial sums: the clamps are exact
  add_notes(notes, in, reader, false);
  return {std::move(out), ""};
}

} // namespace tierlift::ref
