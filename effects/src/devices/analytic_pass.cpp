// One pass of an effect graph as math (analytic_device.h): the pass's listings read
// symbolically (analytic::extract_taps / extract_reads), the bound textures and sampler states,
// the graph's conventions and the target's size, format and blend handed to analytic::.
#include "analytic_pass.h"
#include "analytic_stencil.h"

#include <optional>

#include <fmt/format.h>

#include "tierlift/analytic/linear_pass.h"
#include "tierlift/analytic/taps.h"

namespace tierlift::effects::detail {
namespace {

// The parts of a pass that do not depend on its form: stages, model, blend, ps_1_x rule.
std::string prepare(const PassDesc& pass, const EffectGraph& graph, const ImageMap& images,
                    analytic::LinearPassInput& in) {
  const TextureDesc* target = graph.find_texture(pass.target);
  if (!target) return fmt::format("pass '{}': unknown target '{}'", pass.name, pass.target);
  for (const TextureBind& b : pass.textures) {
    if (pass::is_vertex_sampler(b.stage))
      return fmt::format("pass '{}': the analytic model has no vertex texture fetch (vertex "
                         "sampler {} bound)",
                         pass.name, b.stage - pass::kVertexSampler0);
    auto it = images.find(b.texture);
    if (it == images.end() || b.stage >= pass::kMaxSamplers)
      return fmt::format("pass '{}': texture '{}' has no image", pass.name, b.texture);
    in.textures.push_back(
        {b.stage, &it->second, sampler_model(pass.draw.textures[b.stage].sampler)});
  }
  in.model.conventions = graph.conventions;
  // RGBA8 midpoints: the graph's devices round them as lavapipe does (to even) under
  // Rounding::Llvmpipe and by img::quantize (half up) under Exact; the model states the
  // same convention (D3D9 and Vulkan leave ties open, so neither is an error).
  in.model.unorm8_ties = graph.conventions.rounding == ir::Rounding::Llvmpipe
                             ? analytic::Unorm8Ties::ToEven
                             : analytic::Unorm8Ties::HalfUp;
  in.model.target_width = target->width;
  in.model.target_height = target->height;
  in.model.target_format = target->format;
  switch (pass.draw.blend) {
  case pass::BlendMode::Replace: in.blend = analytic::Blend::Replace; break;
  case pass::BlendMode::OneOne: in.blend = analytic::Blend::OneOne; break;
  default:
    return fmt::format("pass '{}': the analytic model knows Replace and ONE/ONE blending only",
                       pass.name);
  }
  auto dst = images.find(pass.target);
  if (dst == images.end())
    return fmt::format("pass '{}': target '{}' has no image", pass.name, pass.target);
  in.destination = &dst->second;
  in.ps1x_clamp = ir::is_ps1x(pass.draw.pixel_program->profile);
  if (in.ps1x_clamp && graph.conventions.ps1x_fixed_bits != 0)
    return fmt::format("pass '{}': ps_1_x fixed-point emulation ({} bits) is not modelled",
                       pass.name, graph.conventions.ps1x_fixed_bits);
  if (ir::Status quad = analytic::check_position_passthrough(*pass.draw.vertex_program); !quad)
    return fmt::format("cannot model pass '{}' (a full-screen quad): vertex listing: {}", pass.name,
                       quad.message());
  return "";
}

// An object pass (AnalyticForm::Coverage): each target's covered pixels that pass the stencil
// test take the constant its oC# receives, stored with the target's rule; the rest keep
// their value. Replace blending only.
std::string run_object_pass(const PassDesc& pass, const EffectGraph& graph, ImageMap& images,
                            MidpointMasks& midpoints) {
  if (pass.draw.blend != pass::BlendMode::Replace)
    return fmt::format("pass '{}': the analytic object pass knows Replace blending only",
                       pass.name);
  const TextureDesc* target = graph.find_texture(pass.target);
  if (!target) return fmt::format("pass '{}': unknown target '{}'", pass.name, pass.target);
  std::array<pass::Vec4, 4> colors{};
  uint8_t written = 0;
  if (std::string e = constant_outputs(pass, colors, written); !e.empty()) return e;
  std::vector<uint8_t> covered;
  if (std::string e = coverage(pass, graph.conventions, target->width, target->height, covered);
      !e.empty())
    return e;
  std::vector<std::string> names{pass.target};
  names.insert(names.end(), pass.more_targets.begin(), pass.more_targets.end());
  std::vector<img::Image> out;
  for (const std::string& name : names) {
    auto it = images.find(name);
    if (it == images.end())
      return fmt::format("pass '{}': target '{}' has no image", pass.name, name);
    out.push_back(it->second);
  }
  if (!pass.stencil.empty()) {
    auto s = images.find(pass.stencil);
    if (s == images.end())
      return fmt::format("pass '{}': stencil '{}' has no image", pass.name, pass.stencil);
    apply_stencil(pass, s->second, covered);
  }
  for (size_t t = 0; t < out.size(); ++t)
    for (size_t i = 0; i < covered.size(); ++i)
      if (covered[i])
        for (size_t c = 0; c < 4; ++c)
          out[t].rgba[4 * i + c] = img::quantize(out[t].format, colors[t][c]);
  for (size_t t = 0; t < out.size(); ++t) {
    images[names[t]] = std::move(out[t]);
    // The constants are chosen by the listing; a tie would need c·255 at k + ½ exactly.
    midpoints.erase(names[t]);
  }
  return "";
}

// Where the pass's stencil test fails (or its triangles do not reach), the target keeps
// `before`; only those pixels that pass take the computed `result`.
std::string mask_by_stencil(const PassDesc& pass, const EffectGraph& graph, ImageMap& images,
                            const img::Image& before, img::Image& result,
                            std::vector<uint8_t>* midpoint_mask) {
  std::vector<uint8_t> covered;
  if (std::string e = coverage(pass, graph.conventions, result.width, result.height, covered);
      !e.empty())
    return e;
  if (!pass.stencil.empty()) {
    auto s = images.find(pass.stencil);
    if (s == images.end())
      return fmt::format("pass '{}': stencil '{}' has no image", pass.name, pass.stencil);
    apply_stencil(pass, s->second, covered);
  }
  for (size_t i = 0; i < covered.size(); ++i) {
    if (covered[i]) continue;
    for (size_t c = 0; c < 4; ++c) result.rgba[4 * i + c] = before.rgba[4 * i + c];
    if (midpoint_mask && i < midpoint_mask->size()) (*midpoint_mask)[i] = 0;
  }
  return "";
}

// Outside the pass's scissor rectangle the target keeps `before` (and the rounding ties it
// had: its value there is the stored one, unchanged).
void keep_outside_scissor(const pass::ScissorRect& r, const img::Image& before, img::Image& result,
                          const MidpointMasks& midpoints, const std::string& target,
                          std::vector<uint8_t>* midpoint_mask) {
  const std::vector<uint8_t>* old = nullptr;
  if (auto it = midpoints.find(target); it != midpoints.end()) old = &it->second;
  for (uint32_t y = 0; y < result.height; ++y)
    for (uint32_t x = 0; x < result.width; ++x) {
      if (int64_t{x} >= r.x0 && int64_t{x} < r.x1 && int64_t{y} >= r.y0 && int64_t{y} < r.y1)
        continue;
      const size_t i = size_t{y} * result.width + x;
      for (size_t c = 0; c < 4; ++c)
        result.rgba[4 * i + c] = 4 * i + c < before.rgba.size() ? before.rgba[4 * i + c] : 0.0f;
      if (midpoint_mask && i < midpoint_mask->size())
        (*midpoint_mask)[i] = old && i < old->size() ? (*old)[i] : 0;
    }
}

} // namespace

analytic::SamplerModel sampler_model(const pass::SamplerState& s) {
  analytic::SamplerModel m;
  m.filter = s.filter == pass::Filter::Linear ? analytic::Filter::Linear : analytic::Filter::Point;
  m.address_u = s.address_u;
  m.address_v = s.address_v;
  for (int c = 0; c < 4; ++c) m.border[c] = s.border_color[c];
  return m;
}

std::string run_analytic_pass(const PassDesc& pass, const EffectGraph& graph, ImageMap& images,
                              MidpointMasks& midpoints, std::vector<std::string>* notes) {
  if (!pass.draw.vertex_program || !pass.draw.pixel_program)
    return fmt::format("pass '{}': needs a vertex and a pixel listing", pass.name);
  // The model reads taps off straight-line listings; i# and b# only steer flow control. A
  // Kernel pass states its taps, so its listing's flow control is the devices' concern.
  const pass::ConstantBank plain;
  const bool flow_constants =
      pass.draw.vs_constants.i != plain.i || pass.draw.ps_constants.i != plain.i ||
      pass.draw.vs_constants.b != plain.b || pass.draw.ps_constants.b != plain.b;
  if (pass.analytic != AnalyticForm::Kernel && flow_constants)
    return fmt::format("pass '{}': the analytic model takes no integer or boolean constants",
                       pass.name);
  if (pass.analytic == AnalyticForm::Coverage) {
    if (pass.draw.scissor)
      return fmt::format("pass '{}': the analytic object pass has no scissor rectangle", pass.name);
    return run_object_pass(pass, graph, images, midpoints);
  }
  if (!pass.more_targets.empty())
    return fmt::format("pass '{}': the analytic model writes several render targets only in an "
                       "object pass (constant outputs)",
                       pass.name);
  if (!pass.draw.vertices.empty() && pass.stencil.empty())
    return fmt::format("pass '{}': the analytic model reads taps off a full-screen quad; a "
                       "pass with its own triangles must be an object pass",
                       pass.name);
  analytic::LinearPassInput in;
  if (std::string e = prepare(pass, graph, images, in); !e.empty()) return e;

  // RGBA8: the pixels whose store is a proven rounding tie (linear_pass.h, `slack`); ONE/ONE
  // keeps the ties of the passes summed into the target before.
  std::vector<uint8_t> mask;
  if (in.model.target_format == img::Format::RGBA8) {
    const size_t size = size_t(in.model.target_width) * in.model.target_height;
    auto it = midpoints.find(pass.target);
    if (in.blend == analytic::Blend::OneOne && it != midpoints.end() && it->second.size() == size)
      mask = it->second;
    else
      mask.assign(size, 0);
    in.slack = &mask;
  }
  std::vector<std::string> pass_notes;
  std::optional<img::ImageResult> result;
  if (pass.analytic == AnalyticForm::Kernel) {
    // A GLSL pass or a loop (tier dx9c): the model cannot read them, so it takes the kernel
    // the pass states (taps at the sample point plus an offset), interpolating the coordinate
    // in double, or as the devices do when the offset is added in the pixel stage.
    std::vector<analytic::Tap> taps;
    for (const KernelTap& k : pass.kernel) {
      analytic::Tap t;
      t.sampler = k.stage;
      t.offset = k.offset;
      t.weight = k.weight;
      if (k.pixel_add) {
        t.corners = {{{0, 0}, {1, 0}, {0, 1}, {1, 1}}}; // the quad uv, passed on unchanged
        t.pixel_add = {{static_cast<float>(k.offset[0]), static_cast<float>(k.offset[1])}};
      }
      taps.push_back(t);
    }
    result.emplace(analytic::linear_pass(taps, in, &pass_notes));
  } else if (pass.analytic == AnalyticForm::Linear) {
    ir::Result<analytic::TapExtraction> ex =
        analytic::extract_taps(*pass.draw.vertex_program, pass.draw.vs_constants.f,
                               *pass.draw.pixel_program, pass.draw.ps_constants.f);
    if (!ex)
      return fmt::format("cannot model pass '{}' as a weighted sum of reads: {}", pass.name,
                         ex.message());
    pass_notes = ex->notes;
    result.emplace(analytic::linear_pass(ex->taps, in, &pass_notes));
  } else if (pass.analytic == AnalyticForm::MaskByAlphaFogged) {
    ir::Result<std::vector<analytic::Tap>> ex = analytic::extract_reads(
        *pass.draw.vertex_program, pass.draw.vs_constants.f, *pass.draw.pixel_program);
    if (!ex)
      return fmt::format("cannot model pass '{}' as fogged glow sources: {}", pass.name,
                         ex.message());
    if (ex->size() != 2)
      return fmt::format("cannot model pass '{}' as fogged glow sources: the pixel listing takes "
                         "{} different reads (expected the sources, then the depth)",
                         pass.name, ex->size());
    result.emplace(analytic::fogged_mask_pass(
        (*ex)[0], (*ex)[1], analytic::fog_form(*pass.draw.pixel_program, pass.draw.ps_constants.f),
        in, &pass_notes));
  } else {
    ir::Result<std::vector<analytic::Tap>> ex = analytic::extract_reads(
        *pass.draw.vertex_program, pass.draw.vs_constants.f, *pass.draw.pixel_program);
    if (!ex)
      return fmt::format("cannot model pass '{}' as rgb × alpha of one read: {}", pass.name,
                         ex.message());
    if (ex->size() != 1)
      return fmt::format("cannot model pass '{}' as rgb × alpha of one read: the pixel listing "
                         "takes {} different reads",
                         pass.name, ex->size());
    result.emplace(analytic::mask_by_alpha_pass((*ex)[0], in, &pass_notes));
  }
  if (!*result) return fmt::format("pass '{}': {}", pass.name, result->message());
  img::Image image = std::move(*result).value();
  if (!pass.stencil.empty()) {
    if (!pass.draw.vertices.empty())
      return fmt::format("pass '{}': a stencil-tested pass with its own triangles is modelled "
                         "only as an object pass",
                         pass.name);
    const img::Image before = images[pass.target];
    if (std::string e =
            mask_by_stencil(pass, graph, images, before, image, in.slack ? &mask : nullptr);
        !e.empty())
      return e;
  }
  if (pass.draw.scissor)
    keep_outside_scissor(*pass.draw.scissor, images[pass.target], image, midpoints, pass.target,
                         in.slack ? &mask : nullptr);
  images[pass.target] = std::move(image);
  if (in.slack) midpoints[pass.target] = std::move(mask);
  if (notes)
    for (const std::string& n : pass_notes)
      notes->push_back(fmt::format("pass '{}': {}", pass.name, n));
  return "";
}

} // namespace tierlift::effects::detail
