// Blending in float on the stored destination value, then the format's store rule.
#include "tierlift/cpu/draw.h"

namespace tierlift::cpu {
namespace {
float clamp01(float v) {
  return v > 0 ? (v < 1 ? v : 1) : 0;
} // NaN → 0
} // namespace

Vec4 blend_and_store(BlendMode mode, img::Format format, const Vec4& src_in, const Vec4& dst) {
  Vec4 src = src_in;
  // UNORM attachments clamp the source colour (and so the SRCALPHA factors) to [0, 1]
  // before blending (Vulkan "Blend Operations"; D3D9 hardware does the same).
  if (format == img::Format::RGBA8)
    for (auto& c : src) c = clamp01(c);
  Vec4 out;
  const float a = src[3];
  for (int c = 0; c < 4; ++c) {
    switch (mode) {
    case BlendMode::Replace: out[c] = src[c]; break;
    case BlendMode::OneOne: out[c] = src[c] + dst[c]; break;
    case BlendMode::SrcAlphaOne: out[c] = src[c] * a + dst[c]; break;
    case BlendMode::SrcAlphaInvSrcAlpha: out[c] = src[c] * a + dst[c] * (1.0f - a); break;
    }
    out[c] = img::quantize(format, out[c]);
  }
  return out;
}

} // namespace tierlift::cpu
