// D3DSAMP_SRGBTEXTURE on the host: an sRGB sampler stage's texels decoded once, before any
// filtering, into a float image both devices then sample as they sample any float texture
// (NUMERICS.md S1, S2). A device decodes the stages of a pass it draws with srgb_resolved;
// `tierlift run`'s graph of one pass carries the decoded images as its input textures.
#pragma once

#include <memory>

#include "tierlift/image/image.h"
#include "tierlift/pass/pass.h"

namespace tierlift::pass {

// An RGBA8 image as an sRGB stage reads it: RGBA32F, each R, G and B byte k replaced by
// rounding::srgb_decode_levels()[k], alpha as stored (Direct3D 9 decodes colour, not alpha).
// Images of other formats come back as they are: Direct3D 9 offers sRGB reads of 8-bit
// formats only (D3DUSAGE_QUERY_SRGBREAD), and a float texture holds linear values already.
std::shared_ptr<const img::Image> srgb_decoded(const std::shared_ptr<const img::Image>& image);

// `b` with its image (and a cube's or volume's layers) decoded when b.sampler.srgb, and the
// flag cleared: what the stage reads, for a device that samples it as a plain texture.
TextureBinding srgb_resolved(const TextureBinding& b);

// Whether any stage of `pass` reads sRGB (a pixel stage or a vertex sampler).
bool reads_srgb(const Pass& pass);

} // namespace tierlift::pass
