// Internal to the analytic device: one pass of an effect graph as analytic:: math.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "tierlift/analytic/blur_model.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/graph.h"

namespace tierlift::effects::detail {

// D3DSAMP_* state as the analytic model's sampler.
analytic::SamplerModel sampler_model(const pass::SamplerState& s);

// Computes `pass` from `images` (every texture of `graph`) and replaces its target there.
// Empty string on success (notes appended to *notes), else why, naming the pass; the
// images are unchanged then.
// `midpoints` holds each RGBA8 texture's mask of proven rounding ties (analytic::LinearPassInput::
// slack); the target's is updated with the pass.
using MidpointMasks = std::map<std::string, std::vector<uint8_t>, std::less<>>;
std::string run_analytic_pass(const PassDesc& pass, const EffectGraph& graph, ImageMap& images,
                              MidpointMasks& midpoints, std::vector<std::string>* notes);

} // namespace tierlift::effects::detail
