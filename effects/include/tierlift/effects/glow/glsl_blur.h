// The separable blur of the GLSL article (seed 004) as an effect graph whose passes are GLSL
// (docs/glsl.md):
//   blur_h   scene → blur_h: glsl/seed004_blur_h.frag, the seed's nine taps along x
//   blur_v   blur_h → final: glsl/seed004_blur_v.frag, the same along y
// Each pass carries three descriptions of the same blur: the GLSL compiled by glslang (what
// the Vulkan device draws), its ps_2_0 twin (glsl/blur9_{h,v}.psh, what the interpreter runs)
// and the kernel (taps at k · step, the seed's weights: what the analytic device evaluates).
// The vertex stage is glow/quad4_coords.vsh with oT0 = uv + half a texel: the GLSL's
// vTexCoord then lands on texel centres, as OpenGL's pixel centres put it there.
// Point sampling with clamp addressing: every tap sits on a texel centre at the seed's 512
// texels (step = one texel), where a bilinear read is that texel anyway, and point filtering
// keeps fp32 coordinate error out of the result (glow.h says the same of the glow's taps).
#pragma once

#include <string>
#include <vector>

#include "tierlift/effects/glow/glow.h"

namespace tierlift::effects {

// The seed's weights (σ ≈ 2.7), taps −4 … +4; they sum to 0.98.
inline constexpr double kSeedBlurWeights[9] = {0.05, 0.09, 0.12, 0.15, 0.16,
                                               0.15, 0.12, 0.09, 0.05};
inline constexpr double kSeedBlurSize = 1.0 / 512.0; // the seed's blurSize, in uv

inline constexpr std::string_view kGlslBlurH = "glsl/seed004_blur_h.frag";
inline constexpr std::string_view kGlslBlurV = "glsl/seed004_blur_v.frag";
inline constexpr std::string_view kGlslTwinH = "glsl/blur9_h.psh";
inline constexpr std::string_view kGlslTwinV = "glsl/blur9_v.psh";

struct GlslBlurParams {
  // GLSL fragment shaders: a file path, or empty for the built-in (the seed's text).
  std::string horizontal, vertical;
  // Their ps_2_0 twins: a file path, or empty for the built-in (the seed's blur).
  std::string horizontal_twin, vertical_twin;
  // The kernel the analytic device evaluates: tap k (k = −n … n, n = (size − 1) / 2) at
  // k · step in uv along the pass's axis, weight weights[k + n]. A scene that brings its own
  // GLSL states its kernel here; the three ways then check the GLSL against it.
  std::vector<double> weights{std::begin(kSeedBlurWeights), std::end(kSeedBlurWeights)};
  double step = kSeedBlurSize;
};

// The graph at params' size and format (`params` is the scene's: width, height, format,
// listing options; its glow fields are unused). Texture "scene" is the input, "blur_h" the
// horizontal result, "final" the blur. A GLSL file that does not compile gives glslang's
// messages positioned in it (file:line:col, source line, caret) in `error`; so does a twin
// listing. Also refused: a GLSL pass sampling a stage its twin does not bind.
PlanResult build_glsl_blur(const EffectParams& params, const GlslBlurParams& glsl);

// "kernel weights sum to 0.98: the blur is 3.96 % darker than its source (0.9604 after
// both axes)", as glow_warnings says it of a glow profile; empty when they sum to 1.
std::vector<std::string> glsl_blur_warnings(const GlslBlurParams& glsl);

} // namespace tierlift::effects
