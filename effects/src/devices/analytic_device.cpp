// The analytic device (analytic_device.h): the graph's textures in host memory, each pass
// computed as math by run_analytic_pass.
#include "tierlift/effects/graph/analytic_device.h"

#include <fmt/format.h>

#include "analytic_pass.h"

namespace tierlift::effects {

ir::Status AnalyticPassDevice::begin_run(const EffectGraph& graph, const ImageMap& inputs) {
  graph_ = &graph;
  images_.clear();
  notes_.clear();
  midpoints_.clear();
  for (const TextureDesc& t : graph.textures) {
    auto it = inputs.find(t.name);
    images_[t.name] =
        it != inputs.end()
            ? it->second
            : img::Image(t.width, t.height, t.attachment() ? img::Format::RGBA32F : t.format);
  }
  return ir::ok_status();
}

ir::Result<pass::DrawReport> AnalyticPassDevice::draw(const PassDesc& pass) {
  if (!graph_) return device_error("no run was begun");
  if (!pass.depth.empty()) // the model has no depth buffer: refused, never drawn without one
    return device_error(
        fmt::format("pass '{}': the analytic device has no depth buffer", pass.name));
  if (std::string e = detail::run_analytic_pass(pass, *graph_, images_, midpoints_, &notes_);
      !e.empty())
    return device_error(std::move(e));
  return pass::DrawReport{}; // math, not a draw: nothing is counted
}

bool AnalyticPassDevice::rounding_midpoints(const std::string& texture,
                                            std::vector<uint8_t>& mask) const {
  auto it = midpoints_.find(texture);
  if (it == midpoints_.end()) return false;
  mask = it->second;
  return true;
}

ir::Status AnalyticPassDevice::update_input(const std::string& name, const img::Image& image) {
  auto it = images_.find(name);
  if (!graph_ || it == images_.end()) return device_error(fmt::format("no input '{}'", name));
  it->second = image;
  return ir::ok_status();
}

ir::Result<img::Image> AnalyticPassDevice::read_texture(const std::string& name) {
  auto it = images_.find(name);
  if (it == images_.end()) return device_error(fmt::format("no texture '{}'", name));
  return it->second;
}

std::unique_ptr<PassDevice> make_analytic_pass_device() {
  return std::make_unique<AnalyticPassDevice>();
}

} // namespace tierlift::effects
