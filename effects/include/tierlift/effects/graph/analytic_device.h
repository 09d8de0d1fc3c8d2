// The analytic device: the third way of docs/design.md's "Three ways, one answer". It runs an
// effect graph's passes as math, in double, sharing no code with the CPU device:
//   * AnalyticForm::Linear — the taps (sampler stage, coordinate scale and offset, weight)
//     are read off that pass's own listings and constants by analytic::extract_taps, never from
//     the generator's parameters, and evaluated by analytic::linear_pass: bilinear or point reads
//     at the sample positions of the graph's conventions (pixel centre, sub-texel bits), the
//     ps_1_x range rule when the pixel listing is ps_1_x, Replace or ONE/ONE blending with
//     what the target holds, img::quantize for the target's format;
//   * AnalyticForm::MaskByAlpha — rgb × alpha of the one read the pixel listing takes;
//   * AnalyticForm::MaskByAlphaFogged — the same of its first read, fogged by its second (the
//     depth) with D3D's linear fog, the fog's numbers read off the listing's own constants
//     (analytic::fog_form, analytic::fogged_mask_pass).
// A pass it cannot model (a listing outside the form, another blend mode, the vertex
// listing moving the quad, ps_1_x fixed-point emulation) is an error naming the pass and,
// where the listing is at fault, the instruction (line:col).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tierlift/effects/graph/device.h"

namespace tierlift::effects {

class AnalyticPassDevice final : public PassDevice {
public:
  std::string name() const override { return "analytic"; }
  ir::Status begin_run(const EffectGraph& graph, const ImageMap& inputs) override;
  ir::Result<pass::DrawReport> draw(const PassDesc& pass) override;
  ir::Status update_input(const std::string& name, const img::Image& image) override;
  ir::Result<img::Image> read_texture(const std::string& name) override;
  // The assumptions the model made in this run, one line each, "pass 'name': …" (e.g. the
  // ps_1_x clamp of the final sum only, a read of an unbound stage).
  const std::vector<std::string>& notes() const { return notes_; }
  bool rounding_midpoints(const std::string& texture, std::vector<uint8_t>& mask) const override;

private:
  const EffectGraph* graph_ = nullptr;
  ImageMap images_;
  std::vector<std::string> notes_;
  std::map<std::string, std::vector<uint8_t>, std::less<>> midpoints_; // RGBA8 targets
};

std::unique_ptr<PassDevice> make_analytic_pass_device();

} // namespace tierlift::effects
