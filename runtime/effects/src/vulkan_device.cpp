// The Vulkan device behind the PassDevice interface (built only with tierlift_vulkan).
#include "tierlift/effects/device.h"

#if TIERLIFT_HAVE_VULKAN
#include <fmt/format.h>

#include "tierlift/effects/run_graph.h"
#include "tierlift/vulkan/device.h"

namespace tierlift::effects {
namespace {

class VulkanPassDevice final : public PassDevice {
public:
  explicit VulkanPassDevice(vulkan::Device& device) : device_(device) {}
  std::string name() const override { return "vulkan"; }

  std::string begin_run(const EffectGraph& graph, const ImageMap& inputs) override {
    graph_ = &graph;
    images_.clear();
    for (const TextureDesc& t : graph.textures) {
      auto it = inputs.find(t.name);
      images_[t.name] = it != inputs.end() ? it->second : img::Image(t.width, t.height, t.format);
    }
    return {};
  }

  std::string run_pass(const PassDesc& desc) override {
    if (!graph_) return "no run was begun";
    std::string error;
    std::optional<cpu::Pass> pass = make_pass(desc, images_, graph_->conventions, &error);
    if (!pass) return error;
    auto it = images_.find(desc.target);
    if (it == images_.end()) return fmt::format("no texture '{}'", desc.target);
    vulkan::DrawResult r = device_.draw(*pass, it->second);
    return r.ok ? std::string() : r.error;
  }

  std::string read_texture(const std::string& name, img::Image& out) override {
    auto it = images_.find(name);
    if (it == images_.end()) return fmt::format("no texture '{}'", name);
    out = it->second;
    return {};
  }

private:
  vulkan::Device& device_;
  const EffectGraph* graph_ = nullptr;
  ImageMap images_;
};

} // namespace

std::unique_ptr<PassDevice> make_vulkan_pass_device(vulkan::Device& device) {
  return std::make_unique<VulkanPassDevice>(device);
}

} // namespace tierlift::effects
#endif
