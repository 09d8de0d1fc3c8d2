// The analytic device (analytic_device.h): the graph's textures in host memory, each pass
// computed as math by run_analytic_pass.
#include "tierlift/effects/analytic_device.h"

#include <fmt/format.h>

#include "analytic_pass.h"

namespace tierlift::effects {

std::string AnalyticPassDevice::begin_run(const EffectGraph& graph, const ImageMap& inputs) {
  graph_ = &graph;
  images_.clear();
  notes_.clear();
  midpoints_.clear();
  for (const TextureDesc& t : graph.textures) {
    auto it = inputs.find(t.name);
    images_[t.name] = it != inputs.end() ? it->second
                                         : img::Image(t.width, t.height,
                                                      t.stencil ? img::Format::RGBA32F : t.format);
  }
  return {};
}

std::string AnalyticPassDevice::run_pass(const PassDesc& pass) {
  if (!graph_) return "no run was begun";
  return detail::run_analytic_pass(pass, *graph_, images_, midpoints_, &notes_);
}

bool AnalyticPassDevice::rounding_midpoints(const std::string& texture,
                                            std::vector<uint8_t>& mask) const {
  auto it = midpoints_.find(texture);
  if (it == midpoints_.end()) return false;
  mask = it->second;
  return true;
}

std::string AnalyticPassDevice::update_input(const std::string& name, const img::Image& image) {
  auto it = images_.find(name);
  if (!graph_ || it == images_.end()) return fmt::format("no input '{}'", name);
  it->second = image;
  return {};
}

std::string AnalyticPassDevice::read_texture(const std::string& name, img::Image& out) {
  auto it = images_.find(name);
  if (it == images_.end()) return fmt::format("no texture '{}'", name);
  out = it->second;
  return {};
}

std::unique_ptr<PassDevice> make_analytic_pass_device() {
  return std::make_unique<AnalyticPassDevice>();
}

} // namespace tierlift::effects
