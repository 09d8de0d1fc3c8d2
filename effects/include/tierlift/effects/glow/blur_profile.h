// The 1D blur profile of the glow, sampled at whole texels into taps. Terms:
//  - Gaussians (σ, weight): the article's "smooth, broad base" plus "a bright spike in the
//    center" by default;
//  - a sawtooth (period, radius, weight): the article demo's "periodic sawtooth profile that
//    produces an interesting diffraction-like multiple-image effect". At x full-resolution
//    pixels from the centre
//        saw(x) = 1 − frac(|x| / period)   for |x| ≤ radius,   0 beyond,
//    a peak of 1 at every multiple of the period, falling linearly outward towards 0 just
//    before the next peak: every glow source shows again at ±period, ±2·period, …, each
//    copy smeared away from the centre.
// Each term keeps its own weight: its samples are normalised to sum to that weight, so the
// taps sum to the sum of the weights (not to one when the weights do not).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tierlift/ir/result.h"

namespace tierlift::effects {

// The widest blur: radius 1024 texels, so at most 2·1024 + 1 taps — the one cap on taps, read
// by sample_blur_profile and by the scenes' "taps" and GLSL "weights".
inline constexpr int kMaxBlurRadius = 1024;
inline constexpr int kMaxBlurTaps = 2 * kMaxBlurRadius + 1;

struct Gaussian {
  double sigma = 1;  // in full-resolution pixels
  double weight = 1; // what the term's taps sum to
};

struct Sawtooth {
  double period = 8;  // in full-resolution pixels, > 0
  double radius = 32; // in full-resolution pixels, ≥ 0: no taps beyond
  double weight = 1;  // what the term's taps sum to
};

struct BlurProfile {
  std::vector<Gaussian> terms;
  std::optional<Sawtooth> sawtooth;
  unsigned max_taps = 0; // 0: no limit; else odd: at most this many taps per axis
};

// One Gaussian, σ = 16 px (weight 1): with intensity 3 at downsample 4 (EffectParams) a halo a
// person sees around the built-in scene's lights (the old σ 8 + σ 1.5 at intensity 1 hardly
// showed).
BlurProfile default_blur_profile();

// Σ of the term weights: what the taps sum to, and the gain of one blur axis.
double profile_weight_sum(const BlurProfile& profile);

struct BlurTap {
  int offset = 0; // in texels of the texture being blurred
  double weight = 0;
};

// Samples the profile at texel offsets −R..R of a texture d = `downsample` times smaller
// than full resolution (texel offset k lies k·d full-resolution pixels from the centre):
//   radius of a Gaussian      ceil(3 σ / d)            texels
//   radius of the sawtooth    floor(radius / d)        texels
//   R = the largest of them, cut to (max_taps − 1) / 2 when max_taps is set
//   gauss(k) = exp(−k² / 2s²) with s = σ / d;  saw(k) = saw(k·d) above (a position within
//   1e-9 of a multiple of the period counts as that multiple)
//   tap(k) = Σ_terms weight · value(k) / Σ_{j=−R..R} value(j)
// Fails (one error of rule "profile") when a value is not finite, σ ≤ 0, period ≤ 0,
// radius < 0, a weight < 0, there is no term, the weights sum to 0, max_taps is even, or R
// would exceed 1024.
ir::Result<std::vector<BlurTap>> sample_blur_profile(const BlurProfile& profile,
                                                     unsigned downsample);

} // namespace tierlift::effects
