#include "tierlift/effects/graph/run_graph.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "tierlift/crash/crash.h"

namespace tierlift::effects {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The run's error; `cause`, a device's refusal, follows it as notes (kRunRule).
ir::Failure run_error(std::string message, const std::vector<ir::Diagnostic>& cause = {}) {
  ir::Failure out = ir::fail("graph", std::string(kRunRule), std::move(message));
  for (ir::Diagnostic d : cause) {
    d.severity = ir::Severity::Note;
    out.diagnostics.push_back(std::move(d));
  }
  return out;
}

// An input as the graph declares it: right size, stored in the declared format.
ir::Status prepare_input(const TextureDesc& t, ImageMap& images) {
  auto it = images.find(t.name);
  if (it == images.end() && t.contents) it = images.emplace(t.name, *t.contents).first;
  if (it == images.end()) return run_error(fmt::format("input texture '{}' was not given", t.name));
  img::Image& im = it->second;
  if (im.width != t.width || im.height != t.height)
    return run_error(fmt::format("input texture '{}' is {}x{}, the graph expects {}x{}", t.name,
                                 im.width, im.height, t.width, t.height));
  if (im.format != t.format) {
    im.format = t.format;
    img::quantize_in_place(im);
  }
  return ir::ok_status();
}

} // namespace

pass::Pass graph_draw(const PassDesc& desc, const ir::Conventions& conventions) {
  pass::Pass draw = desc.draw;
  if (draw.vertex_program && draw.vertices.empty()) pass::set_full_screen_quad_uv(draw);
  draw.color_targets = static_cast<uint32_t>(1 + desc.more_targets.size());
  draw.conventions = conventions;
  return draw;
}

namespace {

// check_graph, the inputs at their declared size and format, begin_run.
ir::Status begin_graph(const EffectGraph& graph, PassDevice& device, ImageMap& images) {
  if (ir::Status checked = check_graph(graph); !checked) return run_error(checked.message());
  for (const TextureDesc& t : graph.textures)
    if (t.input)
      if (ir::Status e = prepare_input(t, images); !e) return e;
  ImageMap inputs;
  for (const TextureDesc& t : graph.textures)
    if (t.input) inputs.emplace(t.name, images.find(t.name)->second);
  if (ir::Status begun = device.begin_run(graph, inputs); !begun)
    return run_error(fmt::format("{}: {}", device.name(), begun.message()), begun.diagnostics());
  return ir::ok_status();
}

// Every texture back into `images`, or those `only` names when given (a failure leaves the
// map as it was given).
ir::Status read_all(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                    const std::vector<std::string>* only = nullptr) {
  ImageMap out;
  for (const TextureDesc& t : graph.textures) {
    if (only && std::find(only->begin(), only->end(), t.name) == only->end()) continue;
    ir::Result<img::Image> image = device.read_texture(t.name);
    if (!image)
      return run_error(
          fmt::format("{}: reading '{}' back: {}", device.name(), t.name, image.message()));
    out[t.name] = std::move(*image);
  }
  for (auto& [name, image] : out) images[name] = std::move(image);
  return ir::ok_status();
}

// The inputs that change before frame f, at their declared size and format.
ir::Status replace_inputs(const EffectGraph& graph, PassDevice& device, unsigned f,
                          const FrameInputs& inputs_at) {
  ImageMap changed;
  if (ir::Status given = inputs_at(f, changed); !given) return run_error(given.message());
  for (auto& [name, image] : changed) {
    const TextureDesc* t = graph.find_texture(name);
    if (!t || !t->input) return run_error(fmt::format("'{}' is not an input texture", name));
    if (ir::Status e = prepare_input(*t, changed); !e) return e;
    if (ir::Status replaced = device.update_input(name, image); !replaced)
      return run_error(replaced.message());
  }
  return ir::ok_status();
}

// A pass's target (and, when asked, its further targets, stencil and depth) read back after it.
ir::Status record_pass(const PassDesc& desc, PassDevice& device, bool keep_pass_images,
                       PassRecord& rec) {
  if (!keep_pass_images) return ir::ok_status();
  auto read = [&](const std::string& name, img::Image& out) -> ir::Status {
    ir::Result<img::Image> image = device.read_texture(name);
    if (!image)
      return run_error(fmt::format("pass '{}' on {}: reading '{}' back: {}", desc.name,
                                   device.name(), name, image.message()));
    out = std::move(*image);
    return ir::ok_status();
  };
  if (ir::Status e = read(desc.target, rec.result); !e) return e;
  device.rounding_midpoints(desc.target, rec.midpoints);
  std::vector<std::string> extra = desc.more_targets;
  if (!desc.stencil.empty() && desc.draw.depth_stencil.stencil_test) extra.push_back(desc.stencil);
  if (!desc.depth.empty()) extra.push_back(desc.depth);
  for (const std::string& name : extra) {
    PassRecord::Extra x{name, {}, {}};
    if (ir::Status e = read(name, x.result); !e) return e;
    device.rounding_midpoints(name, x.midpoints);
    rec.more.push_back(std::move(x));
  }
  return ir::ok_status();
}

} // namespace

namespace {

ir::Result<GraphRun> run_graph_reading_back(const EffectGraph& graph, PassDevice& device,
                                            ImageMap& images, bool keep_pass_images,
                                            const PassProgress& progress,
                                            const std::vector<std::string>* read_back) {
  GraphRun run;
  auto t_all = std::chrono::steady_clock::now();
  {
    const crash::Stage stage("setup", fmt::format("while setting up the {} device (textures, "
                                                  "uploads, pipelines)",
                                                  device.name()));
    if (ir::Status begun = begin_graph(graph, device, images); !begun)
      return std::move(begun).failure();
  }
  run.setup_ms = ms_since(t_all);

  for (const PassDesc& desc : graph.passes) {
    if (progress) progress(run.passes.size(), graph.passes.size(), desc);
    // A crash in a pass (a driver's, most likely) names the pass and the device.
    const crash::Stage stage(
        "pass", fmt::format("while running pass '{}' on {}", desc.name, device.name()));
    auto t0 = std::chrono::steady_clock::now();
    ir::Result<pass::DrawReport> drawn = device.draw(desc.at_frame(0));
    // The pass's own time, not the time it was queued.
    ir::Status done = drawn ? device.finish() : ir::Status(drawn.failure());
    if (!done)
      return run_error(fmt::format("pass '{}' on {}: {}", desc.name, device.name(), done.message()),
                       done.diagnostics());
    PassRecord rec{desc.name, desc.target, {}, ms_since(t0), {}, {}, *drawn, drawn.diagnostics()};
    if (ir::Status e = record_pass(desc, device, keep_pass_images, rec); !e) return e.failure();
    run.passes.push_back(std::move(rec));
  }
  // Every texture back into the map (a failed run leaves the map as it was given).
  if (ir::Status e = read_all(graph, device, images, read_back); !e) return e.failure();
  for (const TextureDesc& t : graph.textures)
    if (std::vector<uint8_t> mask; device.rounding_midpoints(t.name, mask))
      run.midpoints[t.name] = std::move(mask);
  run.total_ms = ms_since(t_all);
  return run;
}

} // namespace

ir::Result<GraphRun> run_graph(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                               bool keep_pass_images, const PassProgress& progress) {
  return run_graph_reading_back(graph, device, images, keep_pass_images, progress, nullptr);
}

ir::Result<GraphRun> run_graph_reading(const EffectGraph& graph, PassDevice& device,
                                       ImageMap& images,
                                       const std::vector<std::string>& read_back) {
  return run_graph_reading_back(graph, device, images, false, {}, &read_back);
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

ir::Result<FrameTimes> run_frames(const EffectGraph& graph, PassDevice& device, ImageMap& images,
                                  unsigned frames, const FrameSink& sink,
                                  const FrameInputs& inputs_at, const FrameProgress& progress) {
  FrameTimes times;
  auto t0 = std::chrono::steady_clock::now();
  if (ir::Status begun = begin_graph(graph, device, images); !begun)
    return std::move(begun).failure();
  times.setup_ms = ms_since(t0);
  auto frame_error = [&](unsigned f, const std::string& why,
                         const std::vector<ir::Diagnostic>& cause = {}) {
    return run_error(fmt::format("frame {} on {}: {}", f + 1, device.name(), why), cause);
  };
  for (unsigned f = 0; f < frames; ++f) {
    auto t = std::chrono::steady_clock::now();
    if (inputs_at && f > 0)
      if (ir::Status e = replace_inputs(graph, device, f, inputs_at); !e)
        return frame_error(f, e.message());
    for (const PassDesc& desc : graph.passes)
      if (ir::Result<pass::DrawReport> drawn = device.draw(desc.at_frame(f)); !drawn)
        return run_error(fmt::format("frame {}, pass '{}' on {}: {}", f + 1, desc.name,
                                     device.name(), drawn.message()),
                         drawn.diagnostics());
    if (ir::Status done = device.finish(); !done)
      return frame_error(f, done.message(), done.diagnostics());
    times.frame_ms.push_back(ms_since(t));
    if (sink)
      if (ir::Status taken = sink(f, device); !taken) return frame_error(f, taken.message());
    if (progress) progress(f + 1, frames);
  }
  if (ir::Status e = read_all(graph, device, images); !e) return e.failure();
  return times;
}

} // namespace tierlift::effects
