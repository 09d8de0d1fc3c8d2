#include "tierlift/effects/run_graph.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

namespace tierlift::effects {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// An input as the graph declares it: right size, stored in the declared format.
std::string prepare_input(const TextureDesc& t, ImageMap& images) {
  auto it = images.find(t.name);
  if (it == images.end() && t.contents) it = images.emplace(t.name, *t.contents).first;
  if (it == images.end()) return fmt::format("input texture '{}' was not given", t.name);
  img::Image& im = it->second;
  if (im.width != t.width || im.height != t.height)
    return fmt::format("input texture '{}' is {}x{}, the graph expects {}x{}", t.name, im.width,
                       im.height, t.width, t.height);
  if (im.format != t.format) {
    im.format = t.format;
    img::quantize_in_place(im);
  }
  return {};
}

} // namespace

ir::Result<pass::Pass> make_pass(const PassDesc& desc, const ImageMap& images,
                                 const ir::Conventions& conventions) {
  if (!desc.vs)
    return ir::fail(desc.name, "graph", fmt::format("pass '{}': no vertex listing", desc.name));
  pass::Pass pass;
  pass.vertex_program = desc.vs;
  pass.pixel_program = desc.ps;
  pass.vs_constants.f = desc.vs_constants;
  pass.ps_constants.f = desc.ps_constants;
  if (desc.vertices.empty()) {
    pass::set_full_screen_quad_uv(pass);
  } else {
    pass.vertices = desc.vertices;
    pass.triangles = desc.triangles;
  }
  pass.color_targets = static_cast<uint32_t>(1 + desc.more_targets.size());
  pass.depth_stencil = desc.depth_stencil;
  pass.scissor = desc.scissor;
  for (const TextureBind& b : desc.textures) {
    auto it = images.find(b.texture);
    if (it == images.end() || b.stage >= pass::kMaxSamplers)
      return ir::fail(desc.name, "graph",
                      fmt::format("pass '{}': texture '{}' has no image", desc.name, b.texture));
    pass::TextureBinding& binding = pass.textures[b.stage];
    binding.image = std::make_shared<const img::Image>(it->second);
    binding.sampler = b.sampler;
  }
  pass.blend = desc.blend;
  pass.conventions = conventions;
  pass.pixel_spirv = desc.glsl_spirv;
  return pass;
}

namespace {

// check_graph, the inputs at their declared size and format, begin_run. Empty on success.
std::string begin_graph(const EffectGraph& graph, PassDevice& device, ImageMap& images) {
  std::string error = check_graph(graph);
  for (const TextureDesc& t : graph.textures)
    if (error.empty() && t.input) error = prepare_input(t, images);
  if (!error.empty()) return error;
  ImageMap inputs;
  for (const TextureDesc& t : graph.textures)
    if (t.input) inputs.emplace(t.name, images.find(t.name)->second);
  if (std::string e = device.begin_run(graph, inputs); !e.empty())
    return fmt::format("{}: {}", device.name(), e);
  return {};
}

// Every texture back into `images` (a failure leaves the map as it was given).
std::string read_all(const EffectGraph& graph, PassDevice& device, ImageMap& images) {
  ImageMap out;
  for (const TextureDesc& t : graph.textures)
    if (std::string e = device.read_texture(t.name, out[t.name]); !e.empty())
      return fmt::format("{}: reading '{}' back: {}", device.name(), t.name, e);
  for (auto& [name, image] : out) images[name] = std::move(image);
  return {};
}

// The inputs that change before frame f, at their declared size and format.
std::string replace_inputs(const EffectGraph& graph, PassDevice& device, unsigned f,
                           const FrameInputs& inputs_at) {
  ImageMap changed;
  if (std::string e = inputs_at(f, changed); !e.empty()) return e;
  for (auto& [name, image] : changed) {
    const TextureDesc* t = graph.find_texture(name);
    if (!t || !t->input) return fmt::format("'{}' is not an input texture", name);
    if (std::string e = prepare_input(*t, changed); !e.empty()) return e;
    if (std::string e = device.update_input(name, image); !e.empty()) return e;
  }
  return {};
}

} // namespace

GraphRun run_graph(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                   bool keep_pass_images, const PassProgress& progress) {
  GraphRun run;
  auto t_all = std::chrono::steady_clock::now();
  run.error = begin_graph(graph, device, images);
  if (!run.error.empty()) return run;

  for (const PassDesc& desc : graph.passes) {
    if (progress) progress(run.passes.size(), graph.passes.size(), desc);
    auto t0 = std::chrono::steady_clock::now();
    std::string e = device.run_pass(desc.at_frame(0));
    if (e.empty()) e = device.finish(); // the pass's own time, not the time it was queued
    if (!e.empty()) {
      run.error = fmt::format("pass '{}' on {}: {}", desc.name, device.name(), e);
      return run;
    }
    PassRecord rec{desc.name, desc.target, {}, ms_since(t0), {}, {}};
    if (keep_pass_images)
      if (std::string e = device.read_texture(desc.target, rec.result); !e.empty()) {
        run.error = fmt::format("pass '{}' on {}: reading '{}' back: {}", desc.name, device.name(),
                                desc.target, e);
        return run;
      }
    if (keep_pass_images) device.rounding_midpoints(desc.target, rec.midpoints);
    std::vector<std::string> extra = desc.more_targets;
    if (!desc.stencil.empty() && desc.depth_stencil.stencil_test) extra.push_back(desc.stencil);
    for (const std::string& name : keep_pass_images ? extra : std::vector<std::string>{}) {
      PassRecord::Extra x{name, {}, {}};
      if (std::string e = device.read_texture(name, x.result); !e.empty()) {
        run.error = fmt::format("pass '{}' on {}: reading '{}' back: {}", desc.name, device.name(),
                                name, e);
        return run;
      }
      device.rounding_midpoints(name, x.midpoints);
      rec.more.push_back(std::move(x));
    }
    run.passes.push_back(std::move(rec));
  }
  // Every texture back into the map (a failed run leaves the map as it was given).
  run.error = read_all(graph, device, images);
  if (!run.error.empty()) return run;
  for (const TextureDesc& t : graph.textures)
    if (std::vector<uint8_t> mask; device.rounding_midpoints(t.name, mask))
      run.midpoints[t.name] = std::move(mask);
  run.ok = true;
  run.total_ms = ms_since(t_all);
  return run;
}

double FrameTimes::median_ms() const {
  if (frame_ms.empty()) return 0;
  std::vector<double> v = frame_ms;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}
double FrameTimes::min_ms() const {
  return frame_ms.empty() ? 0 : *std::min_element(frame_ms.begin(), frame_ms.end());
}
double FrameTimes::max_ms() const {
  return frame_ms.empty() ? 0 : *std::max_element(frame_ms.begin(), frame_ms.end());
}

FramesRun run_frames(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                     unsigned frames, const FrameSink& sink, const FrameInputs& inputs_at) {
  FramesRun run;
  auto t0 = std::chrono::steady_clock::now();
  run.error = begin_graph(graph, device, images);
  if (!run.error.empty()) return run;
  run.times.setup_ms = ms_since(t0);
  for (unsigned f = 0; f < frames; ++f) {
    auto t = std::chrono::steady_clock::now();
    if (inputs_at && f > 0)
      if (std::string e = replace_inputs(graph, device, f, inputs_at); !e.empty()) {
        run.error = fmt::format("frame {} on {}: {}", f + 1, device.name(), e);
        return run;
      }
    for (const PassDesc& desc : graph.passes)
      if (std::string e = device.run_pass(desc.at_frame(f)); !e.empty()) {
        run.error =
            fmt::format("frame {}, pass '{}' on {}: {}", f + 1, desc.name, device.name(), e);
        return run;
      }
    if (std::string e = device.finish(); !e.empty()) {
      run.error = fmt::format("frame {} on {}: {}", f + 1, device.name(), e);
      return run;
    }
    run.times.frame_ms.push_back(ms_since(t));
    if (sink)
      if (std::string e = sink(f, device); !e.empty()) {
        run.error = fmt::format("frame {} on {}: {}", f + 1, device.name(), e);
        return run;
      }
  }
  run.error = read_all(graph, device, images);
  run.ok = run.error.empty();
  return run;
}

} // namespace tierlift::effects
