// The CPU device: the graph's textures in a map in host memory, each pass drawn by the
// interpreter (cpu::draw).
#include <fmt/format.h>

#include "tierlift/cpu/draw.h"
#include "tierlift/effects/device.h"
#include "tierlift/effects/run_graph.h"

namespace tierlift::effects {

std::string CpuPassDevice::begin_run(const EffectGraph& graph, const ImageMap& inputs) {
  graph_ = &graph;
  images_.clear();
  for (const TextureDesc& t : graph.textures) {
    auto it = inputs.find(t.name);
    images_[t.name] = it != inputs.end() ? it->second : img::Image(t.width, t.height, t.format);
  }
  return {};
}

std::string CpuPassDevice::run_pass(const PassDesc& desc) {
  if (!graph_) return "no run was begun";
  std::string error;
  std::optional<cpu::Pass> pass = make_pass(desc, images_, graph_->conventions, &error);
  if (!pass) return error;
  auto it = images_.find(desc.target);
  if (it == images_.end()) return fmt::format("no texture '{}'", desc.target);
  img::Image target = it->second; // a failed draw leaves the texture as it was
  cpu::DrawStats s = cpu::draw(*pass, target, threads_);
  if (!s.ok) return s.error;
  it->second = std::move(target);
  return {};
}

std::string CpuPassDevice::read_texture(const std::string& name, img::Image& out) {
  auto it = images_.find(name);
  if (it == images_.end()) return fmt::format("no texture '{}'", name);
  out = it->second;
  return {};
}

} // namespace tierlift::effects
