// The CPU device: the graph's textures in a map in host memory, each pass drawn by the
// interpreter (cpu::draw). Textures are bound to a pass by reference, not copied, and a run
// reuses the buffers of the run before (same graph, same sizes): at 1920×1080 a copy or a
// fresh allocation of one texture costs about as much as a blur pass.
#include <chrono>
#include <fmt/format.h>

#include "tierlift/cpu/draw.h"
#include "tierlift/effects/graph/device.h"
#include "tierlift/effects/graph/run_graph.h"

namespace tierlift::effects {
namespace {

// `im` becomes a w×h image of `format` holding `pixels` (or zeros), in its own buffer when
// that is large enough.
void reset_image(img::Image& im, uint32_t w, uint32_t h, img::Format format,
                 const img::Image* pixels) {
  im.width = w;
  im.height = h;
  im.format = format;
  if (pixels)
    im.rgba.assign(pixels->rgba.begin(), pixels->rgba.end());
  else
    im.rgba.assign(size_t{w} * h * 4, 0.0f);
}

} // namespace

ir::Status CpuPassDevice::begin_run(const EffectGraph& graph, const ImageMap& inputs) {
  graph_ = &graph;
  ImageMap kept;
  kept.swap(images_);
  stale_.clear();
  stencils_.clear();
  depths_.clear();
  for (const TextureDesc& t : graph.textures) {
    if (t.stencil) {
      stencils_[t.name].assign(size_t{t.width} * t.height, 0);
      continue;
    }
    if (t.depth) { // the clear value, or the red channel of the image the graph carries
      std::vector<float>& z = depths_[t.name];
      z.assign(size_t{t.width} * t.height, t.depth_clear);
      if (t.contents && t.contents->rgba.size() == z.size() * 4)
        for (size_t i = 0; i < z.size(); ++i) z[i] = t.contents->rgba[4 * i];
      continue;
    }
    auto in = inputs.find(t.name);
    auto old = kept.find(t.name);
    img::Image& im = images_[t.name];
    if (old != kept.end()) im = std::move(old->second);
    if (in != inputs.end()) {
      reset_image(im, in->second.width, in->second.height, in->second.format, &in->second);
    } else if (im.rgba.size() == size_t{t.width} * t.height * 4) {
      // The run before's buffer, left as it is until something reads it (stale_).
      im.width = t.width;
      im.height = t.height;
      im.format = t.format;
      stale_.insert(t.name);
    } else {
      reset_image(im, t.width, t.height, t.format, nullptr);
    }
  }
  return ir::ok_status();
}

void CpuPassDevice::settle(const std::string& name) {
  auto it = stale_.find(name);
  if (it == stale_.end()) return;
  stale_.erase(it);
  auto im = images_.find(name);
  if (im != images_.end()) std::fill(im->second.rgba.begin(), im->second.rgba.end(), 0.0f);
}

ir::Result<pass::DrawReport> CpuPassDevice::draw(const PassDesc& desc) {
  if (!graph_) return device_error("no run was begun");
  pass::Pass pass = graph_draw(desc, graph_->conventions);
  pass.executor = executor_;
  // A GLSL pass: the interpreter runs D3D9 listings only, so it runs the pass's ps_2_0 twin
  // (PassDesc::draw's pixel_program; docs/glsl.md). The GLSL and the twin are compared on the
  // Vulkan device, where both run, so the twin standing in here is checked, not assumed.
  pass.pixel_spirv.reset();
  auto it = images_.find(desc.target);
  if (it == images_.end()) return device_error(fmt::format("no texture '{}'", desc.target));
  cpu::DrawTargets targets;
  targets.color[0] = &it->second;
  for (size_t i = 0; i < desc.more_targets.size() && i + 1 < targets.color.size(); ++i) {
    auto more = images_.find(desc.more_targets[i]);
    if (more == images_.end())
      return device_error(fmt::format("no texture '{}'", desc.more_targets[i]));
    targets.color[i + 1] = &more->second;
  }
  if (!desc.stencil.empty()) {
    auto s = stencils_.find(desc.stencil);
    if (s == stencils_.end())
      return device_error(fmt::format("no stencil texture '{}'", desc.stencil));
    targets.stencil = s->second.data();
  }
  if (!desc.depth.empty()) {
    auto z = depths_.find(desc.depth);
    if (z == depths_.end()) return device_error(fmt::format("no depth texture '{}'", desc.depth));
    targets.depth = z->second.data();
  }
  for (const TextureBind& b : desc.textures) {
    settle(b.texture);
    auto tex = images_.find(b.texture);
    pass::TextureBinding* bound = pass::sampler_binding(pass, b.stage); // either stage's
    if (tex == images_.end() || !bound)
      return device_error(
          fmt::format("pass '{}': texture '{}' has no image", desc.name, b.texture));
    // Not owned: the image outlives the draw, and check_graph refuses a pass that reads its
    // own target, so no texture is written while it is sampled.
    bound->image = std::shared_ptr<const img::Image>(std::shared_ptr<void>(), &tex->second);
  }
  // In place: cpu::draw fails only before it writes a pixel, so a failed draw leaves the
  // texture as it was.
  // One stale target: the draw zeroes it unless it overwrites it all. Several: each zeroed
  // here, since DrawTargets::stale speaks for all of them at once.
  if (desc.more_targets.empty()) {
    targets.stale = stale_.count(desc.target) != 0;
  } else {
    settle(desc.target);
    for (const std::string& m : desc.more_targets) settle(m);
  }
  const auto t0 = std::chrono::steady_clock::now();
  ir::Result<cpu::DrawStats> s = cpu::draw(pass, targets, threads_);
  pass::DrawReport report;
  report.draw_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (!s) {
    settle(desc.target); // zeros, as the run began with
    return std::move(s).failure();
  }
  stale_.erase(desc.target); // drawn: zeroed first or overwritten
  report.pixels_shaded = s->pixels_shaded;
  report.pixels_killed = s->pixels_killed;
  ir::Result<pass::DrawReport> out(report);
  if (s->triangles == 0) // an empty image is almost always a mistake in the vertex listing
    out.add({ir::Severity::Warning,
             {},
             "no triangle reached the screen (the vertex listing's oPos is degenerate, behind "
             "the eye or clipped away): the image is empty",
             "nothing-drawn",
             ""});
  return out;
}

ir::Status CpuPassDevice::update_input(const std::string& name, const img::Image& image) {
  auto it = images_.find(name);
  if (!graph_ || it == images_.end()) return device_error(fmt::format("no input '{}'", name));
  reset_image(it->second, image.width, image.height, image.format, &image);
  stale_.erase(name);
  return ir::ok_status();
}

ir::Result<img::Image> CpuPassDevice::read_texture(const std::string& name) {
  if (auto s = stencils_.find(name); s != stencils_.end()) {
    const TextureDesc* t = graph_ ? graph_->find_texture(name) : nullptr;
    if (!t) return device_error(fmt::format("no texture '{}'", name));
    img::Image out(t->width, t->height, img::Format::RGBA32F);
    for (size_t i = 0; i < s->second.size(); ++i) out.rgba[4 * i] = s->second[i];
    return out;
  }
  if (auto z = depths_.find(name); z != depths_.end()) {
    const TextureDesc* t = graph_ ? graph_->find_texture(name) : nullptr;
    if (!t) return device_error(fmt::format("no texture '{}'", name));
    img::Image out(t->width, t->height, img::Format::RGBA32F);
    for (size_t i = 0; i < z->second.size(); ++i) out.rgba[4 * i] = z->second[i];
    return out;
  }
  settle(name);
  auto it = images_.find(name);
  if (it == images_.end()) return device_error(fmt::format("no texture '{}'", name));
  return it->second;
}

} // namespace tierlift::effects
