// The 1D blur profile of the glow: a sum of Gaussians (σ, weight), the article's "smooth,
// broad base" plus "a bright spike in the center" by default, sampled at whole texels into
// taps and normalised to sum to one.
#pragma once

#include <string>
#include <vector>

namespace tierlift::effects {

struct Gaussian {
  double sigma = 1;  // in full-resolution pixels
  double weight = 1; // share of the profile's area
};

struct BlurProfile {
  std::vector<Gaussian> terms;
};

// Broad base σ = 8 px (weight 0.7) and spike σ = 1.5 px (weight 0.3).
BlurProfile default_blur_profile();

struct BlurTap {
  int offset = 0; // in texels of the texture being blurred
  double weight = 0;
};

// Samples the profile at texel offsets −R..R of a texture `downsample` times smaller than
// full resolution: σ_texels = σ / downsample, R = ceil(3 · largest σ_texels) (at least 0),
// value(k) = Σ weight · exp(−k² / 2σ²) / σ, then normalised to Σ = 1. Empty and *error set
// when a term is not finite, σ ≤ 0, a weight < 0, the sum is 0, or R would exceed 1024.
std::vector<BlurTap> sample_blur_profile(const BlurProfile& profile, unsigned downsample,
                                         std::string* error);

} // namespace tierlift::effects
